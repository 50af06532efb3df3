// A G-code program read back by our controller model beside LinuxCNC's `rs274` on the same file,
// as issue 25 compares them: both alternately, RUNS times each, both writing their full output to
// a file (rs274 its canonical calls, ours the trace `postproc read` prints); the medians and the
// ratio. The machine is shared and noisy, so only times of one run are compared.
//
// usage: readback_bench [--dialect NAME] [--runs N] [--make LINES] [--postproc BIN]... [--keep] [--out-dir DIR] PROGRAM
//   --dialect   controller model to read with (default pikocnc)
//   --runs      runs of each reader (default 5)
//   --make      first write a spiral milling program of LINES N-numbered blocks to PROGRAM
//   --postproc  run `BIN read --dialect NAME PROGRAM` as a process instead of reading in-process;
//               given more than once, each binary in turn (before and after a change, in one run),
//               and their outputs compared byte for byte
//   --keep      keep the outputs to compare or inspect; by default they are removed
//   --out-dir   where the outputs go (default /tmp); /dev/shm keeps the disk out of the times (a
//               run that overwrites its last 100 MB output may wait for that to reach the disk)
// rs274 is run when it is on PATH (`rs274 -t EMPTY.tbl PROGRAM OUT </dev/null`), otherwise skipped.
// Release build: cmake --build build-release --target readback_bench postproc
#include <fmt/format.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "machines/registry/registry.hpp"
#include "toolpath/trace_writer.hpp"

extern char** environ;

namespace {

// ---- the program: a spiral of short lines with a 30-degree arc every fifth block -------------

// A length in ten-thousandths of a millimetre, written with four decimals ("-0.0000" never).
std::string fixed4(std::int64_t units) {
  const bool negative = units < 0;
  const std::uint64_t u = negative ? static_cast<std::uint64_t>(-units) : static_cast<std::uint64_t>(units);
  return fmt::format("{}{}.{:04}", negative ? "-" : "", u / 10000, u % 10000);
}
std::int64_t units(double mm) { return std::llround(mm * 1e4); }

// Outward spiral (an Archimedean one with about 2 mm between turns) of 0.5 mm steps, in the subset
// of RS274 that PikoCNC and LinuxCNC both read. Every fifth block is a G2 or G3 (alternately) of 30
// degrees and 1 mm radius turning off the path and back; its centre is given by I J from the
// rounded start point, and its end is computed from that rounded centre, so that both ends lie on
// the circle within the rounding (LinuxCNC checks this).
void write_spiral_program(std::ostream& out, std::size_t blocks) {
  out << "%\nG21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F800\n";
  std::int64_t x = 0, y = 0;  // the current point, in ten-thousandths
  double heading = 0;
  constexpr double kStep = 0.5, kRadius = 1.0, kSweep = std::numbers::pi / 6;
  std::string line;
  for (std::size_t k = 1; k <= blocks; ++k) {
    line.clear();
    const double px = static_cast<double>(x) * 1e-4, py = static_cast<double>(y) * 1e-4;
    if (k % 5 == 0) {
      const bool ccw = (k / 5) % 2 == 0;
      const double side = ccw ? 1.0 : -1.0;  // the centre lies left of the path for a CCW arc
      const std::int64_t i = units(-std::sin(heading) * side * kRadius), j = units(std::cos(heading) * side * kRadius);
      const double cx = px + static_cast<double>(i) * 1e-4, cy = py + static_cast<double>(j) * 1e-4;
      const double r = std::hypot(px - cx, py - cy);
      const double start = std::atan2(py - cy, px - cx), end = start + side * kSweep;
      const std::int64_t ex = units(cx + r * std::cos(end)), ey = units(cy + r * std::sin(end));
      line = fmt::format("N{} {} X{} Y{} I{} J{}\n", k * 10, ccw ? "G3" : "G2", fixed4(ex), fixed4(ey), fixed4(i),
                         fixed4(j));
      x = ex;
      y = ey;
      heading += side * kSweep;
    } else {
      // Curvature of the spiral at this length of path: radius sqrt(2 * length / pi).
      const double length = kStep * static_cast<double>(k);
      heading += std::min(0.2, kStep / std::sqrt(2.0 * length / std::numbers::pi + 1.0));
      x = units(px + kStep * std::cos(heading));
      y = units(py + kStep * std::sin(heading));
      line = fmt::format("N{} G1 X{} Y{}\n", k * 10, fixed4(x), fixed4(y));
    }
    out << line;
  }
  out << "G0 Z5\nM30\n%\n";
}

// ---- timing ---------------------------------------------------------------------------------

struct Timing {
  double wall = 0, user = 0;  // seconds
  long peak_kb = 0;
};

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; }

std::optional<std::string> on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

// Runs `argv` with stdin from /dev/null, stdout to `stdout_path` and stderr discarded.
Timing run_process(const std::vector<std::string>& argv, const std::string& stdout_path) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ) != 0)
    throw std::runtime_error("cannot start " + argv[0]);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  Timing t;
  t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t.user = seconds(usage.ru_utime);
  t.peak_kb = usage.ru_maxrss;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(fmt::format("{} failed (status {})", argv[0], status));
  return t;
}

// `postproc read --dialect NAME PROGRAM > out`, in this process.
Timing read_in_process(const std::string& program, const std::string& dialect, const std::string& out_path) {
  const machines::Controller* controller = machines::find_controller(dialect);
  if (!controller) throw std::runtime_error("unknown dialect " + dialect + " (known: " + machines::controller_names() + ")");
  rusage before{}, after{};
  getrusage(RUSAGE_SELF, &before);
  const auto t0 = std::chrono::steady_clock::now();
  {
    std::ofstream out(out_path, std::ios::binary);
    std::ostringstream warnings;
    auto reader = controller->open(program, dialect, {}, warnings);
    toolpath::write_trace(*reader, out);
  }
  Timing t;
  t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  getrusage(RUSAGE_SELF, &after);
  t.user = seconds(after.ru_utime) - seconds(before.ru_utime);
  t.peak_kb = after.ru_maxrss;
  return t;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

std::string list(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += fmt::format("{}{:.2f}", s.empty() ? "" : " ", x);
  return s;
}

long file_size(const std::string& path) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  return f ? static_cast<long>(f.tellg()) : -1;
}

// One reader of the comparison and its times.
struct Reader {
  std::string label;     // "rs274", "in-process" or a postproc binary
  std::string binary;    // empty: in-process
  std::string output;    // where it writes
  std::vector<double> wall, user;
  long peak_kb = 0;
};

bool same_files(const std::string& a, const std::string& b) {
  std::ifstream x(a, std::ios::binary), y(b, std::ios::binary);
  std::vector<char> p(1 << 16), q(1 << 16);
  for (;;) {
    x.read(p.data(), static_cast<std::streamsize>(p.size()));
    y.read(q.data(), static_cast<std::streamsize>(q.size()));
    if (x.gcount() != y.gcount() || !std::equal(p.begin(), p.begin() + x.gcount(), q.begin())) return false;
    if (x.gcount() == 0) return true;
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string dialect = "pikocnc", program, out_dir = "/tmp";
  std::vector<std::string> binaries;
  int runs = 5;
  std::size_t make = 0;
  bool keep = false;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
        return argv[++i];
      };
      if (a == "--dialect") dialect = value();
      else if (a == "--runs") runs = std::max(1, std::stoi(value()));
      else if (a == "--make") make = std::stoul(value());
      else if (a == "--postproc") binaries.push_back(value());
      else if (a == "--keep") keep = true;
      else if (a == "--out-dir") out_dir = value();
      else if (!a.empty() && a[0] == '-') throw std::runtime_error("unknown option " + a);
      else program = a;
    }
    if (program.empty())
      throw std::runtime_error(
          "usage: readback_bench [--dialect NAME] [--runs N] [--make LINES] [--postproc BIN]... [--keep] [--out-dir DIR] PROGRAM");
    if (make > 0) {
      std::ofstream out(program, std::ios::binary);
      write_spiral_program(out, make);
      if (!out) throw std::runtime_error("cannot write " + program);
      fmt::print("wrote {} ({} blocks, {} bytes)\n", program, make, file_size(program));
    }
    if (file_size(program) < 0) throw std::runtime_error("cannot read " + program);

    const std::string base = fmt::format("{}/readback_bench.{}", out_dir, getpid());
    const std::string table = base + ".tbl";
    std::ofstream(table).flush();  // an empty tool table: rs274 wants one
    std::vector<Reader> readers;
    if (const std::optional<std::string> rs274 = on_path("rs274"))
      readers.push_back({"rs274", *rs274, base + ".rs274.out", {}, {}, 0});
    else
      fmt::print("rs274 is not on PATH: skipped (LinuxCNC's linuxcnc-uspace package has it)\n");
    const bool with_rs274 = !readers.empty();
    if (binaries.empty()) readers.push_back({"in-process", "", base + ".0.trace", {}, {}, 0});
    for (std::size_t i = 0; i < binaries.size(); ++i)
      readers.push_back({binaries[i], binaries[i], fmt::format("{}.{}.trace", base, i), {}, {}, 0});

    for (int run = 0; run < runs; ++run) {
      std::string line = fmt::format("run {}:", run + 1);
      for (Reader& r : readers) {
        const Timing t = r.label == "rs274" ? run_process({r.binary, "-t", table, program, r.output}, "/dev/null")
                         : r.binary.empty() ? read_in_process(program, dialect, r.output)
                                            : run_process({r.binary, "read", "--dialect", dialect, program}, r.output);
        r.wall.push_back(t.wall);
        r.user.push_back(t.user);
        r.peak_kb = std::max(r.peak_kb, t.peak_kb);
        line += fmt::format(" {:.2f} s", t.wall);
      }
      fmt::print("{}\n", line);
    }
    fmt::print("{} blocks read with --dialect {}, {} runs each, alternately; medians:\n", program, dialect, runs);
    for (const Reader& r : readers) {
      fmt::print("  {:<12} {:.3f} s wall, {:.3f} s user; peak RSS {} kB; output {} bytes", r.label, median(r.wall),
                 median(r.user), r.peak_kb, file_size(r.output));
      if (with_rs274 && &r != &readers.front())
        fmt::print("; rs274 / this: {:.1f}x wall, {:.1f}x user", median(readers.front().wall) / median(r.wall),
                   median(readers.front().user) / median(r.user));
      fmt::print("\n    wall: {}\n", list(r.wall));
    }
    const std::size_t ours = with_rs274 ? 1 : 0;
    for (std::size_t i = ours + 1; i < readers.size(); ++i)
      if (!same_files(readers[ours].output, readers[i].output))
        fmt::print("OUTPUTS DIFFER: {} and {}\n", readers[ours].label, readers[i].label);
    for (const Reader& r : readers) {
      if (keep) fmt::print("kept: {}\n", r.output);
      else std::remove(r.output.c_str());
    }
    std::remove(table.c_str());
  } catch (const std::exception& e) {
    fmt::print(stderr, "readback_bench: {}\n", e.what());
    return 1;
  }
  return 0;
}
