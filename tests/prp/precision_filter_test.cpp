// zero_value snapping and movement/feed/spin precision (spec 3.1).
#include <gtest/gtest.h>

#include "prp/precision_filter.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;

namespace {

TEST(PrecisionFilter, DigitsOfMovementPrecision) {
  EXPECT_EQ(prp::digits_of(0.001), 3);
  EXPECT_EQ(prp::digits_of(0.0001), 4);
  EXPECT_EQ(prp::digits_of(3), 3);
  EXPECT_EQ(prp::digits_of(0), std::nullopt);
}

TEST(PrecisionFilter, SnapsRoundsAndKeepsUnchangedAxes) {
  prp::PrecisionSettings s;
  s.zero_value = 0.001;
  s.movement_digits = 3;
  s.feed_digits = 0;
  ListSource source({command("@rapid_move", {{"xpos", num(10)}, {"ypos", num(-0.0004)}, {"zpos", num(5)}}),
                     command("@line", {{"xpos", num(10.0006)}, {"ypos", num(2.12345)}, {"zpos", num(5)},
                                       {"feed", num(99.6)}}),
                     command("@line", {{"xpos", toolpath::Value::make_integer(12)}, {"ypos", num(-0.00049)},
                                       {"zpos", num(5)}})});
  prp::PrecisionFilter filter(source, s);
  auto out = drain(filter);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(*out[0].find("ypos"), num(0));      // |y| < zero_value: exactly 0, never -0
  EXPECT_EQ(*out[1].find("xpos"), num(10));     // moved less than zero_value: stays
  EXPECT_EQ(*out[1].find("ypos"), num(2.123));  // rounded to 3 digits
  EXPECT_EQ(*out[1].find("feed"), num(100));
  EXPECT_EQ(*out[2].find("xpos"), toolpath::Value::make_integer(12));  // already exact: untouched
  EXPECT_EQ(*out[2].find("ypos"), num(0));
  EXPECT_FALSE(std::signbit(out[2].find("ypos")->numeric));
}

// Names compare case-insensitively; a name given twice is rounded at its first occurrence only (the
// one Command::find sees); a change flag survives rounding; text values are left alone.
TEST(PrecisionFilter, FirstOccurrenceFlagsAndText) {
  prp::PrecisionSettings s;
  s.movement_digits = 2;
  s.spin_digits = -2;
  ListSource source({command("@line", {{"XPOS", toolpath::Value::make_numeric(1.234, toolpath::ChangeFlag::Changed)},
                                       {"xpos", num(5.678)},
                                       {"radius", toolpath::Value::make_string("1.234")},
                                       {"Spin", toolpath::Value::make_integer(1234)},
                                       {"start_angle", num(1.234)}})});
  prp::PrecisionFilter filter(source, s);
  auto out = drain(filter);
  ASSERT_EQ(out.size(), 1u);
  const auto& p = out[0].parameters;
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[0].value, toolpath::Value::make_numeric(1.23, toolpath::ChangeFlag::Changed));
  EXPECT_EQ(p[1].value, num(5.678));
  EXPECT_EQ(p[2].value, toolpath::Value::make_string("1.234"));
  EXPECT_EQ(p[3].value, num(1200));  // spin_precision -2: hundreds
  EXPECT_EQ(p[4].value, num(1.234));  // not a length
}

}  // namespace
