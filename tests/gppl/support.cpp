// Helpers shared by the GPPL tests.
#include "support.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gppl_test {

Post::Post(const std::string& source, gppl::CompileOptions options, const std::string& name) {
  program = gppl::compile_source(source, name, options);
  run = std::make_unique<gppl::Interpreter>(program, out);
}

gppl::RunResult Post::call(const std::string& procedure) {
  const auto id = run->find_procedure(procedure);
  if (!id) throw std::runtime_error("no procedure " + procedure);
  return run->call(*id);
}

gppl::VariableId Post::id(const std::string& variable) const {
  const auto id = run->find_variable(variable);
  if (!id) throw std::runtime_error("no variable " + variable);
  return *id;
}

void Post::set(const std::string& variable, const gppl::Value& v, gppl::ChangeOverride change) {
  run->assign(run->add_variable(variable), v, change);
}

const gppl::Value& Post::get(const std::string& variable) const { return run->value(id(variable)); }

std::string Post::text() {
  run->finish();
  std::string all;
  for (std::size_t i = 0; i < out.lines.size(); ++i) {
    if (i > 0) all += '\n';
    all += out.lines[i];
  }
  return all;
}

std::string compile_error(const std::string& source, gppl::CompileOptions options) {
  try {
    gppl::compile_source(source, "e.gpp", options);
  } catch (const gppl::Errors& e) {
    const gppl::Error& first = e.all().front();
    return fmt::format("{}:{}: error {}", first.where().line, first.where().column, first.number());
  }
  return "no error";
}

std::string first_file_error(const std::string& path) {
  try {
    gppl::compile_file(path, {});
  } catch (const gppl::Errors& e) {
    return e.all().front().what();
  }
  return "no error";
}

std::string run_error(const std::string& source) {
  try {
    Post post(source);
    post.run->start();
    post.call("@t");
  } catch (const gppl::Error& e) {
    return fmt::format("{}:{}: error {}", e.where().line, e.where().column, e.number());
  }
  return "no error";
}

gppl::Value integer(std::int64_t v) { return gppl::Value::of_integer(v); }
gppl::Value numeric(double v) { return gppl::Value::of_numeric(v); }
gppl::Value logical(bool v) { return gppl::Value::of_logical(v); }
gppl::Value string(std::string v) { return gppl::Value::of_string(std::move(v)); }

}  // namespace gppl_test
