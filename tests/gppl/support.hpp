// Helpers shared by the GPPL tests: compile a post from text, run procedures, capture lines.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gppl/gppl.hpp"

namespace gppl_test {

struct CapturedLines : gppl::OutputSink {
  std::vector<std::string> lines;
  std::vector<std::string> procedures;
  void write_line(std::string_view line, const gppl::LineOrigin& origin) override {
    lines.emplace_back(line);
    procedures.emplace_back(origin.procedure);
  }
};

// A compiled post with an interpreter writing into `out`.
struct Post {
  explicit Post(const std::string& source, gppl::CompileOptions options = {}, const std::string& name = "test.gpp");
  std::shared_ptr<const gppl::Program> program;
  CapturedLines out;
  std::unique_ptr<gppl::Interpreter> run;

  gppl::RunResult call(const std::string& procedure);
  void set(const std::string& variable, const gppl::Value& v,
           gppl::ChangeOverride change = gppl::ChangeOverride::Compute);
  const gppl::Value& get(const std::string& variable) const;
  gppl::VariableId id(const std::string& variable) const;
  // Flushes the open line and returns every line written so far, joined with '\n'.
  std::string text();
};

// "line:column: error N" of the first load-time error, or "no error".
std::string compile_error(const std::string& source, gppl::CompileOptions options = {});
// The whole message of the first error compiling the post file at `path`, or "no error".
std::string first_file_error(const std::string& path);
// "line:column: error N" of the run-time error of procedure @t (after @init_post), or "no error".
std::string run_error(const std::string& source);

gppl::Value integer(std::int64_t v);
gppl::Value numeric(double v);
gppl::Value logical(bool v);
gppl::Value string(std::string v);

}  // namespace gppl_test
