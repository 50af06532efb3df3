// post_bench: end-to-end throughput of the engine on a long synthetic job posted through the
// shipped Fanuc post (read the trace, run the post, write the NC file), and the peak memory.
//
//   build-release/bin/post_bench [--motions N] [--post P.gpp] [--prp P.prp] [--job FILE]
//
// Run it from the repository root, in a Release build. The run itself uses three threads (reader,
// PRP filters, post). Figures: docs/performance.md.
#include <fmt/format.h>

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "bench/synthetic_job.hpp"
#include "postproc/engine.hpp"
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

}  // namespace

int main(int argc, char** argv) {
  std::size_t motions = 10'000'000;
  std::string post = "machines/fanuc/fanuc.gpp", prp = "machines/fanuc/fanuc.prp", job;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string a = argv[i];
    if (a == "--motions") motions = std::strtoull(argv[i + 1], nullptr, 10);
    else if (a == "--post") post = argv[i + 1];
    else if (a == "--prp") prp = argv[i + 1];
    else if (a == "--job") job = argv[i + 1];
    else {
      std::cerr << "usage: post_bench [--motions N] [--post P.gpp] [--prp P.prp] [--job FILE]\n";
      return 2;
    }
  }
  namespace fs = std::filesystem;
  fs::path work = fs::temp_directory_path() / fmt::format("post_bench-{}", ::getpid());
  fs::create_directories(work);
  if (job.empty()) {
    job = (work / "job.trace").string();
    std::ofstream out(job, std::ios::binary);
    bench::SyntheticJob source(motions);
    toolpath::TraceWriter writer(out);
    toolpath::Command c;
    while (source.next(c)) writer.write(c);
  }
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

  t0 = std::chrono::steady_clock::now();
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
  double run_s = seconds_since(t0);
  std::uintmax_t out_bytes = 0;
  for (const auto& p : written) out_bytes += fs::file_size(p);

  std::cout << fmt::format("job: {} commands, {:.1f} MB ({})\n", read_count, megabytes, job);
  std::cout << fmt::format("read only:   {:.2f} s  {:.2f} M commands/s  {:.0f} MB/s\n", read_s,
                           static_cast<double>(read_count) / read_s / 1e6, megabytes / read_s);
  std::cout << fmt::format("end to end:  {:.2f} s  {:.2f} M commands/s  {:.0f} MB/s in, {:.1f} MB NC out ({} lines)\n",
                           run_s, static_cast<double>(summary.commands) / run_s / 1e6, megabytes / run_s,
                           static_cast<double>(out_bytes) / 1e6, summary.lines);
  std::cout << fmt::format("peak memory: {:.1f} MB\n", static_cast<double>(peak_rss_kib()) / 1024.0);
  fs::remove_all(work);
  return 0;
}
