// zero_value snapping and movement/feed/spin precision (spec 3.1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "prp/filters/precision_filter.hpp"
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

// DecimalGrid::round takes a shortcut for whole numbers; over a table of values (whole numbers up
// to and past the shortcut's limit, fractions, halves, -0, tiny, huge, inf, NaN) and every digit
// count a PRP can give, it returns the general rule's result bit for bit.
TEST(PrecisionFilter, WholeNumberShortcutIsTheGeneralRuleBitForBit) {
  auto bits = [](double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  };
  std::vector<double> values = {0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 2.5, 45.0, -45.0, 1500.0, 6000.0, 1.0005,
                                123.4565, -0.0004, 0.1, 1e-300, 5e-324, 4503599627370496.0, 9007199254740992.0,
                                9007199254740993.0, 1e15, -1e15, 1e16, 1e300, -1e300,
                                std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                std::nan(""), std::numeric_limits<double>::max()};
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const double whole = static_cast<double>(static_cast<std::int64_t>(rng() >> (11 + i % 53))) * (i % 2 ? 1 : -1);
    values.push_back(whole);
    values.push_back(std::nextafter(whole, 1e308));
    values.push_back(std::nextafter(whole, -1e308));
    values.push_back(whole / 8);
  }
  for (int digits : {-3, -1, 0, 1, 2, 3, 4, 5, 6, 9, 12, 15, 16, 17, 22, 23}) {
    const prp::DecimalGrid grid(digits);
    const double limit = digits >= 0 && digits <= 15 ? std::ldexp(1.0, 53) / std::pow(10.0, digits) : 0;
    std::vector<double> table = values;
    for (double near : {limit, std::floor(limit), std::floor(limit) + 1, std::floor(limit) - 1})
      table.insert(table.end(), {near, -near});
    for (double v : table) {
      const double fast = grid.round(v), general = grid.round_general(v);
      if (std::isnan(general)) EXPECT_TRUE(std::isnan(fast)) << digits;
      else EXPECT_EQ(bits(fast), bits(general)) << v << " to " << digits << " digits";
      EXPECT_EQ(grid.keeps(v), general == v) << v << " to " << digits << " digits";
    }
  }
}

}  // namespace

namespace {

std::uint64_t bits_of(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// The filter's shortcuts against `every_value_in_full` on the same commands: the same values, bit
// for bit, flags and texts included.
void expect_same_as_every_value_in_full(const std::vector<toolpath::Command>& in, prp::PrecisionSettings s, int round) {
  ListSource fast_in(in), full_in(in);
  prp::PrecisionFilter fast(fast_in, s);
  s.every_value_in_full = true;
  prp::PrecisionFilter full(full_in, s);
  const auto a = drain(fast), b = drain(full);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].parameters.size(), b[i].parameters.size());
    for (std::size_t j = 0; j < a[i].parameters.size(); ++j) {
      const toolpath::Value &x = a[i].parameters[j].value, &y = b[i].parameters[j].value;
      ASSERT_EQ(x.kind, y.kind) << round << " " << i << " " << j;
      ASSERT_EQ(x.flag, y.flag);
      ASSERT_EQ(x.integer, y.integer);
      ASSERT_EQ(bits_of(x.numeric), bits_of(y.numeric))
          << round << " " << i << " " << a[i].parameters[j].name << " " << x.numeric;
      ASSERT_EQ(x.text, y.text);
    }
  }
}

// The filter leaves most values alone after a few comparisons; on random streams (values at and off
// the grids, near zero_value, near the axis they move on, integers, texts, names given twice, NaN,
// infinities, -0) and random settings, it gives what working out every value in full gives, bit
// for bit and kind for kind.
TEST(PrecisionFilter, ShortcutGivesTheFullStepsResults) {
  std::mt19937_64 rng(31);
  auto pick = [&](auto... options) {
    const double table[] = {static_cast<double>(options)...};
    return table[rng() % sizeof...(options)];
  };
  const char* names[] = {"xpos", "ypos", "zpos", "XPOS", "feed", "spin", "radius", "xcenter_rel", "zstart",
                         "drill_depth", "apos", "tool_number"};
  const char* commands[] = {"@line", "@rapid_move", "@arc", "@start_program", "@drill", "@message"};
  for (int round = 0; round < 200; ++round) {
    prp::PrecisionSettings s;
    // Up to 1 a whole number never snaps (the shortcut takes it), above 1 it may.
    s.zero_value = pick(0.0, 0.001, 0.001, 0.5, 1.0, 1.5, 2.0, -1.0);
    if (rng() % 4) s.movement_digits = static_cast<int>(pick(3, 3, 0, 1, 4, 16, -1));
    if (rng() % 2) s.feed_digits = static_cast<int>(pick(0, 1, 2, -2));
    if (rng() % 2) s.spin_digits = static_cast<int>(pick(0, -2, 3));
    std::vector<toolpath::Command> in;
    double around = 10.0;  // values stay near each other, so axes often move less than zero_value
    for (int i = 0; i < 200; ++i) {
      toolpath::Command c;
      c.name = commands[rng() % std::size(commands)];
      c.depth = rng() % 10 == 0 ? 2 : 1;
      const int n = static_cast<int>(rng() % 8);
      for (int j = 0; j < n; ++j) {
        double v;
        switch (rng() % 8) {
          case 0: v = around + pick(0.0, 0.0004, -0.0004, 0.0005, 0.3, -1.7, 1.0); break;
          case 1: v = pick(0.0, -0.0, 0.0004, -0.0004, 0.0005, 0.001, 1e-300, 0.49, -1.5); break;
          case 2: v = static_cast<double>(static_cast<std::int64_t>(rng() % 20000) - 10000) / 1000.0; break;
          case 3: v = std::ldexp(static_cast<double>(rng() >> 11), -static_cast<int>(rng() % 60)); break;
          case 4:
            v = pick(std::nan(""), std::numeric_limits<double>::infinity(), -1e300, 2.5, 1234.5678, 1e16,
                     9007199254740993.0, -4503599627370497.0, around + 1.0, around - 2.0);
            break;
          default: v = static_cast<double>(static_cast<std::int64_t>(rng() % 2000) - 1000); break;
        }
        toolpath::Value value;
        switch (rng() % 6) {
          case 0: value = toolpath::Value::make_integer(static_cast<std::int64_t>(rng() % 5) - 2); break;
          case 1: value = toolpath::Value::make_string("1.2345"); break;
          default: value = toolpath::Value::make_numeric(v, rng() % 5 ? toolpath::ChangeFlag::None : toolpath::ChangeFlag::Changed);
        }
        c.parameters.push_back({names[rng() % std::size(names)], value});
      }
      if (rng() % 3 == 0) around += pick(0.0, 0.0004, 5.0, -3.25);
      in.push_back(std::move(c));
    }
    expect_same_as_every_value_in_full(in, s, round);
    if (testing::Test::HasFatalFailure()) return;
  }
}

}  // namespace

namespace {

// A fraction that passed the tests passes again at once when its parameter repeats it (kept_):
// streams drawn from a few values, on and off the grids, near zero_value, -0 and NaN, repeated
// parameter after parameter and command after command, give what working out every value gives.
TEST(PrecisionFilter, RepeatedFractionsGiveTheFullStepsResults) {
  std::mt19937_64 rng(41);
  const double pool[] = {-0.5,   0.5,   2.1234, 2.123,  -0.0004, 0.0004, 0.001, -0.0, 0.0, 5.0,
                         2.5,    1e-300, 0.49,  -1.5,   10.0005, 10.001, 1e16 + 2, std::nan("")};
  const char* names[] = {"xpos", "ypos", "zpos", "radius", "feed", "spin", "zstart"};
  const char* commands[] = {"@line", "@arc", "@message", "@rapid_move"};
  for (int round = 0; round < 300; ++round) {
    prp::PrecisionSettings s;
    s.zero_value = std::vector<double>{0.0, 0.001, 0.5, 2.0}[rng() % 4];
    if (rng() % 4) s.movement_digits = static_cast<int>(rng() % 5);
    if (rng() % 2) s.feed_digits = static_cast<int>(rng() % 3) - 1;
    if (rng() % 2) s.spin_digits = static_cast<int>(rng() % 3) - 1;
    std::vector<toolpath::Command> in;
    for (int i = 0; i < 60; ++i) {
      toolpath::Command c;
      c.name = commands[rng() % std::size(commands)];
      for (int j = static_cast<int>(rng() % 6); j > 0; --j)
        c.parameters.push_back({names[rng() % std::size(names)], num(pool[rng() % (rng() % 3 ? 4 : std::size(pool))])});
      in.push_back(std::move(c));
    }
    expect_same_as_every_value_in_full(in, s, round);
    if (testing::Test::HasFatalFailure()) return;
  }
}

}  // namespace
