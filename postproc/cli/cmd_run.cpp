// `postproc run --post P.gpp [--prp P.prp] job.trace [-o DIR|FILE|-]`: posts a job.
#include <fmt/format.h>

#include <ostream>

#include "postproc/cli/cli.hpp"
#include "postproc/cli/cli_support.hpp"
#include "postproc/cli/open_input.hpp"

namespace postproc::cli {
namespace {

int run_run(const Arguments& args, std::ostream& out, std::ostream& err) {
  if (args.positional().size() != 1) throw UsageError{"expected one job file"};
  EngineOptions engine_opts = engine_options(args, &err);
  Destination to = Destination::parse(args.value("-o"));
  bool quiet = args.has("--quiet");
  auto line_end = args.has("--crlf") ? OutputFiles::LineEnd::CRLF : OutputFiles::LineEnd::LF;

  const std::string dialect = args.value("--dialect", "trace");
  RunOptions::ReaderThread reader_thread = RunOptions::ReaderThread::Auto;
  if (const std::string threads = args.value("--threads", ""); threads == "2") reader_thread = RunOptions::ReaderThread::Shared;
  else if (threads == "3") reader_thread = RunOptions::ReaderThread::Own;
  else if (!threads.empty()) throw UsageError{fmt::format("--threads is 2 or 3, not '{}'", threads)};

  Engine engine(engine_opts);
  print_machine_warnings(engine, err);
  if (!to.to_stdout) std::filesystem::create_directories(to.directory);
  OutputFiles files(to.directory, line_end, to.to_stdout);
  auto main_path = [&](const std::string& default_name) -> std::filesystem::path {
    if (to.to_stdout) return default_name;
    return to.main_file.empty() ? to.directory / default_name : to.main_file;
  };
  RunSummary summary;
  if (dialect == "trace") {
    Input input = Input::open(args.positional()[0]);
    RunOptions options = run_options(input, err);
    options.reader_thread = reader_thread;
    TraceOutput trace(args, err);
    trace.apply(options);
    options.main_path = main_path;
    Progress progress(err, quiet, input, args.has("--progress"));
    options.progress = [&](std::size_t n) { progress.update(n); };
    summary = engine.run(*input.reader, files, options);
  } else {
    // NC code read back by a controller model: its motion is posted again (closing the loop).
    auto source = open_source(args.positional()[0], dialect, err, read_options(args));
    RunOptions options;
    options.input_name = args.positional()[0];
    options.main_path = main_path;
    options.warnings = &err;
    options.reader_thread = reader_thread;
    summary = engine.run(*source, files, options);
  }
  if (to.to_stdout) {
    files.commit_to(out);
    return kOk;
  }
  auto written = files.commit();
  if (!quiet)
    for (const auto& path : written) err << "wrote " << path.string() << '\n';
  if (!quiet)
    err << fmt::format("{} commands ({} without a procedure), {} lines\n", summary.commands, summary.skipped,
                       summary.lines);
  return kOk;
}

}  // namespace

Subcommand run_command() {
  std::vector<OptionSpec> options = engine_option_specs();
  options.push_back({"-o", "", true, "output: - (stdout, the default), a folder, or the main file"});
  options.push_back({"--dialect", "", true, input_help()});
  options.push_back(kToolTableOption);
  options.push_back({"--crlf", "", false, "end lines with CR LF (as SolidCAM on Windows) instead of LF"});
  options.push_back({"--quiet", "-q", false, "no progress bar, no summary and no `input` log lines"});
  options.push_back({"--threads", "", true,
                     "2: the input is read on the PRP filters' thread, the post runs on the other; 3: reading "
                     "has a thread of its own. Default: 3 where the process may use 3 CPUs or more, else 2 "
                     "(the output is the same)"});
  return {
      "run",
      "postproc run --post P.gpp [--prp P.prp] [--dialect NAME] [-o DIR|FILE|-] JOB.trace|PROG.nc",
      "Post a job: write the NC program (to stdout unless -o names a folder or a file).",
      options,
      run_run,
  };
}

}  // namespace postproc::cli
