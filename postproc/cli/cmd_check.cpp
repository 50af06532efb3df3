// `postproc check FILE...`: static checks of posts (.gpp) and machine parameter files (.prp),
// printing every error with its position.
#include <fmt/format.h>

#include <algorithm>
#include <ostream>

#include "postproc/checks/post_check.hpp"
#include "postproc/cli/cli.hpp"
#include "postproc/cli/cli_support.hpp"
#include "postproc/engine/host_variables.hpp"
#include "prp/prp.hpp"

namespace postproc::cli {
namespace {

void print(const std::vector<toolpath::Diagnostic>& all, std::ostream& out) {
  for (const auto& d : all) out << d.text() << '\n';
}

std::size_t errors_in(const std::vector<toolpath::Diagnostic>& all) {
  return static_cast<std::size_t>(std::count_if(all.begin(), all.end(), [](const auto& d) { return d.error(); }));
}

int run_check(const Arguments& args, std::ostream& out, std::ostream&) {
  if (args.positional().empty()) throw UsageError{"expected one or more .gpp files or machine files (.prp, .mac, .vmid)"};
  std::string units_word = args.value("--units", "metric");
  if (units_word != "metric" && units_word != "inch") throw UsageError{"--units must be metric or inch"};
  auto units = units_word == "inch" ? prp::Units::Inch : prp::Units::Metric;

  // The PRP whose external variables the posts may use: --prp, or the first .prp among the files.
  std::string machine_file = args.value("--prp");
  for (const auto& path : args.positional())
    if (machine_file.empty() && is_machine_file(path)) machine_file = path;
  prp::MachineParameters machine;
  std::size_t errors = 0;
  if (!machine_file.empty()) {
    const auto found = check_machine_file(machine_file, units);
    if (args.has("--prp")) print(found, out);  // else reported below, as one of the files
    if (errors_in(found) == 0) machine = prp::load_file(machine_file, units);
    else if (args.has("--prp")) ++errors;
  }
  PostCheckOptions options;
  options.machine = &machine;
  if (args.has("--job")) {  // the names the job carries are defined, as in a run of that job
    Input job = Input::open(args.value("--job"));
    options.job_variables = job_variables(*job.reader);
  }
  if (args.has("--include")) options.include_paths.push_back(args.value("--include"));
  for (const auto& path : args.positional()) {
    const auto found = is_machine_file(path) ? check_machine_file(path, units) : check_post_file(path, options);
    print(found, out);
    const std::size_t n = errors_in(found);
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
