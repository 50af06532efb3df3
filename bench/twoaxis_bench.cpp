// Reads a large generated 2XAxisCNC program (a contour of relative moves with coefficient changes,
// comments, spindle, pauses and relay toggles) back into stream commands and reports frames per
// second and peak memory.
// usage: twoaxis_bench [FRAMES=1000000] [FILE=/tmp/twoaxis_bench.nc]   (Release build)
#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "bench/read_timing.hpp"
#include "machines/2xaxiscnc/reader.hpp"

namespace {

// "12,345" with the decimals the post writes (up to 4, trailing zeros stripped).
void put_number(std::string& buf, long units) {
  if (units < 0) {
    buf += '-';
    units = -units;
  }
  buf += std::to_string(units / 10000);
  long frac = units % 10000;
  if (frac == 0) return;
  int digits = 4;
  while (frac % 10 == 0) {
    frac /= 10;
    --digits;
  }
  buf += fmt::format(",{:0{}}", frac, digits);
}

void generate(const std::string& path, long frames) {
  std::ofstream out(path, std::ios::binary);
  std::string buf;
  buf.reserve(1 << 20);
  buf += "(BENCH)\r\nM03\r\n";
  unsigned seed = 12345;
  auto rnd = [&] {
    seed = seed * 1103515245u + 12345u;
    return static_cast<long>((seed >> 8) % 200000) - 100000;  // +-10 mm in 1e-4 mm
  };
  for (long n = 2; n < frames; ++n) {
    const long kind = n % 100;
    if (kind == 0) {
      buf += fmt::format("(pass_{})\r\n", n / 100);
    } else if (kind == 1) {
      buf += "Out1\r\n";
    } else if (kind == 2) {
      buf += "P0,5\r\n";
    } else {
      put_number(buf, rnd());
      buf += ' ';
      put_number(buf, rnd());
      if (kind % 20 == 3) buf += fmt::format(" 0,{}", 1 + kind % 9);
      buf += "\r\n";
    }
    if (buf.size() > (1 << 20) - 256) {
      out << buf;
      buf.clear();
    }
  }
  buf += "M05\r\n";
  out << buf;
}

}  // namespace

int main(int argc, char** argv) {
  const long frames = argc > 1 ? std::stol(argv[1]) : 1'000'000;
  const std::string path = argc > 2 ? argv[2] : "/tmp/twoaxis_bench.nc";
  generate(path, frames);
  const long rss_before = bench::peak_rss_kb();
  auto reader = twoaxis::TwoAxisReader::open(path);
  const bench::ReadTiming t = bench::time_reading(*reader);
  fmt::print("{} frames, {} commands in {:.3f} s: {:.2f} M frames/s, {:.2f} M commands/s\n", frames, t.commands,
             t.seconds, frames / t.seconds / 1e6, t.commands / t.seconds / 1e6);
  fmt::print("peak RSS {} kB before reading, {} kB after; {} diagnostics; checksum {:.3f}\n", rss_before,
             bench::peak_rss_kb(), reader->diagnostics().total(), t.checksum);
  std::remove(path.c_str());
  return reader->diagnostics().errors() == 0 ? 0 : 1;
}
