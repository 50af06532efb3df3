// post_bench: end-to-end throughput of the engine on a long synthetic job posted through the
// shipped Fanuc post (read the trace, run the post, write the NC file), and the peak memory.
//
//   build-release/bin/post_bench [--motions N] [--post P.gpp] [--prp P.prp] [--job FILE]
//                                [--shape solidcam|flat|procedures] [--runs K]
//
// The generated job has the shape SolidCAM sends for the PRP (`solidcam`, the default): with
// procedures when gen_procs is Y or C, else flat. `flat` with a gen_procs = Y PRP measures our own
// procedure generation, which must hold the whole job before the post can start. The run is
// repeated K times (default 3) and the best and median are reported. Run it from the repository
// root, in a Release build. The run itself uses three threads (reader, PRP filters, post).
// Figures: docs/performance.md.
#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "bench/synthetic_job.hpp"
#include "postproc/engine/engine.hpp"
#include "prp/prp.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/trace_writer.hpp"

namespace {

long peak_rss_kib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
  return -1;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct RunResult {
  double seconds = 0;
  std::size_t commands = 0, lines = 0;
  std::uintmax_t out_bytes = 0;
};

RunResult post_once(const std::string& job, const std::string& post, const std::string& prp,
                    const std::filesystem::path& work) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  postproc::EngineOptions engine_options;
  engine_options.post = post;
  engine_options.prp = prp;
  postproc::Engine engine(engine_options);
  auto reader = toolpath::TraceReader::open(job);
  postproc::OutputFiles files(work);
  postproc::RunOptions options;
  options.input_name = job;
  options.main_path = [&](const std::string& name) { return work / name; };
  auto summary = engine.run(*reader, files, options);
  auto written = files.commit();
  RunResult r{seconds_since(t0), summary.commands, summary.lines, 0};
  for (const auto& p : written) r.out_bytes += fs::file_size(p);
  return r;
}

bench::JobShape shape_for(const std::string& shape, const std::string& prp) {
  if (shape == "flat") return bench::JobShape::flat;
  if (shape == "procedures") return bench::JobShape::procedures;
  const std::string& g = prp::load_file(prp, prp::Units::Metric).text("gen_procs");
  return toolpath::iequals(g, "Y") || toolpath::iequals(g, "C") ? bench::JobShape::procedures : bench::JobShape::flat;
}

}  // namespace

int run(int argc, char** argv) {
  std::size_t motions = 10'000'000, runs = 3;
  std::string post = "machines/fanuc/fanuc.gpp", prp = "machines/fanuc/fanuc.prp", job, shape = "solidcam";
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--motions") motions = std::strtoull(argv[i + 1], nullptr, 10);
    else if (a == "--post") post = argv[i + 1];
    else if (a == "--prp") prp = argv[i + 1];
    else if (a == "--job") job = argv[i + 1];
    else if (a == "--shape") shape = argv[i + 1];
    else if (a == "--runs") runs = std::max<std::size_t>(1, std::strtoull(argv[i + 1], nullptr, 10));
    else {
      std::cerr << "usage: post_bench [--motions N] [--post P.gpp] [--prp P.prp] [--job FILE]"
                   " [--shape solidcam|flat|procedures] [--runs K]\n";
      return 2;
    }
  }
  if (argc % 2 == 0 || (shape != "solidcam" && shape != "flat" && shape != "procedures")) {
    std::cerr << "post_bench: options take one value each; --shape is solidcam, flat or procedures\n";
    return 2;
  }
  namespace fs = std::filesystem;
  const fs::path work = fs::temp_directory_path() / fmt::format("post_bench-{}", ::getpid());
  fs::create_directories(work);
  struct RemoveAtExit {  // the job and the NC files go, whether the runs succeed or throw
    const fs::path& path;
    ~RemoveAtExit() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  } remove_at_exit{work};
  std::string made;
  if (job.empty()) {
    const bench::JobShape s = shape_for(shape, prp);
    made = s == bench::JobShape::procedures ? "procedures" : "flat";
    job = (work / "job.trace").string();
    bench::write_job(job, motions, s);
  }
  // The job file was just written: let the disk take it now, or its write-back would slow the
  // timed runs (a job a user posts has long been on disk).
  ::sync();
  const double megabytes = static_cast<double>(fs::file_size(job)) / 1e6;

  // Reading alone, to tell the reader's share from the engine's.
  auto t0 = std::chrono::steady_clock::now();
  std::size_t read_count = 0;
  {
    auto reader = toolpath::TraceReader::open(job);
    toolpath::Command c;
    while (reader->next(c)) ++read_count;
  }
  double read_s = seconds_since(t0);

  std::vector<RunResult> results;
  for (std::size_t i = 0; i < runs; ++i) results.push_back(post_once(job, post, prp, work));
  std::sort(results.begin(), results.end(), [](const RunResult& a, const RunResult& b) { return a.seconds < b.seconds; });
  const RunResult& best = results.front();
  const RunResult& median = results[results.size() / 2];
  auto rate = [&](const RunResult& r) { return static_cast<double>(r.commands) / r.seconds / 1e6; };

  std::cout << fmt::format("job: {} commands, {:.1f} MB ({}{})\n", read_count, megabytes, job,
                           made.empty() ? "" : ", shape " + made);
  std::cout << fmt::format("read only:   {:.2f} s  {:.2f} M commands/s  {:.0f} MB/s\n", read_s,
                           static_cast<double>(read_count) / read_s / 1e6, megabytes / read_s);
  std::cout << fmt::format("end to end, best of {}:  {:.2f} s  {:.2f} M commands/s  {:.0f} MB/s in\n", runs,
                           best.seconds, rate(best), megabytes / best.seconds);
  std::cout << fmt::format("end to end, median:     {:.2f} s  {:.2f} M commands/s  {:.0f} MB/s in\n",
                           median.seconds, rate(median), megabytes / median.seconds);
  std::cout << fmt::format("NC out: {:.1f} MB ({} lines)\n", static_cast<double>(best.out_bytes) / 1e6, best.lines);
  std::cout << fmt::format("peak memory: {:.1f} MB\n", static_cast<double>(peak_rss_kib()) / 1024.0);
  return 0;
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {  // a PRP or post that does not load, a job that does not post
    std::cerr << "post_bench: " << e.what() << '\n';
    return 1;
  }
}
