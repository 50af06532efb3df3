// `postproc verify`: post a job, read its NC program back, compare (postproc/checks/verify.hpp).
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "postproc/checks/verify.hpp"
#include "prp/filters/time_estimate.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/value.hpp"

namespace postproc::verify {
namespace {

// A private temporary folder, removed with everything in it when the run is over.
class TemporaryFolder {
public:
  TemporaryFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "postproc-verify-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot make a temporary folder in " + pattern);
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
};

std::string line_of(const std::filesystem::path& file, std::size_t number) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (n == number) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return line;
    }
  }
  return {};
}

}  // namespace

JobReport verify_job(const Engine& engine, const std::string& job, const Tolerances& tolerances,
                     const std::optional<std::filesystem::path>& keep_program, const machines::Controller& controller,
                     std::string_view dialect, const machines::ReadOptions& read, std::ostream* warnings) {
  TemporaryFolder folder;
  std::filesystem::path main_file;
  const machines::VerifyProfile profile = controller.verify_profile(read);
  ExpectedMotion expected(engine.machine(), profile);
  {
    auto reader = toolpath::TraceReader::open(job);
    OutputFiles files(folder.path());
    RunOptions options;
    options.input_name = job;
    options.warnings = warnings;
    options.main_path = [&](const std::string& default_name) {
      main_file = folder.path() / default_name;
      return main_file;
    };
    options.reopen = [job]() -> std::unique_ptr<toolpath::CommandSource> { return toolpath::TraceReader::open(job); };
    options.posted = [&](const toolpath::Command& c) { expected.add(c); };
    engine.run(*reader, files, options);
    files.commit();
    main_file = files.main_path();
  }
  JobReport report;
  report.program = main_file;
  if (keep_program) {
    std::filesystem::copy_file(main_file, *keep_program, std::filesystem::copy_options::overwrite_existing);
    report.program = *keep_program;
  }
  auto expected_all = expected.motion();
  std::ostringstream discarded;  // the model's warnings, when the caller takes none
  // The cycle time of the program the model runs: split where the model changes the tool.
  prp::TimeEstimate estimate(prp::time_settings(engine.machine(prp::Units::Metric)));
  CycleTime& time = report.cycle_time;
  time.tools.push_back({});
  double tool_start = 0;
  StateChecks checks(profile, engine.machine(prp::Units::Metric).rotary_limits());
  auto observe = [&](const toolpath::Command& c, std::size_t line) {
    checks.command(c, line);
    const bool change = toolpath::iequals(c.name, "@change_tool") || toolpath::iequals(c.name, "@turn_change_tool");
    if (change) {
      const toolpath::Value* t = c.find("tool_number");
      const std::int64_t number = t ? static_cast<std::int64_t>(t->as_number()) : -1;
      if (time.tools.size() == 1 || number != time.tools.back().number) {  // the same tool again: one entry
        time.tools.back().seconds = estimate.seconds() - tool_start;
        tool_start = estimate.seconds();
        time.tools.push_back({number, 0});
      }
    }
    estimate.add(c);
  };
  auto actual_raw = nc_motion(main_file, controller, dialect, read, warnings ? *warnings : discarded, observe);
  auto expected_raw = as_programmed(*expected_all, profile);
  auto expected_motion = normalised(*expected_raw, tolerances);
  auto actual_motion = normalised(*actual_raw, tolerances);
  report.result = compare(*expected_motion, *actual_motion, tolerances);
  report.findings = checks.findings();
  time.tools.back().seconds = estimate.seconds() - tool_start;
  time.seconds = estimate.seconds();
  time.rapid_feed_missing = estimate.rapid_feed_missing();
  if (const auto& d = report.result.divergence) {
    if (d->expected) report.expected_command = fmt::format("command #{} {}", d->expected->where, d->expected->name);
    if (d->actual)
      report.nc_line = fmt::format("{}:{}: {}", report.program.filename().string(), d->actual->where,
                                   line_of(main_file, d->actual->where));
  }
  return report;
}

}  // namespace postproc::verify
