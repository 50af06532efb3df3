// `postproc verify --post P.gpp [--prp P.prp] JOB.trace`: posts a job with a PikoCNC post, reads
// the NC program back with the PikoCNC model and compares the motion with the toolpath.
#include <fmt/format.h>

#include <ostream>
#include <string>

#include "postproc/cli/cli.hpp"
#include "postproc/cli/cli_support.hpp"
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

// The controller the post writes for. A 2XAxisCNC post's machine speed and rapid coefficient are
// its `input` answers machine_speed and rapid_coef (the post's defaults otherwise).
verify::Target verify_target(const std::string& dialect, const EngineOptions& engine) {
  verify::Target t;
  if (dialect == "pikocnc" || dialect == "pikocnc-2025") return t;
  if (dialect != "2xaxiscnc") throw UsageError{"verify knows the dialects pikocnc and 2xaxiscnc, not `" + dialect + "`"};
  t.kind = verify::Target::Kind::TwoAxisCnc;
  for (const auto& a : engine.answers) {
    double* field = toolpath::iequals(a.name, "machine_speed") ? &t.machine_speed
                    : toolpath::iequals(a.name, "rapid_coef")  ? &t.rapid_coefficient
                                                               : nullptr;
    if (!field) continue;
    try {
      *field = std::stod(a.value);
    } catch (const std::exception&) {
      // the post rejects the answer itself, naming its input statement
    }
  }
  return t;
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
  const verify::Target target = verify_target(args.value("--dialect", "pikocnc"), engine_opts);
  Engine engine(engine_opts);
  print_machine_warnings(engine, err);  // before posting, as `run` does
  verify::JobReport report = verify::verify_job(engine, job, tolerances, keep, target, &err);
  const auto& r = report.result;
  // Say which controller model read the NC: a post for another controller is not verified by it.
  const std::string model = target.kind == verify::Target::Kind::TwoAxisCnc
                                ? "the 2XAxisCNC model (--dialect 2xaxiscnc)"
                                : "the PikoCNC model (--dialect pikocnc)";
  if (!r.divergence) {
    if (!args.has("--quiet")) out << fmt::format("{}: ok, {} motion events match; NC read by {}\n", job, r.compared, model);
    return kOk;
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
  options.push_back({"--dialect", "", true, "the controller of the post: pikocnc (default) or 2xaxiscnc"});
  return {
      "verify",
      "postproc verify --post P.gpp [--prp P.prp] [--dialect pikocnc|2xaxiscnc] [--tolerance MM] [--nc FILE] JOB.trace",
      "Post a job with a PikoCNC (or 2XAxisCNC) post, read the NC back with the controller model, compare the motion.",
      options,
      run_verify,
  };
}

}  // namespace postproc::cli
