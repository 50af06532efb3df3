// eps_line: short lines are dropped, measured from the last position sent; a contour's last line stays.
#include <gtest/gtest.h>

#include "prp/filters/short_line_filter.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;

namespace {

toolpath::Command line(double x, double y, std::size_t index) {
  return command("@line", {{"xpos", num(x)}, {"ypos", num(y)}, {"zpos", num(0)}}, index);
}

std::vector<std::size_t> indexes_after(std::vector<toolpath::Command> in, double eps) {
  ListSource source(std::move(in));
  prp::ShortLineFilter filter(source, eps);
  std::vector<std::size_t> out;
  for (const auto& c : drain(filter)) out.push_back(c.index);
  return out;
}

TEST(ShortLineFilter, DropsShortLinesButKeepsTheContourEnd) {
  auto rapid = command("@rapid_move", {{"xpos", num(0)}, {"ypos", num(0)}, {"zpos", num(0)}}, 0);
  // 1: long; 2, 3: 0.004 each (dropped, the chain is measured from 1's end); 4: 0.004 more, but
  // 0.012 from the last line sent, so kept; 5: short and last before the rapid: kept.
  std::vector<toolpath::Command> in = {rapid,           line(1, 0, 1),     line(1.004, 0, 2), line(1.008, 0, 3),
                                       line(1.012, 0, 4), line(1.013, 0, 5), command("@rapid_move", {}, 6)};
  EXPECT_EQ(indexes_after(in, 0.01), (std::vector<std::size_t>{0, 1, 4, 5, 6}));
  EXPECT_EQ(indexes_after(in, 0.0), (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6}));
}

TEST(ShortLineFilter, ShortLineAtTheEndOfTheStreamIsKept) {
  std::vector<toolpath::Command> in = {line(0, 0, 0), line(0.001, 0, 1)};
  EXPECT_EQ(indexes_after(in, 0.01), (std::vector<std::size_t>{0, 1}));
}

TEST(ShortLineFilter, LineBeforeAnArcIsKept) {
  std::vector<toolpath::Command> in = {line(0, 0, 0), line(0.001, 0, 1), command("@arc", {}, 2), line(0.002, 0, 3)};
  EXPECT_EQ(indexes_after(in, 0.01), (std::vector<std::size_t>{0, 1, 2, 3}));
}

}  // namespace
