// `postproc verify --post P.gpp [--prp P.prp] [--dialect NAME] JOB.trace`: posts a job, reads the
// NC program back with the controller model the post writes for (the registry's first by default)
// and compares the motion with the toolpath.
#include <fmt/format.h>

#include <ostream>
#include <string>

#include "machines/registry/registry.hpp"
#include "postproc/cli/cli.hpp"
#include "postproc/cli/cli_support.hpp"
#include "postproc/cli/open_input.hpp"
#include "postproc/checks/verify.hpp"
#include "toolpath/value.hpp"

namespace postproc::cli {
namespace {

double positive_number(const Arguments& args, std::string_view option, double fallback) {
  if (!args.has(option)) return fallback;
  std::string text = args.value(option);
  try {
    std::size_t used = 0;
    double v = std::stod(text, &used);
    if (used == text.size() && v > 0) return v;
  } catch (const std::exception&) {
  }
  throw UsageError{fmt::format("{} needs a positive number, not `{}`", option, text)};
}

// The controller the post writes for, from the registry; the run's answers go with it (a program
// may depend on the application's settings, which the post asks for).
const machines::Controller& verify_controller(const std::string& dialect) {
  if (const machines::Controller* c = machines::find_controller(dialect)) return *c;
  throw UsageError{"verify knows the controllers " + machines::controller_names() + ", not `" + dialect + "`"};
}

machines::ReadOptions verify_read_options(const Arguments& args, const EngineOptions& engine) {
  machines::ReadOptions read = read_options(args);
  for (const auto& a : engine.answers) read.answers.emplace_back(a.name, a.value);
  return read;
}

std::string_view verify_dialect_help() {
  static const std::string help = fmt::format("the controller of the post: {} (default {})", machines::controller_names(),
                                              machines::default_controller().names().front());
  return help;
}

void print_side(std::ostream& out, std::string_view label, const std::optional<verify::Motion>& m) {
  out << fmt::format("  {:<9}{}\n", label, m ? verify::describe(*m) : std::string("(nothing)"));
}

int run_verify(const Arguments& args, std::ostream& out, std::ostream& err) {
  if (args.positional().size() != 1) throw UsageError{"expected one job file"};
  EngineOptions engine_opts = engine_options(args, &err);
  verify::Tolerances tolerances;
  tolerances.position = positive_number(args, "--tolerance", tolerances.position);
  std::optional<std::filesystem::path> keep;
  if (args.has("--nc")) keep = args.value("--nc");

  const std::string& job = args.positional()[0];
  const std::string dialect = args.value("--dialect", std::string(machines::default_controller().names().front()));
  const machines::Controller& controller = verify_controller(dialect);
  Engine engine(engine_opts);
  print_machine_warnings(engine, err);  // before posting, as `run` does
  verify::JobReport report = verify::verify_job(engine, job, tolerances, keep, controller, dialect,
                                                verify_read_options(args, engine_opts), &err);
  const auto& r = report.result;
  // Say which controller model read the NC: a post for another controller is not verified by it.
  const std::string model = fmt::format("the {} model (--dialect {})", controller.title(), dialect);
  // The machine-state findings: an error fails the run even when the motion matches.
  bool scrap = false;
  for (const auto& f : report.findings) {
    const bool error = f.severity == toolpath::Severity::Error;
    scrap |= error;
    out << fmt::format("{}:{}: {}: {}{}\n", report.program.filename().string(), f.line, error ? "error" : "warning",
                       f.what, f.count > 1 ? fmt::format(" ({} times)", f.count) : "");
  }
  if (!r.divergence) {
    if (!args.has("--quiet") || scrap) {
      out << fmt::format("{}: {}, {} motion events match; NC read by {}\n", job,
                         scrap ? "the motion matches but the machine state does not" : "ok", r.compared, model);
      out << fmt::format("  cycle time {}\n", verify::describe(report.cycle_time));
    }
    return scrap ? kBadInput : kOk;
  }
  const auto& d = *r.divergence;
  out << fmt::format("{}: divergence at motion event {}: {}\n", job, d.ordinal, d.what);
  out << fmt::format("  toolpath: {}\n", report.expected_command.empty() ? "(ended)" : report.expected_command);
  out << fmt::format("  NC:       {}\n", report.nc_line.empty() ? "(ended)" : report.nc_line);
  print_side(out, "expected", d.expected);
  print_side(out, "actual", d.actual);
  out << fmt::format("  NC read by {}\n", model);
  return kBadInput;
}

}  // namespace

Subcommand verify_command() {
  std::vector<OptionSpec> options = engine_option_specs();
  // verify posts quietly
  std::erase_if(options, [](const OptionSpec& o) { return o.name == "--trace" || o.name == "--progress"; });
  options.push_back({"--tolerance", "", true, "mm by which positions, centres and radii may differ (default 0.001)"});
  options.push_back({"--nc", "", true, "also write the NC program that was read back to this file"});
  options.push_back({"--quiet", "-q", false, "print nothing when the motion matches"});
  options.push_back({"--dialect", "", true, verify_dialect_help()});
  options.push_back(kToolTableOption);
  return {
      "verify",
      "postproc verify --post P.gpp [--prp P.prp] [--dialect NAME] [--tolerance MM] [--nc FILE] JOB.trace",
      "Post a job, read the NC back with the model of the controller it is for (--dialect), compare the motion.",
      options,
      run_verify,
  };
}

}  // namespace postproc::cli
