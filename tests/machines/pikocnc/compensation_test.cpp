// Cutter radius compensation (docs/pikocnc.md): the offset geometry, a table of corners (inside,
// outside, tangent; line/arc combinations; both sides; planes G17 and G19, which follow the mill
// rules), and properties of compensated random polygons. G18 (lathe entry rule), errors and the
// documented example are golden folders (compensation_*).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "machines/pikocnc/model/offset.hpp"
#include "machines/pikocnc/model/reader.hpp"

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kTol = 1e-9;
const double kS2 = std::sqrt(2.0);

// ---- offset geometry ------------------------------------------------------------------------

TEST(PikoOffset, LineMovesToTheLeftForPositiveOffset) {
  const pikocnc::OffsetElement e = pikocnc::offset_line({0, 0}, {10, 0}, 2);
  EXPECT_NEAR((e.start - Vector2d(0, 2)).norm(), 0, kTol);
  EXPECT_NEAR((e.end - Vector2d(10, 2)).norm(), 0, kTol);
  EXPECT_NEAR(e.param({4, 2}, 0), 4, kTol);
}

TEST(PikoOffset, ArcRadiusShrinksOnTheInsideOfTheTurn) {
  // counter-clockwise quarter circle of radius 5 around the origin, left offset 1: radius 4
  const auto ccw = pikocnc::offset_arc({5, 0}, {0, 5}, {0, 0}, true, 90, 1);
  EXPECT_NEAR(ccw.radius, 4, kTol);
  EXPECT_NEAR((ccw.end - Vector2d(0, 4)).norm(), 0, kTol);
  EXPECT_NEAR(ccw.param({0, 4}, ccw.end_param()), 90, kTol);
  EXPECT_NEAR(ccw.param(ccw.point(-5), 0), -5, kTol);  // just before the start reads negative
  EXPECT_NEAR(ccw.distance(90), 2 * M_PI, kTol);  // a quarter of the radius-4 circle
  const auto cw = pikocnc::offset_arc({0, 5}, {5, 0}, {0, 0}, false, 90, 1);
  EXPECT_NEAR(cw.radius, 6, kTol);
  EXPECT_NEAR((cw.point(45) - Vector2d(6 / kS2, 6 / kS2)).norm(), 0, kTol);
}

struct CrossingCase {
  const char* name;
  pikocnc::OffsetElement a, b;
  std::vector<Vector2d> expected;
};

pikocnc::OffsetElement circle(Vector2d c, double r) {
  return pikocnc::offset_arc(c + Vector2d(r, 0), c + Vector2d(r, 0), c, true, 360, 0);
}

TEST(PikoOffset, CrossingsOfCarriers) {
  const std::vector<CrossingCase> cases = {
      {"line-line", pikocnc::offset_line({0, 0}, {10, 0}, 0), pikocnc::offset_line({5, -5}, {5, 5}, 0), {{5, 0}}},
      {"parallel", pikocnc::offset_line({0, 0}, {10, 0}, 0), pikocnc::offset_line({0, 1}, {10, 1}, 0), {}},
      {"line-circle", pikocnc::offset_line({-10, 3}, {10, 3}, 0), circle({0, 0}, 5), {{-4, 3}, {4, 3}}},
      {"line-circle tangent", pikocnc::offset_line({-10, 5}, {10, 5}, 0), circle({0, 0}, 5), {{0, 5}}},
      {"line-circle apart", pikocnc::offset_line({-10, 6}, {10, 6}, 0), circle({0, 0}, 5), {}},
      {"circle-circle", circle({0, 0}, 5), circle({8, 0}, 5), {{4, -3}, {4, 3}}},
      {"circle-circle touching", circle({0, 0}, 5), circle({10, 0}, 5), {{5, 0}}},
      {"circle inside circle", circle({0, 0}, 5), circle({1, 0}, 1), {}},
      {"concentric", circle({0, 0}, 5), circle({0, 0}, 3), {}},
  };
  for (const auto& c : cases) {
    const pikocnc::Crossings x = pikocnc::intersect(c.a, c.b);
    ASSERT_EQ(x.count, c.expected.size()) << c.name;
    for (std::size_t i = 0; i < x.count; ++i)
      EXPECT_NEAR((x.point[i] - c.expected[i]).norm(), 0, kTol) << c.name << " point " << i;
  }
}

// ---- reading programs -----------------------------------------------------------------------

struct Motion {
  std::string name;
  Vector3d to, centre;
  std::string direction;
  double radius = 0;
  bool compensated = false;
  Vector3d programmed;
  std::size_t line = 0;
};

double number(const toolpath::Command& c, const char* name) {
  for (const auto& p : c.parameters)
    if (p.name == name) return p.value.numeric;
  return 0.0;
}

std::string text(const toolpath::Command& c, const char* name) {
  for (const auto& p : c.parameters)
    if (p.name == name) return p.value.text;
  return {};
}

bool flag(const toolpath::Command& c, const char* name) {
  for (const auto& p : c.parameters)
    if (p.name == name) return p.value.logical;
  return false;
}

std::vector<Motion> read_motion(const std::string& program, std::vector<std::string>* warnings = nullptr) {
  std::istringstream in(program);
  pikocnc::PikoReader reader(in, "case.nc");
  std::vector<Motion> out;
  toolpath::Command c;
  while (reader.next(c)) {
    if (c.name != "@rapid_move" && c.name != "@line" && c.name != "@arc") continue;
    Motion m;
    m.name = c.name;
    m.to = {number(c, "xpos"), number(c, "ypos"), number(c, "zpos")};
    m.centre = {number(c, "xcenter"), number(c, "ycenter"), number(c, "zcenter")};
    m.direction = text(c, "arc_direction");
    m.radius = number(c, "radius");
    m.compensated = flag(c, "compensated");
    m.programmed = {number(c, "prog_xpos"), number(c, "prog_ypos"), number(c, "prog_zpos")};
    m.line = reader.line();
    out.push_back(m);
  }
  if (warnings)
    for (const auto& d : reader.diagnostics().kept()) warnings->push_back(std::to_string(d.where.line) + ": " + d.message);
  return out;
}

// ---- corners --------------------------------------------------------------------------------

// A table row is written in plane coordinates (u, v): G17 maps them to X Y, G19 to Y Z.
struct Expected {
  char kind;  // 'R' rapid, 'L' line, 'A' arc
  double u, v;
  double cu = 0, cv = 0;  // arc centre
  const char* dir = "";
};

struct CornerCase {
  const char* name;
  const char* side;   // G41 or G42
  const char* first;  // the element into the corner at (10, 0), from (0, 0)
  const char* second; // the element out of it
  std::vector<Expected> expected;
};

// Words in plane coordinates: "U10 V0 P5 Q5" become X Y I J (G17) or Y Z J K (G19).
std::string in_plane_words(const std::string& words, bool yz) {
  std::string s;
  for (char ch : words) {
    switch (ch) {
      case 'U': s += yz ? 'Y' : 'X'; break;
      case 'V': s += yz ? 'Z' : 'Y'; break;
      case 'P': s += yz ? 'J' : 'I'; break;
      case 'Q': s += yz ? 'K' : 'J'; break;
      default: s += ch;
    }
  }
  return s;
}

Vector3d place(double u, double v, bool yz) { return yz ? Vector3d(0, u, v) : Vector3d(u, v, 0); }

const double k45 = 1 / kS2;  // sin 45

std::vector<CornerCase> corner_cases() {
  const double r50 = std::sqrt(50.0);
  // line then arc / arc then line / arc then arc, with the circle (5,5) r sqrt(50) through (0,0), (10,0), (10,10)
  const double cross_ll = 5 - std::sqrt((r50 - 1) * (r50 - 1) - 16);  // circle (5,5) r-1 and v = 1 or u = 9
  // circles (5,5) r-1 and (15,5) r+1 cross at (5 + x, 5 -+ h)
  const double ra = r50 - 1, rb = r50 + 1;
  const double cross_x = (100 + ra * ra - rb * rb) / 20, cross_h = std::sqrt(ra * ra - cross_x * cross_x);
  return {
      {"line-line left turn, G41: inside", "G41", "G1 U10 V0", "G1 U10 V10",
       {{'R', 0, 1}, {'L', 9, 1}, {'L', 9, 10}}},
      {"line-line left turn, G42: outside", "G42", "G1 U10 V0", "G1 U10 V10",
       {{'R', 0, -1}, {'L', 10, -1}, {'A', 11, 0, 10, 0, "CCW"}, {'L', 11, 10}}},
      {"line-line right turn, G41: outside", "G41", "G1 U10 V0", "G1 U10 V-10",
       {{'R', 0, 1}, {'L', 10, 1}, {'A', 11, 0, 10, 0, "CW"}, {'L', 11, -10}}},
      {"line-line right turn, G42: inside", "G42", "G1 U10 V0", "G1 U10 V-10",
       {{'R', 0, -1}, {'L', 9, -1}, {'L', 9, -10}}},
      {"line-line 45 degrees left, G41: inside", "G41", "G1 U10 V0", "G1 U20 V10",
       {{'R', 0, 1}, {'L', 10 - (kS2 - 1), 1}, {'L', 20 - k45, 10 + k45}}},
      {"line-line 135 degrees left, G42: outside", "G42", "G1 U10 V0", "G1 U0 V10",
       {{'R', 0, -1}, {'L', 10, -1}, {'A', 10 + k45, k45, 10, 0, "CCW"}, {'L', k45, 10 + k45}}},
      {"line-line straight on: no corner", "G41", "G1 U10 V0", "G1 U20 V0",
       {{'R', 0, 1}, {'L', 10, 1}, {'L', 20, 1}}},
      {"line-line reversal, G41: half circle", "G41", "G1 U10 V0", "G1 U5 V0",
       {{'R', 0, 1}, {'L', 10, 1}, {'A', 10, -1, 10, 0, "CW"}, {'L', 5, -1}}},
      {"line-arc tangent, G41", "G41", "G1 U10 V0", "G3 U15 V5 P0 Q5",
       {{'R', 0, 1}, {'L', 10, 1}, {'A', 14, 5, 10, 5, "CCW"}}},
      {"line-arc tangent, G42", "G42", "G1 U10 V0", "G3 U15 V5 P0 Q5",
       {{'R', 0, -1}, {'L', 10, -1}, {'A', 16, 5, 10, 5, "CCW"}}},
      {"line-arc left turn, G41: inside", "G41", "G1 U10 V0", "G3 U10 V10 P-5 Q5",
       {{'R', 0, 1}, {'L', 5 + std::sqrt((r50 - 1) * (r50 - 1) - 16), 1}, {'A', 5 + (r50 - 1) * k45, 5 + (r50 - 1) * k45, 5, 5, "CCW"}}},
      {"line-arc left turn, G42: outside", "G42", "G1 U10 V0", "G3 U10 V10 P-5 Q5",
       {{'R', 0, -1}, {'L', 10, -1}, {'A', 10 + k45, -k45, 10, 0, "CCW"},
        {'A', 5 + (r50 + 1) * k45, 5 + (r50 + 1) * k45, 5, 5, "CCW"}}},
      {"arc-line, G41: inside", "G41", "G3 U10 V0 P5 Q5", "G1 U10 V10",
       {{'R', 5 - (r50 - 1) * k45, 5 - (r50 - 1) * k45}, {'A', 9, cross_ll, 5, 5, "CCW"}, {'L', 9, 10}}},
      {"arc-line, G42: outside", "G42", "G3 U10 V0 P5 Q5", "G1 U10 V10",
       {{'R', 5 - (r50 + 1) * k45, 5 - (r50 + 1) * k45}, {'A', 5 + (r50 + 1) * k45, 5 - (r50 + 1) * k45, 5, 5, "CCW"},
        {'A', 11, 0, 10, 0, "CCW"}, {'L', 11, 10}}},
      {"arc-arc, G41: inside", "G41", "G3 U10 V0 P5 Q5", "G2 U10 V10 P5 Q5",
       {{'R', 5 - (r50 - 1) * k45, 5 - (r50 - 1) * k45}, {'A', 5 + cross_x, 5 - cross_h, 5, 5, "CCW"},
        {'A', 15 - (r50 + 1) * k45, 5 + (r50 + 1) * k45, 15, 5, "CW"}}},
      {"arc-arc, G42: outside", "G42", "G3 U10 V0 P5 Q5", "G2 U10 V10 P5 Q5",
       {{'R', 5 - (r50 + 1) * k45, 5 - (r50 + 1) * k45}, {'A', 10 + k45, -k45, 5, 5, "CCW"},
        {'A', 10 + k45, k45, 10, 0, "CCW"}, {'A', 15 - (r50 - 1) * k45, 5 + (r50 - 1) * k45, 15, 5, "CW"}}},
  };
}

class Corners : public testing::TestWithParam<bool> {};  // false: G17, true: G19

TEST_P(Corners, MatchTheTable) {
  const bool yz = GetParam();
  for (const CornerCase& c : corner_cases()) {
    const std::string program = std::string("%\n") + (yz ? "G19\n" : "G17\n") + in_plane_words("G0 U-5 V-5", yz) + "\n" +
                                c.side + " R1\n" + in_plane_words("G0 U0 V0", yz) + "\nF100\n" + in_plane_words(c.first, yz) +
                                "\n" + in_plane_words(c.second, yz) + "\nG40\n";
    std::vector<Motion> got = read_motion(program);
    got.erase(got.begin());  // the rapid before G41/G42
    ASSERT_EQ(got.size(), c.expected.size()) << c.name << "\n" << program;
    for (std::size_t i = 0; i < got.size(); ++i) {
      const Expected& e = c.expected[i];
      const char* name = e.kind == 'R' ? "@rapid_move" : e.kind == 'L' ? "@line" : "@arc";
      EXPECT_EQ(got[i].name, name) << c.name << " move " << i;
      EXPECT_NEAR((got[i].to - place(e.u, e.v, yz)).norm(), 0, 1e-8) << c.name << " move " << i;
      if (e.kind == 'A') {
        EXPECT_NEAR((got[i].centre - place(e.cu, e.cv, yz)).norm(), 0, 1e-8) << c.name << " move " << i;
        EXPECT_EQ(got[i].direction, e.dir) << c.name << " move " << i;
      }
      EXPECT_TRUE(got[i].compensated) << c.name << " move " << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(PikoCompensation, Corners, testing::Values(false, true),
                         [](const testing::TestParamInfo<bool>& i) { return i.param ? "G19" : "G17"; });

// ---- properties -----------------------------------------------------------------------------

double distance_to_segment(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
  const Vector2d d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + t * d - p).norm();
}

// Convex polygons traversed counter-clockwise: G41 cuts inside, G42 outside. Every compensated
// line lies at the radius from its programmed edge on the chosen side, every corner arc is centred
// on its vertex with the radius, no point of the path comes closer to the contour than the radius,
// and the inside path closes on itself (end-of-contour rule).
TEST(PikoCompensation, RandomConvexPolygonsKeepTheRadius) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int round = 0; round < 60; ++round) {
    const int n = 3 + static_cast<int>(unit(rng) * 8);
    const double size = 20 + 30 * unit(rng);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(2 * M_PI * (i + 0.3 + 0.4 * unit(rng)) / n);
    std::vector<Vector2d> vertex;
    for (double a : angles) vertex.emplace_back(size * std::cos(a), size * std::sin(a));
    double shortest = 1e9;
    for (int i = 0; i < n; ++i) shortest = std::min(shortest, (vertex[(i + 1) % n] - vertex[i]).norm());
    const double r = std::min(0.5 + 2.5 * unit(rng), shortest / 12);
    for (const bool inside : {true, false}) {
      std::ostringstream p;
      p.precision(17);
      p << "%\n" << (inside ? "G41" : "G42") << " R" << r << "\nG0 X" << vertex[0].x() << " Y" << vertex[0].y()
        << "\nG1 Z-1 F100\n";
      for (int i = 1; i <= n; ++i) p << "G1 X" << vertex[i % n].x() << " Y" << vertex[i % n].y() << "\n";
      p << "G0 Z5\nG40\n";
      const std::vector<Motion> got = read_motion(p.str());
      const double side = inside ? 1 : -1;
      Vector2d at;
      bool started = false;
      Vector2d first;
      for (const Motion& m : got) {
        const Vector2d to = m.to.head<2>();
        if (started && m.name == "@line" && (to - at).norm() > 1e-9) {
          // the edge this line offsets ends at its programmed point
          const Vector2d end = m.programmed.head<2>();
          int k = 0;
          while ((vertex[static_cast<std::size_t>(k)] - end).norm() > 1e-9) ++k;
          const Vector2d a = vertex[static_cast<std::size_t>((k + n - 1) % n)], b = end;
          const Vector2d left = Vector2d(-(b - a).y(), (b - a).x()).normalized();
          EXPECT_NEAR((at - a).dot(left), side * r, 1e-8) << p.str();
          EXPECT_NEAR((to - a).dot(left), side * r, 1e-8) << p.str();
        }
        if (m.name == "@arc") {
          EXPECT_FALSE(inside) << "an inside contour of a convex polygon has no corner arcs";
          EXPECT_NEAR(m.radius, r, 1e-8);
          EXPECT_NEAR((m.centre.head<2>() - m.programmed.head<2>()).norm(), 0, 1e-8);
        }
        if (m.name != "@rapid_move" || !started) {
          double nearest = 1e9;
          for (int i = 0; i < n; ++i)
            nearest = std::min(nearest, distance_to_segment(to, vertex[static_cast<std::size_t>(i)], vertex[static_cast<std::size_t>((i + 1) % n)]));
          EXPECT_GE(nearest, r - 1e-8) << p.str();
        }
        EXPECT_TRUE(m.compensated);
        if (!started) first = to;
        started = true;
        at = to;
      }
      if (inside) {
        EXPECT_NEAR((at - first).norm(), 0, 1e-8) << "inside contour closes\n" << p.str();
      }
    }
  }
}

// Arcs keep their centre and change their radius by exactly the compensation radius.
TEST(PikoCompensation, ArcsKeepTheirCentre) {
  const std::vector<Motion> got = read_motion("%\nG42 R1.5\nG0 X-20 Y0\nG1 Z-1 F100\nG2 X20 Y0 I20 J0\nG2 X-20 Y0 I-20 J0\nG0 Z5\nG40\n");
  ASSERT_EQ(got.size(), 5u);
  for (int i : {2, 3}) {
    EXPECT_EQ(got[static_cast<std::size_t>(i)].name, "@arc");
    EXPECT_NEAR(got[static_cast<std::size_t>(i)].radius, 18.5, kTol);
    EXPECT_NEAR(got[static_cast<std::size_t>(i)].centre.head<2>().norm(), 0, kTol);
  }
  EXPECT_NEAR((got[0].to - Vector3d(-18.5, 0, 0)).norm(), 0, kTol);
  EXPECT_NEAR((got[3].to - Vector3d(-18.5, 0, -1)).norm(), 0, kTol);
}

}  // namespace
