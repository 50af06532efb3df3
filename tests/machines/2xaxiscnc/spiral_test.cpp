// A long spiral posted through the 2XAxisCNC post: the written increments add up exactly to the
// rounded end point (relative moves are differences of rounded absolute positions), and the reader
// finds that end point again.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "machines/2xaxiscnc/reader.hpp"
#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

// An Archimedean spiral of `lines` feed moves with irrational coordinates and changing feeds.
std::string spiral_job(int lines, double& end_x, double& end_y) {
  std::string s = "(0)@start_of_file\ng_file_name : 'SPIRAL'\n(1)@start_program\n";
  double x = 0, y = 0;
  for (int i = 1; i <= lines; ++i) {
    const double a = i * 0.1;
    x = (1 + 0.05 * a) * std::cos(a) * std::sqrt(2.0);
    y = (1 + 0.05 * a) * std::sin(a) * std::sqrt(3.0);
    s += fmt::format("({})@line\nxpos : {:.12f}\nypos : {:.12f}\nzpos : -1\nfeed : {}\n", i + 1, x, y, 500 + (i % 7) * 311);
  }
  s += fmt::format("({})@end_program\nxpos : 0\nypos : 0\nzpos : 10\n({})@end_of_file\n", lines + 2, lines + 3);
  end_x = x;
  end_y = y;
  return s;
}

// "12,3456" as a count of 1e-4 mm.
std::int64_t units(const std::string& text) {
  std::string t = text;
  for (char& c : t)
    if (c == ',') c = '.';
  return std::llround(std::stod(t) * 1e4);
}

TEST(TwoAxisSpiral, EndPointStaysExact) {
  const int kLines = 20000;
  double end_x = 0, end_y = 0;
  const fs::path dir = fs::temp_directory_path() / "twoaxis_spiral_test";
  fs::create_directories(dir);
  std::ofstream(dir / "spiral.trace") << spiral_job(kLines, end_x, end_y);
  const auto r = test_support::run_cli({"run", "--post", "../machines/2xaxiscnc/2xaxiscnc.gpp", "--prp",
                                        "../machines/2xaxiscnc/2xaxiscnc.prp", "--answer", "zero_at_end=FALSE",
                                        (dir / "spiral.trace").string(), "-o", (dir / "spiral.nc").string(), "-q"});
  ASSERT_EQ(r.code, 0) << r.err;

  // The job ends at the origin; the frame before the last is the spiral's end.
  std::ifstream nc(dir / "spiral.nc");
  std::string line;
  std::int64_t sx = 0, sy = 0, max_sx = 0;
  int moves = 0;
  while (std::getline(nc, line)) {
    std::istringstream words(line);
    std::string dx, dy;
    if (!(words >> dx >> dy)) continue;
    sx += units(dx);
    sy += units(dy);
    if (++moves == kLines) {
      EXPECT_EQ(sx, std::llround(end_x * 1e4));
      EXPECT_EQ(sy, std::llround(end_y * 1e4));
      max_sx = sx;
    }
  }
  EXPECT_EQ(moves, kLines + 1);
  EXPECT_NE(max_sx, 0);
  EXPECT_EQ(sx, 0);  // and back to the origin exactly
  EXPECT_EQ(sy, 0);

  // The reader, in decimal (exact) mode, ends exactly there too; with single-precision floats as
  // the application reads them, the sum stays within a micrometre over these 20 000 frames.
  for (bool single : {false, true}) {
    twoaxis::Options o;
    o.single_precision = single;
    auto reader = twoaxis::TwoAxisReader::open((dir / "spiral.nc").string(), o);
    toolpath::Command c, last_move;
    int n = 0;
    while (reader->next(c)) {
      if (c.name == "@line" || c.name == "@rapid_move") {
        if (++n == kLines) last_move = c;
      }
      if (c.name == "@end_program") {
        EXPECT_NEAR(c.find("xpos")->as_number(), 0.0, single ? 1e-3 : 1e-9);
        EXPECT_NEAR(c.find("ypos")->as_number(), 0.0, single ? 1e-3 : 1e-9);
      }
    }
    EXPECT_EQ(reader->diagnostics().errors(), 0u);
    EXPECT_NEAR(last_move.find("xpos")->as_number(), std::round(end_x * 1e4) / 1e4, single ? 1e-3 : 1e-9);
    EXPECT_NEAR(last_move.find("ypos")->as_number(), std::round(end_y * 1e4) / 1e4, single ? 1e-3 : 1e-9);
  }
  fs::remove_all(dir);
}

}  // namespace
