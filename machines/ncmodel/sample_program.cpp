#include "machines/ncmodel/sample_program.hpp"

#include <fmt/format.h>

#include <string>

namespace ncmodel {

void write_milling_blocks(std::ostream& out, std::size_t blocks, CommentStyle comments) {
  std::string buf;
  buf.reserve(1 << 20);
  unsigned seed = 12345;
  auto rnd = [&] {  // a small fixed generator: the program is the same on every machine
    seed = seed * 1103515245u + 12345u;
    return static_cast<double>((seed >> 8) % 20000) / 1000.0 - 10.0;
  };
  double x = 0, y = 0;
  for (std::size_t n = 0; n < blocks; ++n) {
    const std::size_t block = (n + 1) * 10, kind = n % 100;
    if (kind == 0) {
      buf += comments == CommentStyle::Semicolon ? fmt::format("N{} ; contour {}\n", block, n / 100)
                                                 : fmt::format("N{} (contour {})\n", block, n / 100);
    } else if (kind == 1) {
      buf += fmt::format("N{} G0 Z2.\n", block);
    } else if (kind == 2) {
      buf += fmt::format("N{} G1 Z-{:.3f} F300\n", block, 0.5 + static_cast<double>(n / 100 % 10) * 0.5);
    } else if (kind < 90) {
      x += rnd();
      y += rnd();
      buf += fmt::format("N{} G1 X{:.3f} Y{:.3f} F1200\n", block, x, y);
    } else if (kind < 98) {  // a half circle of radius 5
      buf += fmt::format("N{} G{} X{:.3f} Y{:.3f} I5. J0.\n", block, kind % 2 ? 2 : 3, x + 10, y);
      x += 10;
    } else {
      buf += fmt::format("N{} G0 X{:.3f} Y{:.3f}\n", block, x, y);
    }
    if (buf.size() > (1 << 20) - 256) {
      out << buf;
      buf.clear();
    }
  }
  out << buf;
}

}  // namespace ncmodel
