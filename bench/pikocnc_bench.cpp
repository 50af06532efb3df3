// Reads a large generated PikoCNC program (typical milling: contour lines, arcs, plunges, rapids,
// comments, drilling cycles) back into stream commands and reports lines per second and peak memory.
// usage: pikocnc_bench [LINES=3000000] [FILE=/tmp/pikocnc_bench.nc]   (Release build)
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "bench/read_timing.hpp"
#include "machines/pikocnc/reader.hpp"

namespace {

// Contours of 200 elements at depths stepping down, like a post writes them.
void generate(const std::string& path, long lines) {
  std::ofstream out(path, std::ios::binary);
  std::string buf;
  buf.reserve(1 << 20);
  buf += "Benchmark job\n%\nG21 G90 G17\nM6 T1\nS12000 M3\nG0 X0 Y0 Z5\n";
  long n = 6, block = 10;
  double x = 0, y = 0;
  unsigned seed = 12345;
  auto rnd = [&] {
    seed = seed * 1103515245u + 12345u;
    return static_cast<double>((seed >> 8) % 20000) / 1000.0 - 10.0;
  };
  while (n < lines) {
    const long kind = n % 100;
    if (kind == 0) {
      buf += fmt::format("N{} (contour {} depth step)\n", block, n / 100);
    } else if (kind == 1) {
      buf += fmt::format("N{} G0 Z2.\n", block);
    } else if (kind == 2) {
      buf += fmt::format("N{} G1 Z-{:.3f} F300\n", block, 0.5 + (n / 100 % 10) * 0.5);
    } else if (kind < 90) {
      x += rnd();
      y += rnd();
      buf += fmt::format("N{} G1 X{:.3f} Y{:.3f} F1200\n", block, x, y);
    } else if (kind < 98) {
      const double i = 5.0, j = 0.0;  // a half circle of radius 5
      const double ex = x + 2 * i, ey = y + 2 * j;
      buf += fmt::format("N{} G{} X{:.3f} Y{:.3f} I{:.3f} J{:.3f}\n", block, kind % 2 ? 2 : 3, ex, ey, i, j);
      x = ex, y = ey;
    } else {
      buf += fmt::format("N{} G0 X{:.3f} Y{:.3f}\n", block, x, y);
    }
    block += 10;
    ++n;
    if (buf.size() > (1 << 20) - 256) {
      out << buf;
      buf.clear();
    }
  }
  buf += "M5\nM30\n";
  out << buf;
}

}  // namespace

int main(int argc, char** argv) {
  const long lines = argc > 1 ? std::stol(argv[1]) : 3'000'000;
  const std::string path = argc > 2 ? argv[2] : "/tmp/pikocnc_bench.nc";
  generate(path, lines);
  const long rss_before = bench::peak_rss_kb();
  auto reader = pikocnc::PikoReader::open(path);
  const bench::ReadTiming t = bench::time_reading(*reader);
  fmt::print("{} lines, {} commands in {:.3f} s: {:.2f} M lines/s, {:.2f} M commands/s\n", lines, t.commands,
             t.seconds, lines / t.seconds / 1e6, t.commands / t.seconds / 1e6);
  fmt::print("peak RSS {} kB before reading, {} kB after; {} warnings; checksum {:.3f}\n", rss_before,
             bench::peak_rss_kb(), reader->diagnostics().total(), t.checksum);
  std::remove(path.c_str());
  return 0;
}
