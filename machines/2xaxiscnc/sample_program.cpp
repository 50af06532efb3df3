// The 2XAxisCNC program of the reading benchmark (Controller::write_sample_program): a contour of
// relative moves with 4 decimals, a coefficient change now and then, comments, a relay and pauses.
#include "machines/2xaxiscnc/sample_program.hpp"

#include <fmt/format.h>

#include <string>

namespace twoaxis {
namespace {

// "12,345" as the post writes it (up to 4 decimals, trailing zeros stripped); `units` of 1e-4 mm.
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

}  // namespace

void write_sample_program(std::ostream& out, std::size_t frames) {
  std::string buf;
  buf.reserve(1 << 20);
  buf += "(BENCH)\r\nM03\r\n";
  unsigned seed = 12345;
  auto rnd = [&] {
    seed = seed * 1103515245u + 12345u;
    return static_cast<long>((seed >> 8) % 200000) - 100000;  // +-10 mm in 1e-4 mm
  };
  for (std::size_t n = 2; n < frames; ++n) {
    const std::size_t kind = n % 100;
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

}  // namespace twoaxis
