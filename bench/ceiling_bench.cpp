// ceiling_bench: the engine against a hand-written post (issue 25). For each shape of the
// synthetic job (bench/synthetic_job.hpp) it runs `postproc run` with the shipped Fanuc post and
// the hand-written Fanuc post (bench/hand_post.hpp, the `hand_post` program) one after the other,
// N times, checks that both wrote the same NC bytes, and prints the median wall time of each, the
// ratio engine / hand-written, their CPU time and their peak memory.
//
//   build-release/bin/ceiling_bench [--motions N] [--runs N] [--shape procedures|flat|both]
//                                   [--post P.gpp] [--prp P.prp] [--job FILE]...
//
// Defaults: 1 000 000 motions, 5 runs, both shapes, machines/fanuc/fanuc.gpp and .prp (run it from
// the repository root, Release build). `procedures` is the job as SolidCAM sends it for
// gen_procs = Y (make_job --procedures), `flat` the inline job the engine makes procedures of with
// the shipped PRP (make_job). `--job FILE` posts that trace instead of a generated job (repeat it
// for several). On one core: `taskset -c 0 build-release/bin/ceiling_bench` (both programs inherit
// the affinity; the engine's three threads then share that core).
//
// Both are separate processes, started the same way (posix_spawn) and timed from the start to
// their exit: the engine's start-up (loading the post and the PRP) counts, as it does for a user.
// CPU time and peak memory are each process's own (wait4's rusage). The programs are looked up
// beside this one (the build's bin/ folder).
#include <fmt/format.h>

#include <fcntl.h>
#include <sched.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/synthetic_job.hpp"
#include "toolpath/trace_writer.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;

struct Sample {
  double wall = 0, user = 0, sys = 0;
  long peak_kib = 0;
  double cpu() const { return user + sys; }
};

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) / 1e6; }

// Runs argv[0] with its arguments and waits for it: wall time from the spawn to the exit, and the
// child's own rusage. Throws when it cannot start or does not exit with 0.
Sample run_program(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (const int e = ::posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ); e != 0)
    throw std::runtime_error(fmt::format("cannot start {}: {}", args[0], std::strerror(e)));
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0)
    if (errno != EINTR) throw std::runtime_error(fmt::format("wait4: {}", std::strerror(errno)));
  Sample s;
  s.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string command;
    for (const auto& a : args) command += (command.empty() ? "" : " ") + a;
    throw std::runtime_error(fmt::format("{} failed (status {:#x})", command, status));
  }
  s.user = seconds(usage.ru_utime);
  s.sys = seconds(usage.ru_stime);
  s.peak_kib = usage.ru_maxrss;  // KiB on Linux
  return s;
}

struct Compared {
  bool same = false;
  std::uintmax_t bytes = 0, lines = 0;
  std::string difference;  // where they first differ
};

// The two files byte for byte; their size and line count.
Compared compare_files(const fs::path& a, const fs::path& b) {
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  if (!fa || !fb) throw std::runtime_error(fmt::format("cannot read {} or {}", a.string(), b.string()));
  Compared c;
  std::vector<char> ba(1 << 20), bb(1 << 20);
  std::uintmax_t line = 1;
  for (;;) {
    fa.read(ba.data(), static_cast<std::streamsize>(ba.size()));
    fb.read(bb.data(), static_cast<std::streamsize>(bb.size()));
    const auto na = static_cast<std::size_t>(fa.gcount()), nb = static_cast<std::size_t>(fb.gcount());
    const std::size_t n = std::min(na, nb);
    const auto diff = std::mismatch(ba.begin(), ba.begin() + static_cast<std::ptrdiff_t>(n), bb.begin());
    const auto same = static_cast<std::size_t>(diff.first - ba.begin());
    line += static_cast<std::uintmax_t>(std::count(ba.begin(), ba.begin() + static_cast<std::ptrdiff_t>(same), '\n'));
    c.bytes += same;
    if (same < n || na != nb) {
      c.difference = fmt::format("byte {}, line {}{}", c.bytes, line, same == n ? " (one file ends there)" : "");
      return c;
    }
    if (n == 0) break;
  }
  c.same = true;
  c.lines = c.bytes == 0 ? 0 : line;  // lines are separated: the last one has no line break
  return c;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

struct Series {
  std::vector<Sample> samples;
  double median_wall() const {
    std::vector<double> v;
    for (const auto& s : samples) v.push_back(s.wall);
    return median(v);
  }
  double min_wall() const {
    double m = samples.front().wall;
    for (const auto& s : samples) m = std::min(m, s.wall);
    return m;
  }
  double median_cpu() const {
    std::vector<double> v;
    for (const auto& s : samples) v.push_back(s.cpu());
    return median(v);
  }
  double median_user() const {
    std::vector<double> v;
    for (const auto& s : samples) v.push_back(s.user);
    return median(v);
  }
  double median_sys() const {
    std::vector<double> v;
    for (const auto& s : samples) v.push_back(s.sys);
    return median(v);
  }
  long peak_kib() const {
    long m = 0;
    for (const auto& s : samples) m = std::max(m, s.peak_kib);
    return m;
  }
};

struct Case {
  std::string name;
  fs::path job;
};

std::string loadavg() {
  std::ifstream in("/proc/loadavg");
  std::string one, five;
  in >> one >> five;
  return one.empty() ? "?" : one + " " + five;
}

int usage() {
  std::cerr << "usage: ceiling_bench [--motions N] [--runs N] [--shape procedures|flat|both] [--post P.gpp]"
               " [--prp P.prp] [--job FILE]... [--engine POSTPROC]...\n"
               "  --engine: the postproc binary to measure (default: the one beside ceiling_bench); give it twice\n"
               "  to compare two builds side by side (before and after a change), each against the hand-written post\n";
  return 2;
}

int run(int argc, char** argv) {
  std::size_t motions = 1'000'000, runs = 5;
  std::string shape = "both", post = "machines/fanuc/fanuc.gpp", prp = "machines/fanuc/fanuc.prp";
  std::vector<std::string> jobs, engines;
  for (int i = 1; i < argc; i += 2) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return usage();
    const char* value = argv[i + 1];
    if (a == "--motions") motions = std::strtoull(value, nullptr, 10);
    else if (a == "--runs") runs = std::max<std::size_t>(1, std::strtoull(value, nullptr, 10));
    else if (a == "--shape") shape = value;
    else if (a == "--post") post = value;
    else if (a == "--prp") prp = value;
    else if (a == "--job") jobs.emplace_back(value);
    else if (a == "--engine") engines.emplace_back(value);
    else return usage();
  }
  if (shape != "procedures" && shape != "flat" && shape != "both") return usage();

  const fs::path bin = fs::read_symlink("/proc/self/exe").parent_path();
  if (engines.empty()) engines.push_back((bin / "postproc").string());
  const std::string hand = (bin / "hand_post").string();
  std::vector<std::string> programs = engines;
  programs.push_back(hand);
  for (const auto& program : programs)
    if (::access(program.c_str(), X_OK) != 0) throw std::runtime_error(program + " is missing: build it first");
  for (const auto& file : {post, prp})
    if (!fs::exists(file)) throw std::runtime_error(file + " not found: run from the repository root");

  const fs::path work = fs::temp_directory_path() / fmt::format("ceiling_bench-{}", ::getpid());
  fs::create_directories(work);
  struct RemoveAtExit {  // the jobs and the NC files go, whether the runs succeed or throw
    const fs::path& path;
    ~RemoveAtExit() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  } remove_at_exit{work};

  std::vector<Case> cases;
  if (!jobs.empty()) {
    for (const auto& j : jobs) cases.push_back({j, fs::path(j)});
  } else {
    for (const auto& [name, s] : {std::pair{"procedures", bench::JobShape::procedures}, std::pair{"flat", bench::JobShape::flat}}) {
      if (shape != "both" && shape != name) continue;
      const fs::path path = work / (std::string(name) + ".trace");
      std::cerr << "making the " << name << " job (" << motions << " motions)...\n";
      bench::write_job(path.string(), motions, s);
      cases.push_back({fmt::format("{} (make_job{} {})", name, std::string(name) == "procedures" ? " --procedures" : "",
                                   motions),
                       path});
    }
  }
  // The jobs were just written: let the disk take them now, or their write-back would slow the
  // timed runs (a job a user posts has long been on disk).
  ::sync();

  cpu_set_t cpus;
  CPU_ZERO(&cpus);
  const int cpu_count = ::sched_getaffinity(0, sizeof cpus, &cpus) == 0 ? CPU_COUNT(&cpus) : -1;
  std::cout << fmt::format("ceiling_bench: {} run(s) of each, alternating (engine{}, then hand-written); {} CPU(s); "
                           "load average {} before\n",
                           runs, engines.size() > 1 ? "s" : "", cpu_count, loadavg());
  for (std::size_t k = 0; k < engines.size(); ++k)
    std::cout << fmt::format("engine {}: {} run -q --post {} --prp {}\n", k + 1, engines[k], post, prp);
  std::cout << fmt::format("hand-written: {}\n", hand);

  const fs::path hand_nc = work / "hand.nc";
  bool all_same = true;
  for (const Case& c : cases) {
    std::vector<Series> e(engines.size());
    Series h;
    Compared last;
    for (std::size_t r = 0; r < runs && all_same; ++r) {
      // engine 1, engine 2, ..., then the hand-written post, whose NC each engine's must equal
      for (std::size_t k = 0; k < engines.size(); ++k) {
        const fs::path nc = work / fmt::format("engine{}.nc", k + 1);
        fs::remove(nc);
        e[k].samples.push_back(
            run_program({engines[k], "run", "-q", "--post", post, "--prp", prp, "-o", nc.string(), c.job.string()}));
      }
      fs::remove(hand_nc);
      h.samples.push_back(run_program({hand, c.job.string(), hand_nc.string()}));
      for (std::size_t k = 0; k < engines.size() && all_same; ++k) {
        last = compare_files(work / fmt::format("engine{}.nc", k + 1), hand_nc);
        if (!last.same) {
          std::cout << fmt::format("\n{}: THE NC PROGRAMS DIFFER (engine {}, run {}): first at {}\n", c.name, k + 1, r + 1,
                                   last.difference);
          all_same = false;
        }
      }
    }
    if (!last.same) continue;
    const double mb = static_cast<double>(fs::file_size(c.job)) / 1e6;
    std::cout << fmt::format("\n{}: trace {:.1f} MB, NC {:.1f} MB, {} lines, byte-identical in every run\n", c.name, mb,
                             static_cast<double>(last.bytes) / 1e6, last.lines);
    std::cout << fmt::format("  {:<22} {:>12} {:>10}   {:<28} {:>10}\n", "", "wall median", "wall min",
                             "CPU median (user + sys)", "peak RSS");
    auto row = [](const char* who, const Series& s) {
      const std::string cpu = fmt::format("{:.3f} s ({:.3f} + {:.3f})", s.median_cpu(), s.median_user(), s.median_sys());
      std::cout << fmt::format("  {:<22} {:>10.3f} s {:>8.3f} s   {:<28} {:>7.1f} MB\n", who, s.median_wall(),
                               s.min_wall(), cpu, static_cast<double>(s.peak_kib()) / 1024.0);
    };
    for (std::size_t k = 0; k < engines.size(); ++k)
      row(engines.size() > 1 ? fmt::format("engine {}", k + 1).c_str() : "engine (postproc run)", e[k]);
    row("hand-written post", h);
    for (std::size_t k = 0; k < engines.size(); ++k)
      std::cout << fmt::format("  engine{} / hand-written: {:.2f}x wall (median), {:.2f}x CPU (median)\n",
                               engines.size() > 1 ? fmt::format(" {}", k + 1) : "", e[k].median_wall() / h.median_wall(),
                               e[k].median_cpu() / h.median_cpu());
  }
  return all_same ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "ceiling_bench: " << e.what() << '\n';
    return 1;
  }
}
