#include "postproc/checks/post_check.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <functional>

#include "postproc/engine/command_names.hpp"
#include "postproc/engine/enumerations.hpp"
#include "postproc/engine/host_variables.hpp"
#include "toolpath/value.hpp"

namespace postproc {
namespace {

toolpath::Diagnostic diagnostic(const gppl::Error& e, toolpath::Severity severity) {
  return {{e.where().file, static_cast<std::size_t>(e.where().line), static_cast<std::size_t>(e.where().column)},
          severity, e.text(), e.number()};
}

// A procedure that no command has and no `call` names never runs: usually a misspelled command
// (`@rapid_mvoe`), whose commands would then be lost.
void unused_procedures(const gppl::Program& program, std::vector<toolpath::Diagnostic>& out) {
  const auto commands = stream_command_names();
  for (const auto& p : gppl::procedures(program)) {
    if (p.called || is_stream_command_name(p.name)) continue;
    std::string message = fmt::format("{}: not a command and never called", p.name);
    if (std::string_view guess = gppl::nearest_name(p.name, commands); !guess.empty())
      message += fmt::format("; did you mean {}?", guess);
    out.push_back({{p.position.file, static_cast<std::size_t>(p.position.line),
                    static_cast<std::size_t>(p.position.column)},
                   toolpath::Severity::Warning, std::move(message), 0});
  }
}

std::vector<toolpath::Diagnostic> check_post(
    const PostCheckOptions& options,
    const std::function<std::shared_ptr<const gppl::Program>(const gppl::CompileOptions&)>& compile) {
  std::vector<std::string> cycles;
  static const prp::MachineParameters kNoMachine;
  const prp::MachineParameters& m = options.machine ? *options.machine : kNoMachine;
  for (const auto* r : m.records("drill_type")) cycles.push_back(r->name);
  Enumerations enums(cycles);
  gppl::CompileOptions compile_options;
  compile_options.host_variables = host_variables(enums, m);
  compile_options.host_variables.insert(compile_options.host_variables.end(), options.job_variables.begin(),
                                        options.job_variables.end());
  compile_options.implicit_host_variables = false;  // every name must be declared: typos are errors here
  compile_options.check_constant_assignments = true;
  compile_options.include_paths = options.include_paths;
  compile_options.symbols = options.symbols;
  std::vector<toolpath::Diagnostic> out;
  try {
    auto program = compile(compile_options);
    for (const auto& w : gppl::warning_details(*program)) out.push_back(diagnostic(w, toolpath::Severity::Warning));
    unused_procedures(*program, out);
  } catch (const gppl::Errors& e) {
    for (const auto& one : e.all()) out.push_back(diagnostic(one, toolpath::Severity::Error));
  } catch (const gppl::Error& e) {
    out.push_back(diagnostic(e, toolpath::Severity::Error));
  }
  return out;
}

std::vector<toolpath::Diagnostic> check_machine(const std::function<prp::MachineParameters()>& load) {
  try {
    return load().warnings();
  } catch (const prp::LoadError& e) {
    return e.errors();
  }
}

}  // namespace

std::vector<toolpath::Diagnostic> check_post_file(const std::string& path, const PostCheckOptions& options) {
  return check_post(options, [&](const gppl::CompileOptions& o) { return gppl::compile_file(path, o); });
}

std::vector<toolpath::Diagnostic> check_post_text(std::string_view text, const std::string& path,
                                                  const PostCheckOptions& options) {
  return check_post(options, [&](const gppl::CompileOptions& o) { return gppl::compile_source(text, path, o); });
}

bool is_machine_file(const std::string& path) {
  const auto ext = std::filesystem::path(path).extension().string();
  return toolpath::iequals(ext, ".prp") || toolpath::iequals(ext, ".mac") || toolpath::iequals(ext, ".vmid");
}

std::vector<toolpath::Diagnostic> check_machine_file(const std::string& path, prp::Units units) {
  return check_machine([&] { return prp::load_file(path, units); });
}

std::vector<toolpath::Diagnostic> check_machine_text(std::string_view text, const std::string& path, prp::Units units) {
  return check_machine([&] { return prp::load_source(text, path, units); });
}

}  // namespace postproc
