// Kinematic coordinate sets on split and linearised arcs: the manual's quadrant circle with a
// rotated part set and a shifted machine set (exact values), then every piece of arcs under
// rotated, mirrored and shifted sets against the set's map applied to the pos piece, and the
// arcs whose sets cannot be derived.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Geometry>

#include "prp/filters/arc_filter.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;
using prp::ArcSettings;
using toolpath::Command;

namespace {

struct SetMap {
  const char* prefix;
  Eigen::Matrix3d linear;
  Eigen::Vector3d shift;
  Eigen::Vector3d operator()(const Eigen::Vector3d& p) const { return linear * p + shift; }
};

void put(Command& c, const std::string& prefix, const char* role, const Eigen::Vector3d& p) {
  c.set("x" + prefix + role, num(p.x()));
  c.set("y" + prefix + role, num(p.y()));
  c.set("z" + prefix + role, num(p.z()));
}

Eigen::Vector3d point(const Command& c, const std::string& prefix, const char* role) {
  return {get(c, ("x" + prefix + role).c_str()), get(c, ("y" + prefix + role).c_str()),
          get(c, ("z" + prefix + role).c_str())};
}

Command motion(const char* name, const Eigen::Vector3d& p, const std::vector<SetMap>& sets) {
  Command c = command(name, {{"xpos", num(p.x())}, {"ypos", num(p.y())}, {"zpos", num(p.z())}});
  for (const auto& s : sets) put(c, s.prefix, "pos", s(p));
  return c;
}

// The manual's quadrant example (a full CW circle R30 about (26, 26) from (26, -4) at Z -6),
// reached by a plunge from Z 10, with h = pos turned 90 degrees about X and shifted 100 along X,
// and m = pos shifted by (-500, -300, -400).
std::vector<Command> circle_with_sets() {
  Eigen::Matrix3d about_x;
  about_x << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  const std::vector<SetMap> sets{{"h", about_x, {100, 0, 0}}, {"m", Eigen::Matrix3d::Identity(), {-500, -300, -400}}};
  Command arc = command("@arc", {{"xpos", num(26)}, {"ypos", num(-4)}, {"zpos", num(-6)}, {"feed", num(100)},
                                 {"xcenter", num(26)}, {"ycenter", num(26)}, {"xcenter_rel", num(0)},
                                 {"ycenter_rel", num(30)}, {"radius", num(30)}, {"start_angle", num(270)},
                                 {"end_angle", num(270)}, {"arc_direction", word("CW")}, {"arc_plane", word("XY")},
                                 {"arc_size", num(360)}, {"zstart", num(-6)}, {"arc_plane_h", word("ZX")},
                                 {"start_angle_h", num(180)}, {"end_angle_h", num(180)}, {"arc_plane_m", word("XY")},
                                 {"start_angle_m", num(270)}, {"end_angle_m", num(270)}, {"xmcenter_rel", num(0)},
                                 {"ymcenter_rel", num(30)}},
                         3);
  for (const auto& s : sets) {
    put(arc, s.prefix, "pos", s({26, -4, -6}));
    put(arc, s.prefix, "center", s({26, 26, -6}));
    put(arc, s.prefix, "start", s({26, -4, -6}));
  }
  return {motion("@rapid_move", {26, -4, 10}, sets), motion("@line", {26, -4, -6}, sets), arc};
}

const auto run = run_arc_filter;

TEST(KinematicSets, QuadrantCircleWithRotatedAndShiftedSets) {
  ArcSettings s;
  s.quadrants = true;
  auto out = run(circle_with_sets(), s);
  ASSERT_EQ(out.size(), 6u);
  // Per piece: h end, h start, h angles (ZX plane: from Z towards X), m end, m angles, m relative centre.
  struct Row {
    double hend[3], hstart[3], hangles[2], mend[3], mangles[2], mrel[2];
  };
  const Row rows[] = {
      {{96, 6, 26}, {126, 6, -4}, {180, 270}, {-504, -274, -406}, {270, 180}, {0, 30}},
      {{126, 6, 56}, {96, 6, 26}, {270, 0}, {-474, -244, -406}, {180, 90}, {30, 0}},
      {{156, 6, 26}, {126, 6, 56}, {0, 90}, {-444, -274, -406}, {90, 0}, {0, -30}},
      {{126, 6, -4}, {156, 6, 26}, {90, 180}, {-474, -304, -406}, {0, 270}, {-30, 0}},
  };
  for (std::size_t i = 0; i < 4; ++i) {
    const Command& c = out[i + 2];
    const Row& r = rows[i];
    SCOPED_TRACE(i);
    auto same = [](const Eigen::Vector3d& got, const double (&want)[3]) {
      return (got - Eigen::Vector3d(want[0], want[1], want[2])).norm() < 1e-9;
    };
    auto angle = [](double got, double want) { return std::abs(std::remainder(got - want, 360.0)) < 1e-9; };
    const double hcentre[3] = {126, 6, 26}, mcentre[3] = {-474, -274, -406};
    EXPECT_TRUE(same(point(c, "h", "pos"), r.hend));
    EXPECT_TRUE(same(point(c, "h", "start"), r.hstart));
    EXPECT_TRUE(same(point(c, "h", "center"), hcentre));
    EXPECT_TRUE(angle(get(c, "start_angle_h"), r.hangles[0])) << get(c, "start_angle_h");
    EXPECT_TRUE(angle(get(c, "end_angle_h"), r.hangles[1])) << get(c, "end_angle_h");
    EXPECT_TRUE(same(point(c, "m", "pos"), r.mend));
    EXPECT_TRUE(same(point(c, "m", "center"), mcentre));
    EXPECT_TRUE(angle(get(c, "start_angle_m"), r.mangles[0]));
    EXPECT_TRUE(angle(get(c, "end_angle_m"), r.mangles[1]));
    EXPECT_NEAR(get(c, "xmcenter_rel"), r.mrel[0], 1e-9);
    EXPECT_NEAR(get(c, "ymcenter_rel"), r.mrel[1], 1e-9);
  }
}

// --- every piece against the set's map ---------------------------------------------------------

struct ArcCase {
  const char* what;
  double start_deg, sweep, rise;
  bool cw;
};

Eigen::Matrix3d rotation(double degrees, Eigen::Vector3d axis) {
  return Eigen::AngleAxisd(degrees * std::numbers::pi / 180, axis.normalized()).toRotationMatrix();
}

std::vector<Command> arc_job(const ArcCase& k, const std::vector<SetMap>& sets) {
  const Eigen::Vector3d centre(10, 20, -5);
  const double r = 25, rad = std::numbers::pi / 180;
  auto at = [&](double deg, double h) {
    return Eigen::Vector3d(centre.x() + r * std::cos(deg * rad), centre.y() + r * std::sin(deg * rad), centre.z() + h);
  };
  const Eigen::Vector3d start = at(k.start_deg, 0);
  const Eigen::Vector3d end = k.sweep == 360 ? Eigen::Vector3d(start + Eigen::Vector3d(0, 0, k.rise))
                                             : at(k.start_deg + (k.cw ? -k.sweep : k.sweep), k.rise);
  Command arc = command("@arc", {{"xpos", num(end.x())}, {"ypos", num(end.y())}, {"zpos", num(end.z())},
                                 {"feed", num(400)}, {"xcenter", num(centre.x())}, {"ycenter", num(centre.y())},
                                 {"xcenter_rel", num(centre.x() - start.x())}, {"ycenter_rel", num(centre.y() - start.y())},
                                 {"radius", num(r)}, {"arc_direction", word(k.cw ? "CW" : "CCW")},
                                 {"arc_plane", word("XY")}, {"arc_size", num(k.sweep)}, {"zstart", num(start.z())}},
                         2);
  for (const auto& s : sets) {
    put(arc, s.prefix, "pos", s(end));
    put(arc, s.prefix, "center", s(centre));
    put(arc, s.prefix, "start", s(start));
    arc.set(std::string("x") + s.prefix + "center_rel", num(s(centre).x() - s(start).x()));
  }
  // A lead-in from above the start, off the arc's plane: it fixes the plane of a half or full
  // circle, and tells a mirrored set from a rotated one.
  return {motion("@rapid_move", start + Eigen::Vector3d(3, -4, 30), sets),
          motion("@rapid_move", start + Eigen::Vector3d(0, 0, 30), sets), motion("@line", start, sets), arc};
}

void check(const std::vector<Command>& out, const std::vector<SetMap>& sets, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_GE(out.size(), 4u);
  Eigen::Vector3d previous(get(out[2], "xpos"), get(out[2], "ypos"), get(out[2], "zpos"));
  for (std::size_t i = 3; i < out.size(); ++i) {
    const Command& c = out[i];
    const Eigen::Vector3d end(get(c, "xpos"), get(c, "ypos"), get(c, "zpos"));
    for (const auto& s : sets) {
      EXPECT_LT((point(c, s.prefix, "pos") - s(end)).norm(), 1e-9) << s.prefix << " piece " << i;
      if (c.name != "@arc") continue;
      const Eigen::Vector3d centre(get(c, "xcenter"), get(c, "ycenter"), get(c, "zstart"));
      EXPECT_LT((point(c, s.prefix, "center") - s(centre)).norm(), 1e-9) << s.prefix << " piece " << i;
      EXPECT_LT((point(c, s.prefix, "start") - s(previous)).norm(), 1e-9) << s.prefix << " piece " << i;
      const Eigen::Vector3d rel = point(c, s.prefix, "center") - point(c, s.prefix, "start");
      EXPECT_NEAR(get(c, (std::string("x") + s.prefix + "center_rel").c_str()), rel.x(), 1e-9);
    }
    previous = end;
  }
}

TEST(KinematicSets, EveryPieceIsTheSetsImageOfThePosPiece) {
  const std::vector<SetMap> sets{
      {"h", rotation(37, {1, 2, 3}), {5, -7, 11}},
      {"m", Eigen::Matrix3d::Identity(), {-400, -250, -300}},
      {"o", Eigen::Vector3d(-1, 1, 1).asDiagonal(), {0, 0, 0}},  // mirrored in X
      {"l", Eigen::Matrix3d::Identity(), {1, 2, 3}},
      {"t", rotation(-90, {0, 1, 0}), {0, 0, 150}},
      {"to", rotation(180, {1, 0, 0}), {2, 2, 2}},
  };
  const ArcCase arcs[] = {{"planar 120 CCW", 30, 120, 0, false},   {"helix 250 CW", 200, 250, -6, true},
                          {"full circle CW", 270, 360, 0, true},   {"helix full circle", 0, 360, 4, false},
                          {"half circle CCW", 90, 180, 0, false},  {"helix half CW", 45, 180, 2, true}};
  ArcSettings quadrants;
  quadrants.quadrants = true;
  ArcSettings halves;
  halves.gt_180 = false;
  ArcSettings chords;
  chords.arc_exist = false;
  chords.max_angle = 15;
  for (const auto& k : arcs) {
    for (const auto* s : {&quadrants, &halves, &chords}) {
      auto out = run(arc_job(k, sets), *s);
      check(out, sets, k.what);
    }
  }
}

std::string error_of(std::vector<Command> in) {
  ArcSettings s;
  s.quadrants = true;
  try {
    run(std::move(in), s);
  } catch (const prp::StreamError& e) {
    return e.what();
  }
  return "no error";
}

TEST(KinematicSets, WhatCannotBeDerivedIsAnError) {
  const ArcCase circle{"", 270, 360, 0, true};
  const std::vector<SetMap> turned{{"h", rotation(90, {1, 0, 0}), {0, 0, 0}}};
  const std::vector<SetMap> shifted{{"l", Eigen::Matrix3d::Identity(), {7, 8, 9}}};

  // Without the lead-in, a full circle's own points leave a turned set's plane open ...
  auto job = arc_job(circle, turned);
  job.erase(job.begin(), job.begin() + 3);
  EXPECT_EQ(error_of(job),
            "command 2 (@arc): the arc's h points lie on one line (a half or full circle) and no recent h point fixes "
            "the orientation of its plane: the pieces' h values cannot be derived");
  // ... but a merely shifted set is shifted on every piece.
  job = arc_job(circle, shifted);
  job.erase(job.begin(), job.begin() + 3);
  job.insert(job.begin(), {command("@rapid_move", {{"xpos", num(10)}, {"ypos", num(-5)}, {"zpos", num(20)}}),
                           command("@rapid_move", {{"xpos", num(10)}, {"ypos", num(-5)}, {"zpos", num(0)}}),
                           command("@line", {{"xpos", num(10)}, {"ypos", num(-5)}, {"zpos", num(-5)}})});
  check(run(job, [] { ArcSettings s; s.quadrants = true; return s; }()), shifted, "shifted");

  job = arc_job(circle, turned);
  job.back().parameters.pop_back();  // xhcenter_rel
  job.back().parameters.pop_back();  // zhstart
  EXPECT_EQ(error_of(job),
            "command 2 (@arc): the arc carries only part of the h coordinate set (it needs xhpos.., xhcenter.. and "
            "xhstart..): the pieces' h values cannot be derived");

  job = arc_job(circle, turned);
  job.back().set("xhcenter", num(get(job.back(), "xhcenter") + 1));
  EXPECT_EQ(error_of(job),
            "command 2 (@arc): the arc's h coordinates are not a rigid image of its working-plane ones (start to "
            "centre 25.02 against 25, start to end 0 against 0): the pieces' h values cannot be derived");
}

// kSetEndPoints (what the arc filter looks for before asking SetHistory::observe) lists exactly
// the catalogue names the spelled rule calls set end points.
TEST(KinematicSets, SetEndPointsAreExactlyTheX_PosNames) {
  std::vector<toolpath::ParamKey> spelled;
  for (std::size_t k = 1; k <= toolpath::param_key_count; ++k) {
    const auto key = static_cast<toolpath::ParamKey>(k);
    if (auto c = prp::classify_set_coordinate(toolpath::param_name(key)); c && c->role == prp::SetRole::End)
      spelled.push_back(key);
  }
  std::vector<toolpath::ParamKey> listed(std::begin(prp::kSetEndPoints), std::end(prp::kSetEndPoints));
  std::sort(listed.begin(), listed.end());
  EXPECT_EQ(listed, spelled);
}

}  // namespace
