// The arc filter against the manual's measured examples (spec 3.2), then property tests over
// random arcs in every plane, both directions, helical, over 180 degrees and full circles.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "prp/filters/arc_filter.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;
using prp::ArcSettings;
using toolpath::Command;
using toolpath::geometry::Plane;

namespace {

// The helix of the manual's arc_3d example: radius 10 about (172.414, 32.5), CCW, Z 2 -> -2.
std::vector<Command> helix_job() {
  return {command("@rapid_move", {{"xpos", num(182.414)}, {"ypos", num(32.5)}, {"zpos", num(2)}}, 1),
          command("@arc",
                  {{"xpos", num(171.015)}, {"ypos", num(22.598)}, {"zpos", num(-2)}, {"feed", num(100)},
                   {"xcenter", num(172.414)}, {"ycenter", num(32.5)}, {"xcenter_rel", num(-10)},
                   {"ycenter_rel", num(0)}, {"radius", num(10)}, {"start_angle", num(0)},
                   {"end_angle", num(261.959)}, {"arc_direction", word("CCW")}, {"arc_plane", word("XY")},
                   {"arc_size", num(261.959)}},
                  2)};
}

const auto run = run_arc_filter;

TEST(ArcFilter, HelixLinearisedIn27EqualStepsAsTheManualPrints) {
  ArcSettings s;
  s.arc_3d = false;
  s.max_angle = 10;
  s.max_chord = 30;
  auto out = run(helix_job(), s);
  ASSERT_EQ(out.size(), 28u);  // the rapid and 27 lines
  std::ifstream expected_file("prp/data/helix-arc_3d-N.nc");
  std::string line;
  for (std::size_t i = 1; i < out.size(); ++i) {
    ASSERT_TRUE(std::getline(expected_file, line));
    double x = 0, y = 0, z = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "X%lf Y%lf Z%lf", &x, &y, &z), 3) << line;
    const Command& c = out[i];
    EXPECT_EQ(c.name, "@line");
    EXPECT_EQ(c.index, 2u);
    // The manual prints 3 decimals of an arc whose own data we only know to 3 decimals.
    EXPECT_NEAR(get(c, "xpos"), x, 0.001) << line;
    EXPECT_NEAR(get(c, "ypos"), y, 0.001) << line;
    EXPECT_NEAR(get(c, "zpos"), z, 0.0005) << line;
    // Equal steps: every vertex 261.959/27 degrees further round, at radius 10.
    const double deg = std::atan2(get(c, "ypos") - 32.5, get(c, "xpos") - 172.414) * 180 / M_PI;
    EXPECT_NEAR(std::remainder(deg - 261.959 / 27 * static_cast<double>(i), 360.0), 0, 0.002) << line;
    EXPECT_NEAR(std::hypot(get(c, "ypos") - 32.5, get(c, "xpos") - 172.414), 10,
                i + 1 < out.size() ? 1e-9 : 0.0004)  // the last vertex is the arc's own (rounded) end
        << line;
    EXPECT_EQ(get(c, "feed"), 100);
  }
  EXPECT_EQ(get(out.back(), "xpos"), 171.015);  // the last vertex is the arc's own end, exactly
  EXPECT_EQ(get(out.back(), "zpos"), -2);
}

// arc_max_deviation (ours, for the 2XAxisCNC post): a quarter circle of radius 10 within 0.01 mm
// takes ceil(90 / (2 acos(1 - 0.01 / 10))) = 18 chords of 5 degrees, each within the tolerance.
TEST(ArcFilter, ChordalDeviationSetsTheChordCount) {
  ArcSettings s;
  s.arc_exist = false;
  s.max_angle = 180;
  s.max_chord = 1e6;
  s.max_deviation = 0.01;
  const std::vector<Command> quarter = {
      command("@rapid_move", {{"xpos", num(10)}, {"ypos", num(0)}, {"zpos", num(0)}}, 1),
      command("@arc",
              {{"xpos", num(0)}, {"ypos", num(10)}, {"zpos", num(0)}, {"feed", num(100)}, {"xcenter", num(0)},
               {"ycenter", num(0)}, {"xcenter_rel", num(-10)}, {"ycenter_rel", num(0)}, {"radius", num(10)},
               {"start_angle", num(0)}, {"end_angle", num(90)}, {"arc_direction", word("CCW")},
               {"arc_plane", word("XY")}, {"arc_size", num(90)}},
              2)};
  auto out = run(quarter, s);
  ASSERT_EQ(out.size(), 19u);  // the rapid and 18 chords
  for (std::size_t i = 1; i < out.size(); ++i) {
    const double deg = std::atan2(get(out[i], "ypos"), get(out[i], "xpos")) * 180 / M_PI;
    EXPECT_NEAR(deg, 5.0 * static_cast<double>(i), 1e-9);
  }
  EXPECT_LE(10 * (1 - std::cos(2.5 * M_PI / 180)), 0.01);
}

TEST(ArcFilter, HelixOver180IsHalvedAtZeroHeight) {
  ArcSettings s;
  s.gt_180 = false;
  auto out = run(helix_job(), s);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_NEAR(get(out[1], "xpos"), 165.856, 0.001);
  EXPECT_NEAR(get(out[1], "ypos"), 40.05, 0.001);
  EXPECT_NEAR(get(out[1], "zpos"), 0, 1e-12);
  EXPECT_NEAR(get(out[1], "arc_size"), 261.959 / 2, 0.001);
  EXPECT_NEAR(get(out[2], "arc_size"), get(out[1], "arc_size"), 1e-9);
  EXPECT_EQ(get(out[2], "xpos"), 171.015);
}

// The manual's quadrant example: a full CW circle of radius 30 about (26, 26) from (26, -4).
std::vector<Command> circle_job() {
  return {command("@line", {{"xpos", num(26)}, {"ypos", num(-4)}, {"zpos", num(-6)}, {"feed", num(33)}}, 1),
          command("@arc",
                  {{"xpos", num(26)}, {"ypos", num(-4)}, {"zpos", num(-6)}, {"feed", num(100)},
                   {"xcenter", num(26)}, {"ycenter", num(26)}, {"xcenter_rel", num(0)}, {"ycenter_rel", num(30)},
                   {"radius", num(30)}, {"start_angle", num(270)}, {"end_angle", num(270)},
                   {"arc_direction", word("CW")}, {"arc_plane", word("XY")}, {"arc_size", num(360)}},
                  2)};
}

TEST(ArcFilter, FullCircleInQuadrants) {
  ArcSettings s;
  s.quadrants = true;
  auto out = run(circle_job(), s);
  ASSERT_EQ(out.size(), 5u);
  const double ends[4][2] = {{-4, 26}, {26, 56}, {56, 26}, {26, -4}};
  const double angles[4][2] = {{270, 180}, {180, 90}, {90, 0}, {0, 270}};
  for (int i = 0; i < 4; ++i) {
    const Command& c = out[static_cast<std::size_t>(i) + 1];
    EXPECT_EQ(c.name, "@arc");
    EXPECT_EQ(get(c, "xpos"), ends[i][0]);
    EXPECT_EQ(get(c, "ypos"), ends[i][1]);
    EXPECT_EQ(get(c, "arc_size"), 90);
    EXPECT_EQ(get(c, "start_angle"), angles[i][0]);
    EXPECT_EQ(get(c, "end_angle"), angles[i][1]);
    EXPECT_EQ(get(c, "radius"), 30);
    EXPECT_EQ(get(c, "xcenter"), 26);
  }
  EXPECT_EQ(get(out[1], "xcenter_rel"), 0);
  EXPECT_EQ(get(out[1], "ycenter_rel"), 30);
  EXPECT_EQ(get(out[2], "xcenter_rel"), 30);
  EXPECT_EQ(get(out[2], "ycenter_rel"), 0);
}

TEST(ArcFilter, FullCircleInHalves) {
  ArcSettings s;
  s.gt_180 = false;
  auto out = run(circle_job(), s);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(get(out[1], "xpos"), 26);
  EXPECT_NEAR(get(out[1], "ypos"), 56, 1e-12);
  EXPECT_EQ(get(out[1], "arc_size"), 180);
  EXPECT_EQ(get(out[2], "ypos"), -4);
}

TEST(ArcFilter, PassesUnchangedAndIsIdempotent) {
  ArcSettings s;  // engine defaults: everything passes
  auto once = run(circle_job(), s);
  EXPECT_EQ(once, circle_job());
  s.quadrants = true;
  auto split = run(circle_job(), s);
  EXPECT_EQ(run(split, s), split);
}

TEST(ArcFilter, TinyArcsBecomeLinesAndBadArcsAreErrors) {
  ArcSettings s;
  s.eps_angle = 361;  // every arc is "too small"
  auto out = run(circle_job(), s);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[1].name, "@line");
  EXPECT_EQ(get(out[1], "feed"), 100);

  auto bad = circle_job();
  bad[1].set("arc_plane", word("XZ"));
  EXPECT_THROW(
      {
        try {
          run(bad, ArcSettings{});
        } catch (const prp::StreamError& e) {
          EXPECT_STREQ(e.what(), "command 2 (@arc): arc_plane `XZ` is none of XY, YZ, ZX");
          throw;
        }
      },
      prp::StreamError);
}

// An arc is one only when its end lies on the circle its start and centre make, and the radius the
// stream gives is that circle's; within 0.005 mm (0.0002 inch), growing by 1e-4 of the radius.
TEST(ArcFilter, ArcsThatAreNoArcsAreErrors) {
  struct Case {
    const char* what;
    double end_x, end_y, centre_x, centre_y, radius;
    prp::Units units;
    const char* error;  // "" when it passes
  } cases[] = {
      {"a true quarter circle", 56, 26, 26, 26, 30, prp::Units::Metric, ""},
      {"trace rounding (3 decimals)", 56.0004, 25.9996, 26, 26, 30.0004, prp::Units::Metric, ""},
      {"end off the circle", 60, 26, 26, 26, 30, prp::Units::Metric,
       "command 2 (@arc): the arc's end point is not on its circle: 34 from the centre, its start 30 (more than 0.005015 apart)"},
      {"a radius that is not the arc's", 56, 26, 26, 26, 7, prp::Units::Metric,
       "command 2 (@arc): radius 7 is not the arc's: its start is 30 from its centre (more than 0.005015 apart)"},
      {"centre on the start", 26, -4, 26, -4, 0, prp::Units::Metric,
       "command 2 (@arc): arc with zero radius: its centre is where it starts"},
      {"inch: 0.001 off is too much", 56.001, 26, 26, 26, 30, prp::Units::Inch,
       "command 2 (@arc): the arc's end point is not on its circle: 30.001 from the centre, its start 30 (more than "
       "0.0002006 apart)"},
  };
  for (const Case& c : cases) {
    auto job = circle_job();
    job[1].set("xpos", num(c.end_x));
    job[1].set("ypos", num(c.end_y));
    job[1].set("xcenter", num(c.centre_x));
    job[1].set("ycenter", num(c.centre_y));
    job[1].set("xcenter_rel", num(c.centre_x - 26));
    job[1].set("ycenter_rel", num(c.centre_y + 4));
    job[1].set("radius", num(c.radius));
    job[1].set("arc_size", num(90));
    ArcSettings s;
    s.circle_tolerance = c.units == prp::Units::Inch ? 0.0002 : 0.005;
    std::string error;
    try {
      run(job, s);
    } catch (const prp::StreamError& e) {
      error = e.what();
    }
    EXPECT_EQ(error, c.error) << c.what;
  }
  EXPECT_EQ(ArcSettings::from(prp::defaults(prp::Units::Metric)).circle_tolerance, 0.005);
  EXPECT_EQ(ArcSettings::from(prp::defaults(prp::Units::Inch)).circle_tolerance, 0.0002);
}

// SolidCAM sends an arc with its start point (xstart, ystart, zstart; real posts compute the arc
// from it): the pieces of a split arc each start where the one before ended. An arc that passes
// keeps what it had.
TEST(ArcFilter, PiecesCarryTheirOwnStartPoint) {
  auto job = circle_job();
  job[1].set("xstart", num(26));
  job[1].set("ystart", num(-4));
  job[1].set("zstart", num(-6));
  EXPECT_EQ(run(job, ArcSettings{}), job);
  ArcSettings s;
  s.quadrants = true;
  auto pieces = run(job, s);
  ASSERT_EQ(pieces.size(), 5u);
  for (std::size_t i = 1; i < pieces.size(); ++i) {
    EXPECT_NEAR(get(pieces[i], "xstart"), get(pieces[i - 1], "xpos"), 1e-12) << i;
    EXPECT_NEAR(get(pieces[i], "ystart"), get(pieces[i - 1], "ypos"), 1e-12) << i;
    EXPECT_NEAR(get(pieces[i], "zstart"), get(pieces[i - 1], "zpos"), 1e-12) << i;
  }
  EXPECT_EQ(run(circle_job(), s)[1].find("xstart"), nullptr);  // none given, none made
}

// --- properties over random arcs -------------------------------------------------------------

struct RandomArc {
  Plane plane;
  bool cw;
  Eigen::Vector3d centre, start, end;
  double radius, start_deg, sweep, rise;
};

RandomArc random_arc(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  RandomArc r;
  r.plane = static_cast<Plane>(rng() % 3);
  r.cw = rng() % 2;
  r.radius = 0.5 + 200 * unit(rng);
  r.start_deg = rng() % 4 == 0 ? 90.0 * (rng() % 4) : 360 * unit(rng);
  const int kind = static_cast<int>(rng() % 4);
  r.sweep = kind == 0 ? 360.0 : kind == 1 ? 180 + 180 * unit(rng) : 1 + 359 * unit(rng);
  r.rise = rng() % 2 ? 0.0 : -50 + 100 * unit(rng);
  const auto a = toolpath::geometry::axes(r.plane);
  r.centre = Eigen::Vector3d(-100 + 200 * unit(rng), -100 + 200 * unit(rng), -100 + 200 * unit(rng));
  auto at = [&](double deg, double h) {
    Eigen::Vector3d p = r.centre;
    p[a.first] += r.radius * std::cos(deg * M_PI / 180);
    p[a.second] += r.radius * std::sin(deg * M_PI / 180);
    p[a.normal] += h;
    return p;
  };
  r.start = at(r.start_deg, 0);
  r.end = r.sweep == 360.0 ? (r.start + Eigen::Vector3d::Unit(a.normal) * r.rise)
                           : at(r.start_deg + (r.cw ? -r.sweep : r.sweep), r.rise);
  return r;
}

std::vector<Command> arc_commands(const RandomArc& r) {
  const auto a = toolpath::geometry::axes(r.plane);
  const char* plane = r.plane == Plane::XY ? "XY" : r.plane == Plane::YZ ? "YZ" : "ZX";
  return {command("@line", {{"xpos", num(r.start.x())}, {"ypos", num(r.start.y())}, {"zpos", num(r.start.z())}}),
          command("@arc", {{"xpos", num(r.end.x())},
                           {"ypos", num(r.end.y())},
                           {"zpos", num(r.end.z())},
                           {"feed", num(500)},
                           {"xcenter", num(r.centre[a.first])},
                           {"ycenter", num(r.centre[a.second])},
                           {"xcenter_rel", num(r.centre[a.first] - r.start[a.first])},
                           {"ycenter_rel", num(r.centre[a.second] - r.start[a.second])},
                           {"radius", num(r.radius)},
                           {"start_angle", num(toolpath::geometry::normalize_degrees(r.start_deg))},
                           {"end_angle", num(toolpath::geometry::normalize_degrees(r.start_deg + (r.cw ? -r.sweep : r.sweep)))},
                           {"arc_direction", word(r.cw ? "CW" : "CCW")},
                           {"arc_plane", word(plane)},
                           {"arc_size", num(r.sweep)}},
                  1)};
}

// Signed progress (degrees, in the arc's direction) from the original start to `p`.
double progress(const RandomArc& r, const Eigen::Vector3d& p) {
  const auto a = toolpath::geometry::axes(r.plane);
  double deg = std::atan2(p[a.second] - r.centre[a.second], p[a.first] - r.centre[a.first]) * 180 / M_PI;
  return toolpath::geometry::normalize_degrees(r.cw ? r.start_deg - deg : deg - r.start_deg);
}

void check_pieces(const RandomArc& r, const std::vector<Command>& out, const ArcSettings& s, const std::string& what) {
  SCOPED_TRACE(what);
  const auto a = toolpath::geometry::axes(r.plane);
  const double tol = 1e-9 * (1 + r.radius + std::abs(r.rise));
  Eigen::Vector3d previous = r.start;
  double swept = 0;
  for (std::size_t i = 1; i < out.size(); ++i) {
    const Command& c = out[i];
    Eigen::Vector3d end(get(c, "xpos"), get(c, "ypos"), get(c, "zpos"));
    // On the original arc: at its radius, at the height its angle calls for.
    EXPECT_NEAR(std::hypot(end[a.first] - r.centre[a.first], end[a.second] - r.centre[a.second]), r.radius, tol);
    double piece_sweep;
    if (c.name == "@arc") {
      // Starts where the previous piece ended; its values describe exactly this piece.
      EXPECT_NEAR(get(c, "xcenter") - get(c, "xcenter_rel"), previous[a.first], tol);
      EXPECT_NEAR(get(c, "ycenter") - get(c, "ycenter_rel"), previous[a.second], tol);
      EXPECT_EQ(get(c, "radius"), r.radius);
      piece_sweep = get(c, "arc_size");
      if (s.quadrants) {
        EXPECT_LE(piece_sweep, 90 + 1e-9);
      }
      if (!s.gt_180) {
        EXPECT_LE(piece_sweep, 180 + 1e-9);
      }
      double from = toolpath::geometry::normalize_degrees(
          std::atan2(previous[a.second] - r.centre[a.second], previous[a.first] - r.centre[a.first]) * 180 / M_PI);
      EXPECT_NEAR(std::remainder(get(c, "start_angle") - from, 360.0), 0, 1e-7);
      EXPECT_NEAR(std::remainder(get(c, "end_angle") - get(c, "start_angle") - (r.cw ? -piece_sweep : piece_sweep), 360.0),
                  0, 1e-7);
    } else {
      EXPECT_EQ(c.name, "@line");
      piece_sweep = toolpath::geometry::normalize_degrees(progress(r, end) - progress(r, previous));
      if (i + 1 == out.size() && piece_sweep < 1e-9) piece_sweep = 360.0 - swept;  // closing a full circle
      EXPECT_LE(piece_sweep, s.max_angle + 1e-7);
    }
    swept += piece_sweep;
    EXPECT_NEAR(end[a.normal] - r.start[a.normal], r.rise * swept / r.sweep, tol) << "piece " << i;
    previous = end;
  }
  EXPECT_NEAR(swept, r.sweep, 1e-7);
  EXPECT_EQ(previous, r.end);  // the last piece ends exactly where the arc does
}

TEST(ArcProperties, RandomArcsSplitAndLinearised) {
  std::mt19937 rng(20240611);
  for (int n = 0; n < 400; ++n) {
    RandomArc r = random_arc(rng);
    const std::string what = ::testing::PrintToString(n) + " plane " + std::to_string(int(r.plane)) +
                             (r.cw ? " CW" : " CCW") + " sweep " + std::to_string(r.sweep) + " rise " +
                             std::to_string(r.rise);
    ArcSettings quadrants;
    quadrants.quadrants = true;
    ArcSettings halves;
    halves.gt_180 = false;
    ArcSettings chords;
    chords.arc_exist = false;
    chords.max_angle = 7.5;
    chords.max_chord = 5;
    ArcSettings planes;  // only XY arcs allowed
    planes.zx_yz = false;
    planes.max_angle = 20;
    for (const auto* s : {&quadrants, &halves, &chords, &planes}) {
      auto out = run(arc_commands(r), *s);
      check_pieces(r, out, *s, what);
      if (s == &planes) {
        EXPECT_EQ(out.size() == 2 && out[1].name == "@arc", r.plane == Plane::XY);
      }
      EXPECT_EQ(run(out, *s), out) << "idempotent: " << what;
    }
  }
}

}  // namespace
