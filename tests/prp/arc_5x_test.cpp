// arc_5x and arc_in_main_planes: an arc while the rotary axes turn becomes @line_5x chords with the
// angles turning in step; an arc whose machine plane is tilted becomes chords when the PRP asks.
#include <gtest/gtest.h>

#include <cmath>

#include "prp/filters/arc_filter.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;
using prp::ArcSettings;
using toolpath::Command;

namespace {

std::vector<Command> quarter(const char* name, std::initializer_list<Pair> extra) {
  Command arc = command(name, {{"xpos", num(0)}, {"ypos", num(10)}, {"zpos", num(0)}, {"feed", num(300)},
                               {"xcenter", num(0)}, {"ycenter", num(0)}, {"xcenter_rel", num(-10)},
                               {"ycenter_rel", num(0)}, {"radius", num(10)}, {"arc_direction", word("CCW")},
                               {"arc_plane", word("XY")}, {"arc_size", num(90)}},
                        1);
  for (const auto& [n, v] : extra) arc.set(n, v);
  return {command("@line_5x", {{"xpos", num(10)}, {"ypos", num(0)}, {"zpos", num(0)}, {"apos", num(0)}, {"bpos", num(10)}}),
          arc};
}

const auto run = run_arc_filter;

TEST(Arc5x, LinearisedWithTheRotaryAxesTurningInStep) {
  ArcSettings s;
  s.arc_5x = false;
  s.max_angle = 30;
  auto out = run(quarter("@arc_5x", {{"apos", num(90)}, {"bpos", num(10)}}), s);
  ASSERT_EQ(out.size(), 4u);
  const double rows[3][5] = {{10 * std::cos(M_PI / 6), 5, 0, 30, 10}, {5, 10 * std::sin(M_PI / 3), 0, 60, 10}, {0, 10, 0, 90, 10}};
  for (std::size_t i = 0; i < 3; ++i) {
    const Command& c = out[i + 1];
    EXPECT_EQ(c.name, "@line_5x");
    EXPECT_EQ(c.index, 1u);
    EXPECT_NEAR(get(c, "xpos"), rows[i][0], 1e-12);
    EXPECT_NEAR(get(c, "ypos"), rows[i][1], 1e-12);
    EXPECT_EQ(get(c, "zpos"), rows[i][2]);
    EXPECT_NEAR(get(c, "apos"), rows[i][3], 1e-12);
    EXPECT_EQ(get(c, "bpos"), rows[i][4]);
    EXPECT_EQ(get(c, "feed"), 300);
  }
  // arc_5x = Y: the arc passes; a plain @arc is not touched by arc_5x.
  EXPECT_EQ(run(quarter("@arc_5x", {{"apos", num(90)}}), ArcSettings{}), quarter("@arc_5x", {{"apos", num(90)}}));
  EXPECT_EQ(run(quarter("@arc", {}), s), quarter("@arc", {}));
}

TEST(ArcInMainPlanes, TiltedMachinePlaneBecomesChords) {
  ArcSettings s;
  s.main_planes = true;
  s.max_angle = 45;
  auto out = run(quarter("@arc", {{"arc_plane_m", word("error")}}), s);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1].name, "@line");
  EXPECT_NEAR(get(out[1], "xpos"), 10 * std::cos(M_PI / 4), 1e-12);
  EXPECT_EQ(out[2].name, "@line");
  EXPECT_EQ(get(out[2], "ypos"), 10);
  auto in_plane = quarter("@arc", {{"arc_plane_m", word("ZX")}});
  EXPECT_EQ(run(in_plane, s), in_plane);
  s.main_planes = false;
  auto tilted = quarter("@arc", {{"arc_plane_m", word("error")}});
  EXPECT_EQ(run(tilted, s), tilted);
}

}  // namespace
