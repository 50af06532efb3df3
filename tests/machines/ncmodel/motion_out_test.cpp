// MotionOut fills each command into the slots of a recycled one (no clearing, no lookup by key).
// Whatever buffers the consumer hands back (other shapes, names in another case, extra
// parameters, trace lines), the commands must be those a consumer with fresh commands gets.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "machines/ncmodel/motion_out.hpp"

namespace {

using toolpath::Command;
using toolpath::Value;

// The same random program of events into `out`, commands taken as they come.
template <class Take>
void run_program(ncmodel::MotionOut& out, std::uint64_t seed, Take take) {
  std::mt19937_64 rng(seed);
  auto coordinate = [&] { return static_cast<double>(static_cast<int>(rng() % 20001) - 10000) / 1000; };
  auto point = [&] { return Eigen::Vector3d(coordinate(), coordinate(), coordinate()); };
  for (int n = 0; n < 20000; ++n) {
    switch (rng() % 12) {
      case 0: out.rapid(point()); break;
      case 1: case 2: case 3: out.line(point(), 100 + rng() % 900); break;
      case 4: {
        const Eigen::Vector3d to = point();
        out.arc(to, (to + out.position()) / 2, toolpath::geometry::Plane(rng() % 3), rng() % 2, 500);
        break;
      }
      case 5: out.dwell(0.5); break;
      case 6: out.spindle(3 + static_cast<int>(rng() % 3), 1000 + rng() % 5000); break;
      case 7: out.speed(2000); break;
      case 8: out.tool_change(static_cast<double>(rng() % 20), rng() % 2 ? std::optional<std::string>("T-" + std::to_string(n)) : std::nullopt); break;
      case 9: out.message("message " + std::to_string(n)); break;
      case 10: out.compensation(rng() % 2 ? "COMP_LEFT" : "COMP_OFF"); break;
      default:
        if (rng() % 4 == 0) out.set_rotary(static_cast<int>(rng() % 3), coordinate());
        out.machine_move({std::optional<double>(coordinate()), std::nullopt, std::optional<double>(coordinate())},
                         {rng() % 2 ? std::optional<double>(coordinate()) : std::nullopt, std::nullopt, std::nullopt});
        break;
    }
    if (rng() % 3 == 0) continue;  // some commands wait in the queue
    while (take()) {}
  }
  out.end_program();
  while (take()) {}
}

TEST(MotionOut, RecycledCommandsAsFreshOnes) {
  std::vector<Command> fresh;
  {
    ncmodel::MotionOut out;
    run_program(out, 7, [&] {
      Command c;
      if (!out.take(c)) return false;
      fresh.push_back(std::move(c));
      return true;
    });
  }
  std::vector<Command> recycled;
  {
    ncmodel::MotionOut out;
    std::mt19937_64 rng(11);
    Command c;
    run_program(out, 7, [&] {
      // What a consumer may hand back: the last command, or one of another making.
      if (rng() % 5 == 0) {
        c.name = rng() % 2 ? "@arc" : "@line";
        c.depth = 3;
        c.line = 12;
        c.parameters.clear();
        c.parameters.emplace_back("XPOS", Value::make_integer(1));
        c.parameters.emplace_back("user_value", Value::make_string("x"));
        c.parameters.back().line = 5;
        c.trace.push_back({toolpath::TraceLine::Kind::Output, "G1 X1"});
      }
      if (!out.take(c)) return false;
      recycled.push_back(c);
      return true;
    });
  }
  ASSERT_EQ(recycled.size(), fresh.size());
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(recycled[i], fresh[i]);
    EXPECT_EQ(recycled[i].line, fresh[i].line);
    for (std::size_t k = 0; k < recycled[i].parameters.size() && k < fresh[i].parameters.size(); ++k) {
      EXPECT_EQ(recycled[i].parameters[k].line, 0u);
      EXPECT_EQ(recycled[i].parameters[k].key, fresh[i].parameters[k].key);
    }
  }
}

// clean() rounds without libm's round: the same doubles as round(v * 1e9) / 1e9 (and -0 as 0) on
// random values of every magnitude, halves of a nanometre, and the edges of its shortcut.
TEST(MotionOutClean, SameAsRoundingWithStdRound) {
  auto reference = [](double v) {
    const double r = std::round(v * 1e9) / 1e9;
    return r == 0 ? 0.0 : r;
  };
  std::vector<double> values = {0.0, -0.0, 0.5e-9, -0.5e-9, 1.5e-9, 2.5e-9, -2.5e-9, 1e-9, 0x1p51 / 1e9, -0x1p51 / 1e9,
                                0x1p52 / 1e9, 1e300, -1e300, std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity()};
  std::mt19937_64 rng(1);
  for (int i = 0; i < 1000000; ++i) {
    const double scale = std::pow(10.0, static_cast<double>(static_cast<int>(rng() % 24)) - 12);
    values.push_back((static_cast<double>(rng() >> 11) / 9007199254740992.0 - 0.5) * scale);
    values.push_back((static_cast<double>(rng() % 2000000001) - 1e9 + 0.5) / 1e9);  // halves of a nanometre
    values.push_back(std::nextafter(values.back(), 0.0));
  }
  for (const double v : values) {
    const double a = ncmodel::clean(v), b = reference(v);
    ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << v;
  }
  EXPECT_TRUE(std::isnan(ncmodel::clean(std::numeric_limits<double>::quiet_NaN())));
}

}  // namespace

