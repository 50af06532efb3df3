// The arc filter's shortcuts must never change a result. The circle check tells most arcs from
// square roots instead of hypot; arc_surely_passes: an arc that surely passes unchanged is not worked
// out: over a table of arcs close to every limit (sweeps near 0,
// eps_angle, 90, 180 and 360 degrees, radii near arc_max_radius, lengths near arc_min_length,
// rises near zero_value) and PRP switches, the filter gives the same commands with and without it,
// and every arc the shortcut passes is one the full rule passes unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "prp/filters/arc_filter.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;
using prp::ArcSettings;
using toolpath::Command;
using toolpath::geometry::Direction;
using toolpath::geometry::Plane;

namespace {

struct TestArc {
  Plane plane;
  Direction direction;
  Eigen::Vector3d start, end, centre;
};

TestArc make(Plane plane, Direction direction, double radius, double start_deg, double sweep, double rise,
             const Eigen::Vector3d& centre) {
  const auto a = toolpath::geometry::axes(plane);
  auto at = [&](double deg, double h) {
    Eigen::Vector3d p = centre;
    p[a.first] += radius * std::cos(deg * std::numbers::pi / 180);
    p[a.second] += radius * std::sin(deg * std::numbers::pi / 180);
    p[a.normal] += h;
    return p;
  };
  const double end_deg = start_deg + (direction == Direction::CCW ? sweep : -sweep);
  TestArc t{plane, direction, at(start_deg, 0), at(end_deg, rise), centre};
  t.centre[a.normal] = t.start[a.normal];
  return t;
}

// The move to the start, then the arc (its start is the tool position: no *_rel values).
std::vector<Command> commands(const TestArc& t) {
  const auto a = toolpath::geometry::axes(t.plane);
  const char* plane = t.plane == Plane::XY ? "XY" : t.plane == Plane::YZ ? "YZ" : "ZX";
  return {command("@line", {{"xpos", num(t.start.x())}, {"ypos", num(t.start.y())}, {"zpos", num(t.start.z())}}, 0),
          command("@arc",
                  {{"xpos", num(t.end.x())},
                   {"ypos", num(t.end.y())},
                   {"zpos", num(t.end.z())},
                   {"xcenter", num(t.centre[a.first])},
                   {"ycenter", num(t.centre[a.second])},
                   {"arc_direction", word(t.direction == Direction::CW ? "CW" : "CCW")},
                   {"arc_plane", word(plane)}},
                  1)};
}

std::vector<ArcSettings> settings_table() {
  std::vector<ArcSettings> table;
  ArcSettings fanuc;  // machines/fanuc/fanuc.prp
  fanuc.check_circles = false;  // the table holds arcs of radius 1e-60: the rules, not the check
  fanuc.max_radius = 2000;
  fanuc.min_length = 0.001;
  fanuc.eps_angle = 0.002;
  fanuc.zero_value = 0.001;
  fanuc.max_chord = 0;  // chords by angle only: a linearised arc of radius 1e6 stays a few dozen lines
  table.push_back(fanuc);
  ArcSettings defaults;
  defaults.check_circles = false;
  defaults.max_chord = 0;
  table.push_back(defaults);
  ArcSettings halves = fanuc;
  halves.gt_180 = false;
  table.push_back(halves);
  ArcSettings flat = fanuc;
  flat.arc_3d = false;
  table.push_back(flat);
  ArcSettings xy_only = fanuc;
  xy_only.zx_yz = false;
  table.push_back(xy_only);
  ArcSettings coarse = fanuc;
  coarse.eps_angle = 5;
  coarse.min_length = 1;
  coarse.max_radius = 5;
  table.push_back(coarse);
  ArcSettings quadrants = fanuc;
  quadrants.quadrants = true;
  table.push_back(quadrants);
  return table;
}

std::vector<TestArc> arc_table() {
  std::vector<TestArc> arcs;
  const double sweeps[] = {1e-12, 1e-9, 1e-7, 0.001, 0.002, 0.0020000001, 0.5, 1, 45, 89.999999, 90, 90.000001,
                           179.9999999, 180, 180.0000001, 270, 359.9999999, 360};
  const double radii[] = {1e-60, 1e-6, 0.001, 0.5, 1, 5, 4.999999999, 5.0000001, 1999.9999999, 2000, 2000.000001, 1e6};
  const double rises[] = {0, 1e-10, 0.0009, 0.0011, 5};
  const Eigen::Vector3d centre(45, -5, 1.5);
  int n = 0;
  for (Plane plane : {Plane::XY, Plane::YZ, Plane::ZX})
    for (Direction direction : {Direction::CCW, Direction::CW})
      for (double sweep : sweeps)
        for (double radius : radii) {
          const double start_deg = 90.0 * (n % 4) + (n % 3 == 0 ? 0.0 : 17.25 * (n % 7));
          arcs.push_back(make(plane, direction, radius, start_deg, sweep, rises[n % 5], centre));
          ++n;
        }
  std::mt19937 rng(20250107);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 300; ++i)
    arcs.push_back(make(static_cast<Plane>(rng() % 3), rng() % 2 ? Direction::CW : Direction::CCW,
                        std::pow(10.0, -4 + 8 * unit(rng)), 360 * unit(rng), 360 * unit(rng),
                        rng() % 2 ? 0.0 : -5 + 10 * unit(rng),
                        Eigen::Vector3d(-100 + 200 * unit(rng), -100 + 200 * unit(rng), -100 + 200 * unit(rng))));
  return arcs;
}

TEST(ArcShortcut, NeverChangesWhatTheFilterGives) {
  int shortcuts = 0, worked_out = 0;
  const auto arcs = arc_table();
  for (const ArcSettings& base : settings_table()) {
    ArcSettings full = base;
    full.work_out_every_arc = true;
    for (std::size_t i = 0; i < arcs.size(); ++i) {
      const TestArc& t = arcs[i];
      SCOPED_TRACE("arc " + std::to_string(i));
      const auto in = commands(t);
      const auto expected = run_arc_filter(in, full);
      EXPECT_EQ(run_arc_filter(in, base), expected);
      if (prp::arc_surely_passes(base, t.start, t.end, t.centre, t.plane, t.direction, false, false)) {
        ++shortcuts;
        EXPECT_EQ(expected, in);  // the full rule passes it unchanged too
      } else {
        ++worked_out;
      }
    }
  }
  // Both ways are taken often, so the table exercises the shortcut and its refusals.
  EXPECT_GT(shortcuts, 2000);
  EXPECT_GT(worked_out, 2000);
}

TEST(ArcShortcut, RefusesWhatItCannotBound) {
  ArcSettings s;
  const Eigen::Vector3d c(0, 0, 0), start(1, 0, 0);
  const double nan = std::nan("");
  // Coinciding start and end (a full circle or nothing), half circles, NaN, a vanishing radius.
  for (const Eigen::Vector3d& end : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(nan, 0, 0),
                                     Eigen::Vector3d(0, 0, 0)})
    EXPECT_FALSE(prp::arc_surely_passes(s, start, end, c, Plane::XY, Direction::CCW, false, false)) << end.x();
  EXPECT_TRUE(prp::arc_surely_passes(s, start, Eigen::Vector3d(0, 1, 0), c, Plane::XY, Direction::CCW, false, false));
  EXPECT_TRUE(prp::arc_surely_passes(s, start, Eigen::Vector3d(0, 1, 0), c, Plane::XY, Direction::CW, false, false));
  s.gt_180 = false;  // 270 degrees clockwise is halved
  EXPECT_FALSE(prp::arc_surely_passes(s, start, Eigen::Vector3d(0, 1, 0), c, Plane::XY, Direction::CW, false, false));
  s = ArcSettings{};
  s.arc_5x = false;
  EXPECT_FALSE(prp::arc_surely_passes(s, start, Eigen::Vector3d(0, 1, 0), c, Plane::XY, Direction::CCW, true, false));
  s = ArcSettings{};
  s.main_planes = true;
  EXPECT_FALSE(prp::arc_surely_passes(s, start, Eigen::Vector3d(0, 1, 0), c, Plane::XY, Direction::CCW, false, true));
}

// The circle check's shortcut passes only arcs that the check with hypot passes: over arcs whose
// end (and given radius) lie at, inside and outside the tolerance by tiny and large amounts, with
// radii near 1e-6, huge coordinates and NaN, the filter throws the same error, or gives the same
// commands, with and without it.
TEST(ArcShortcut, CircleCheckDecidesAsHypot) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  const double factors[] = {0, 0.5, -0.5, 1 - 1e-9, -(1 - 1e-9), 1 - 1e-13, 1, -1, 1 + 1e-13, 1 + 1e-9, 2, -2};
  int passed = 0, refused = 0;
  for (int i = 0; i < 20000; ++i) {
    double r = std::pow(10.0, -7 + 16 * unit(rng));
    if (i % 10 == 0) r = 1e-6 * (1 + (static_cast<double>(rng() % 5) - 2) * 1e-13);
    const double ct = i % 3 ? 0.005 : 0.0002;
    const double tolerance = ct * (1 + 1e-4 * r);
    const double end_r = r + tolerance * factors[rng() % std::size(factors)];
    const double from = 2 * std::numbers::pi * unit(rng), to = 2 * std::numbers::pi * unit(rng);
    Eigen::Vector3d centre(-100 + 200 * unit(rng), -100 + 200 * unit(rng), 1.5);
    if (i % 50 == 0) centre *= 1e60;
    if (i % 997 == 0) centre.x() = std::nan("");
    const Eigen::Vector3d start = centre + Eigen::Vector3d(r * std::cos(from), r * std::sin(from), 0);
    const Eigen::Vector3d end = centre + Eigen::Vector3d(end_r * std::cos(to), end_r * std::sin(to), 0);
    TestArc t{Plane::XY, rng() % 2 ? Direction::CW : Direction::CCW, start, end, centre};
    auto in = commands(t);
    if (rng() % 2) in[1].set("radius", num(r + tolerance * factors[rng() % std::size(factors)]));
    ArcSettings fast;
    fast.circle_tolerance = ct;
    ArcSettings hypot_only = fast;
    hypot_only.work_out_every_arc = true;
    auto outcome = [&](const ArcSettings& s) {
      try {
        auto out = run_arc_filter(in, s);
        return std::pair{std::string(), out};
      } catch (const prp::StreamError& e) {
        return std::pair{std::string(e.what()), std::vector<Command>{}};
      }
    };
    const auto expected = outcome(hypot_only), got = outcome(fast);
    ASSERT_EQ(got.first, expected.first) << i;
    if (i % 997 != 0) {  // every 997th arc has a NaN, which is equal to nothing
      ASSERT_EQ(got.second, expected.second) << i;
    }
    ++(expected.first.empty() ? passed : refused);
  }
  EXPECT_GT(passed, 5000);
  EXPECT_GT(refused, 5000);
}

}  // namespace
