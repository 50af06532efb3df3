// `postproc check FILE...`: static checks of posts (.gpp) and machine parameter files (.prp),
// printing every error with its position.
#include <fmt/format.h>

#include <filesystem>
#include <ostream>
#include <sstream>

#include "gppl/gppl.hpp"
#include "postproc/cli/cli.hpp"
#include "postproc/cli/cli_support.hpp"
#include "postproc/engine/command_names.hpp"
#include "postproc/engine/enumerations.hpp"
#include "postproc/engine/host_variables.hpp"
#include "prp/prp.hpp"
#include "toolpath/value.hpp"

namespace postproc::cli {
namespace {

// Machine files: PRP, its pre-2010 name .mac, and VMID (XML; the loader tells them apart by content).
bool is_prp(const std::string& path) {
  auto ext = std::filesystem::path(path).extension().string();
  return toolpath::iequals(ext, ".prp") || toolpath::iequals(ext, ".mac") || toolpath::iequals(ext, ".vmid");
}

// Returns the number of errors.
std::size_t check_prp(const std::string& path, prp::Units units, std::ostream& out) {
  try {
    auto params = prp::load_file(path, units);
    print_machine_warnings(params, out);
    return 0;
  } catch (const prp::LoadError& e) {
    for (const auto& d : e.errors()) out << d.text() << '\n';
    return e.errors().size();
  }
}

// A procedure that no command has and no `call` names never runs: usually a misspelled command
// (`@rapid_mvoe`), whose commands would then be lost. A warning with the nearest command name.
void warn_unused_procedures(const gppl::Program& program, std::ostream& out) {
  const auto commands = stream_command_names();
  for (const auto& p : gppl::procedures(program)) {
    if (p.called || is_stream_command_name(p.name)) continue;
    std::string message = fmt::format("{}:{}:{}: warning: {}: not a command and never called", p.position.file,
                                      p.position.line, p.position.column, p.name);
    if (std::string_view guess = gppl::nearest_name(p.name, commands); !guess.empty())
      message += fmt::format("; did you mean {}?", guess);
    out << message << '\n';
  }
}

std::size_t check_gpp(const std::string& path, const prp::MachineParameters& machine, const Arguments& args,
                      std::ostream& out) {
  std::vector<std::string> cycles;
  for (const auto* r : machine.records("drill_type")) cycles.push_back(r->name);
  Enumerations enums(cycles);
  gppl::CompileOptions options;
  options.host_variables = host_variables(enums, machine);
  if (args.has("--job")) {  // the names the job carries are defined, as in a run of that job
    Input job = Input::open(args.value("--job"));
    for (auto& v : job_variables(*job.reader)) options.host_variables.push_back(std::move(v));
  }
  options.implicit_host_variables = false;  // every name must be declared: typos are errors here
  options.check_constant_assignments = true;
  if (args.has("--include")) options.include_paths.push_back(args.value("--include"));
  try {
    auto program = gppl::compile_file(path, options);
    for (const auto& w : gppl::warnings(*program)) out << w << '\n';
    warn_unused_procedures(*program, out);
    return 0;
  } catch (const gppl::Errors& e) {
    for (const auto& one : e.all()) out << one.what() << '\n';
    return e.all().size();
  } catch (const gppl::Error& e) {
    out << e.what() << '\n';
    return 1;
  }
}

int run_check(const Arguments& args, std::ostream& out, std::ostream&) {
  if (args.positional().empty()) throw UsageError{"expected one or more .gpp files or machine files (.prp, .mac, .vmid)"};
  std::string units_word = args.value("--units", "metric");
  if (units_word != "metric" && units_word != "inch") throw UsageError{"--units must be metric or inch"};
  auto units = units_word == "inch" ? prp::Units::Inch : prp::Units::Metric;

  // The PRP whose external variables the posts may use: --prp, or the first .prp among the files.
  std::string machine_file = args.value("--prp");
  for (const auto& path : args.positional())
    if (machine_file.empty() && is_prp(path)) machine_file = path;
  prp::MachineParameters machine;
  std::size_t errors = 0;
  if (!machine_file.empty()) {
    std::ostringstream ignored;  // reported below when it is one of the files, or here
    if (check_prp(machine_file, units, args.has("--prp") ? out : ignored) == 0)
      machine = prp::load_file(machine_file, units);
    else if (args.has("--prp"))
      ++errors;
  }
  for (const auto& path : args.positional()) {
    std::size_t n = is_prp(path) ? check_prp(path, units, out) : check_gpp(path, machine, args, out);
    errors += n;
    if (!args.has("--quiet")) out << fmt::format("{}: {}\n", path, n == 0 ? "ok" : fmt::format("{} error(s)", n));
  }
  return errors == 0 ? kOk : kBadInput;
}

}  // namespace

Subcommand check_command() {
  return {
      "check",
      "postproc check [--prp P.prp] [--job JOB] FILE.gpp|FILE.prp|FILE.mac|FILE.vmid...",
      "Check posts and PRP files without running them; print every error with its position.",
      {
          {"--prp", "", true, "the machine file (PRP or VMID) whose external variables the posts may use (default: the first one given)"},
          {"--job", "", true, "a job (.trace) whose parameter names the posts may use, as a run of it would allow"},
          {"--include", "-I", true, "a folder where `inc` files are looked up"},
          {"--units", "", true, "metric (default) or inch"},
          {"--quiet", "-q", false, "print only the errors"},
      },
      run_check,
  };
}

}  // namespace postproc::cli
