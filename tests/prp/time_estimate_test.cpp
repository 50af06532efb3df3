// The machining-time estimate (spec 3.15).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "prp/filters/time_estimate.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;

namespace {

TEST(TimeEstimate, FeedRapidBlocksToolChangesAndDwells) {
  auto params = prp::load_source(
      "@pre_processor\ntime_factor = 2\nblock_time = 0.2\nchange_tool_time = 5\nrapid_feed = 5000, 196.8503\n"
      "calc_job_time = Y\nendp\n",
      "t.prp", prp::Units::Metric);
  const prp::TimeSettings s = prp::time_settings(params);
  EXPECT_TRUE(s.calc_job_time);
  prp::TimeEstimate t(s);
  for (const auto& c : {command("@change_tool", {}),
                        command("@rapid_move", {{"xpos", num(0)}, {"ypos", num(0)}, {"zpos", num(0)}}),
                        command("@rapid_move", {{"xpos", num(100)}, {"ypos", num(0)}, {"zpos", num(0)}}),  // 100 mm
                        command("@line", {{"xpos", num(100)}, {"ypos", num(50)}, {"zpos", num(0)}, {"feed", num(100)}}),
                        command("@arc", {{"xpos", num(100)}, {"ypos", num(50)}, {"zpos", num(0)}, {"radius", num(10)},
                                         {"arc_size", num(360)}}),
                        command("@delay", {{"delay_period", num(1.5)}})})
    t.add(c);
  EXPECT_EQ(t.motion_blocks(), 4u);
  EXPECT_EQ(t.tool_changes(), 1u);
  EXPECT_DOUBLE_EQ(t.rapid_minutes(), 100.0 / 5000);
  EXPECT_DOUBLE_EQ(t.feed_minutes(), 50.0 / 100 + 20 * std::numbers::pi / 100);
  EXPECT_DOUBLE_EQ(t.seconds(), 2 * (t.rapid_minutes() + t.feed_minutes()) * 60 + 0.2 * 4 + 5 + 1.5);
  EXPECT_FALSE(t.rapid_feed_missing());
}

}  // namespace
