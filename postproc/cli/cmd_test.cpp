// `postproc test JOB.trace --post P.gpp [--expect DIR|FILE] [--update]`: regression test of a post.
#include <fmt/format.h>

#include <algorithm>
#include <ostream>
#include <vector>

#include "postproc/cli/cli.hpp"
#include "postproc/engine/directive.hpp"
#include "postproc/cli/cli_support.hpp"
#include "postproc/checks/regression.hpp"
#include "toolpath/value.hpp"

namespace postproc::cli {
namespace {

// Feeds the comparer the lines it should see: every generated line (directives included) against a
// trace, the main file against a golden file, or every file against a golden folder.
class Feeder final : public LineObserver {
public:
  enum class Mode { Trace, File, Folder };
  Feeder(RegressionComparer& comparer, Mode mode, std::string trace_name)
      : comparer_(comparer), mode_(mode), trace_name_(std::move(trace_name)) {}
  void on_line(const LineEvent& e) override {
    if (mode_ == Mode::Trace) {
      if (!e.leading_break) comparer_.produced(trace_name_, e.text, e.origin);  // no `>` line shows it
      return;
    }
    if (e.directive) {  // executed, never written; a file the run deletes is not left "not compared"
      // The break before the directive ends the file's last line (an empty one included).
      comparer_.break_written(mode_ == Mode::File && e.main_file ? main_name_ : std::string(e.file));
      if (auto d = parse_directive(e.text); d && d->verb == Directive::Verb::Delete) comparer_.discarded(d->name);
      return;
    }
    if (mode_ == Mode::File && !e.main_file) {
      comparer_.produced(std::string(e.file), e.text, e.origin);  // reported as not compared
      return;
    }
    comparer_.produced(mode_ == Mode::File ? main_name_ : std::string(e.file), e.text, e.origin);
  }
  void on_slot_filled(std::uint32_t slot, std::string_view text) override { comparer_.filled(slot, text); }
  std::string main_name_;

private:
  RegressionComparer& comparer_;
  Mode mode_;
  std::string trace_name_;
};

CompareOptions compare_options(const Arguments& args) {
  CompareOptions o;
  o.ignore_block_numbers = args.has("--ignore-block-numbers");
  o.ignore_trailing_blanks = args.has("--ignore-trailing-blanks");
  o.ignore_leading_blanks = args.has("--ignore-leading-blanks");
  o.ignore_datetime = args.has("--ignore-dates");
  if (args.has("--tolerance")) {
    std::string t = args.value("--tolerance");
    char* end = nullptr;
    o.numeric_tolerance = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0' || o.numeric_tolerance < 0)
      throw UsageError{"--tolerance needs a number >= 0, not `" + t + "`"};
  }
  return o;
}

// The golden file of an output file in a golden folder: the same name, else the same name in
// another case (SolidCAM runs on Windows: `g_file_name` says `PART_MILLING.MPF` where the file on
// disk is `Part_Milling.MPF`). Empty when there is none.
std::filesystem::path golden_file(const std::string& folder, const std::string& stream) {
  std::filesystem::path exact = std::filesystem::path(folder) / stream;
  if (std::filesystem::exists(exact)) return exact;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
    if (entry.is_regular_file() && toolpath::iequals(entry.path().filename().string(), stream)) return entry.path();
  return {};
}

// The NC files of a golden folder: everything but the job, the post and notes kept beside them.
std::vector<std::string> golden_files(const std::string& folder) {
  static const char* const not_output[] = {".trace", ".gpp", ".prp", ".vmid", ".mac", ".md", ".txt", ".json"};
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (!entry.is_regular_file()) continue;
    std::string ext = entry.path().extension().string();
    bool output = true;
    for (const char* e : not_output) output = output && !toolpath::iequals(ext, e);
    if (output) names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// One line a file, `NAME: 312/315 lines identical, first difference at line 41`, then the sum.
std::string parity_figures(const std::vector<StreamParity>& figures, const std::string& main_name,
                           const std::string& main_key) {
  std::string r;
  std::size_t identical = 0, expected = 0;
  for (const auto& p : figures) {
    identical += p.identical;
    expected += p.expected;
    r += fmt::format("{}: {}/{} lines identical", p.stream == main_key ? main_name : p.stream, p.identical, p.expected);
    if (!p.written) r += " (the run wrote no such file)";
    else if (p.first_difference > 0) r += fmt::format(", first difference at line {}", p.first_difference);
    if (p.produced != p.expected && p.written) r += fmt::format(" ({} lines written)", p.produced);
    if (p.approximate) r += " (too different to align: compared line by line)";
    r += '\n';
  }
  const double percent = expected == 0 ? 100.0 : 100.0 * double(identical) / double(expected);
  r += fmt::format("parity: {}/{} lines identical ({:.1f}%) in {} file{}\n", identical, expected,
                   percent, figures.size(), figures.size() == 1 ? "" : "s");
  return r;
}

int update_golden(const Engine& engine, Input& input, const std::string& expect, std::ostream& err, bool quiet) {
  bool folder = std::filesystem::is_directory(expect) || expect.back() == '/';
  Destination to = Destination::parse(folder && expect.back() != '/' ? expect + "/" : expect);
  std::filesystem::create_directories(to.directory);
  OutputFiles files(to.directory);
  RunOptions options = run_options(input, err);
  options.main_path = [&](const std::string& default_name) -> std::filesystem::path {
    return to.main_file.empty() ? to.directory / default_name : to.main_file;
  };
  engine.run(*input.reader, files, options);
  for (const auto& path : files.commit())
    if (!quiet) err << "updated " << path.string() << '\n';
  return kOk;
}

int run_test(const Arguments& args, std::ostream& out, std::ostream& err) {
  if (args.positional().size() != 1) throw UsageError{"expected one job file"};
  EngineOptions engine_opts = engine_options(args, &err);
  CompareOptions compare = compare_options(args);
  std::string expect = args.value("--expect");
  bool quiet = args.has("--quiet");
  if (args.has("--update") && expect.empty()) throw UsageError{"--update needs --expect (a trace cannot be rewritten)"};

  Engine engine(engine_opts);
  print_machine_warnings(engine, err);
  Input input = Input::open(args.positional()[0]);
  if (args.has("--update")) return update_golden(engine, input, expect, err, quiet);

  Feeder::Mode mode = expect.empty() ? Feeder::Mode::Trace
                      : std::filesystem::is_directory(expect) ? Feeder::Mode::Folder
                                                              : Feeder::Mode::File;
  const std::string main_key = "(main program)";
  RegressionComparer::Opener opener = [&](const std::string& stream) -> std::unique_ptr<ExpectedLines> {
    switch (mode) {
      case Feeder::Mode::Trace: return expected_from_trace(input.path);
      case Feeder::Mode::File: return stream == main_key ? expected_from_file(expect) : nullptr;
      case Feeder::Mode::Folder: {
        auto golden = golden_file(expect, stream);
        return golden.empty() ? nullptr : expected_from_file(golden.string());
      }
    }
    return nullptr;
  };
  RegressionComparer comparer(opener, compare, std::filesystem::path(engine_opts.post).filename().string());
  Feeder feeder(comparer, mode, input.path);
  feeder.main_name_ = main_key;

  OutputFiles files(".", OutputFiles::LineEnd::LF, true);  // nothing is written to disk
  RunOptions options = run_options(input, err);
  TraceOutput trace(args, err);
  trace.apply(options);
  options.observer = &feeder;
  Progress progress(err, quiet, input, args.has("--progress"));
  options.progress = [&](std::size_t n) { progress.update(n); };
  const bool diff = args.has("--diff");
  if (diff) comparer.keep_origins();
  if (mode != Feeder::Mode::Trace) comparer.compare_file_lines();
  engine.run(*input.reader, files, options);
  if (mode == Feeder::Mode::Folder) {
    // A golden file the run never wrote is missing output, all of it.
    for (const auto& name : golden_files(expect))
      if (!comparer.has_stream(name)) comparer.not_written(name);
  }
  comparer.finish();

  std::string report = comparer.report();
  const std::string stream_main = mode == Feeder::Mode::File ? expect : main_key;
  if (mode == Feeder::Mode::File) {
    // Name the main program by the golden file in the report.
    const std::string from = main_key + ":";
    if (report.rfind(from, 0) == 0) report = expect + ":" + report.substr(from.size());
  }
  if (comparer.difference_count() > 0 || args.has("--parity") || diff) {
    out << parity_figures(comparer.parity(), stream_main, main_key);
    if (diff) out << comparer.diff_report();
  }
  if (comparer.difference_count() > 0) {
    out << report;
    return kBadInput;
  }
  if (comparer.lines_compared() == 0) {
    // A green test with nothing behind it is worse than a red one.
    std::string written;
    for (const auto& s : comparer.unmatched_streams()) written += (written.empty() ? "" : ", ") + s;
    out << fmt::format("nothing was compared: {} holds no golden file for the output ({})\n",
                       expect.empty() ? input.path : expect, written.empty() ? "no lines" : written);
    return kBadInput;
  }
  if (!quiet) {
    out << fmt::format("ok: {} lines match", comparer.lines_compared());
    for (const auto& s : comparer.unmatched_streams()) out << fmt::format("; {} not compared (no golden file)", s);
    out << '\n';
  }
  return kOk;
}

}  // namespace

Subcommand test_command() {
  std::vector<OptionSpec> options = engine_option_specs();
  options.insert(options.end(), {
      {"--expect", "", true, "golden output: the main program's file, or a folder of files by name "
                             "(default: the `>` lines of the trace)"},
      {"--update", "", false, "rewrite the golden file or folder from this run"},
      {"--ignore-block-numbers", "", false, "compare lines without their leading N number"},
      {"--ignore-trailing-blanks", "", false, "ignore blanks at line ends"},
      {"--ignore-leading-blanks", "", false, "ignore blanks at line starts"},
      {"--ignore-dates", "", false, "ignore dates and times inside comments"},
      {"--tolerance", "", true, "numbers match when they differ by at most this much"},
      {"--parity", "", false, "print the parity figure of every file even when the test passes"},
      {"--diff", "", false, "print every difference, each output line with the command and GPP line "
                            "that wrote it"},
      {"--quiet", "-q", false, "print nothing when the test passes; no progress bar"},
  });
  return {
      "test",
      "postproc test --post P.gpp [--prp P.prp] [--expect DIR|FILE] [--update] [options] JOB.trace",
      "Regression test: post a job and compare with golden output; exit 1 at the first difference.",
      options,
      run_test,
  };
}

}  // namespace postproc::cli
