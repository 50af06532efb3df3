// R-form arc centres (the PikoCNC manual's section 5.3 vectors) and the sweeps they give; angles brought
// into [0, 360).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "toolpath/geometry.hpp"

namespace {

using Eigen::Vector3d;
using toolpath::geometry::Direction;
using toolpath::geometry::Plane;

TEST(Geometry, CentreFromRadius) {
  struct Case {
    double x, y, r;
    Direction direction;
    Vector3d centre;
    double sweep;
  } cases[] = {
      {10, 10, 10, Direction::CCW, {0, 10, 0}, 90},    // G3 X10 Y10 R10
      {10, 10, 10, Direction::CW, {10, 0, 0}, 90},     // G2 X10 Y10 R10
      {10, 10, -10, Direction::CCW, {10, 0, 0}, 270},  // G3 X10 Y10 R-10
      {10, 0, 5, Direction::CW, {5, 0, 0}, 180},       // half circle
  };
  for (const auto& c : cases) {
    const auto centre = toolpath::geometry::centre_from_radius({0, 0, 0}, {c.x, c.y, 0}, c.r, Plane::XY, c.direction, 0.002);
    ASSERT_TRUE(centre);
    EXPECT_NEAR((*centre - c.centre).norm(), 0, 1e-12);
    const auto arc = toolpath::geometry::make_arc({0, 0, 0}, {c.x, c.y, 0}, *centre, Plane::XY, c.direction, std::nullopt);
    EXPECT_NEAR(arc.sweep, c.sweep, 1e-9);
  }
  EXPECT_FALSE(toolpath::geometry::centre_from_radius({0, 0, 0}, {10, 0, 0}, 4.99, Plane::XY, Direction::CCW, 0.002));
  EXPECT_TRUE(toolpath::geometry::centre_from_radius({0, 0, 0}, {10, 0, 0}, 4.999, Plane::XY, Direction::CCW, 0.002));  // within tolerance
  EXPECT_FALSE(toolpath::geometry::centre_from_radius({0, 0, 0}, {0, 0, 5}, 5, Plane::XY, Direction::CCW, 0.002));  // no chord in the plane
}

// The centre lies in the arc's plane at the start's normal coordinate (a helix rises from it).
TEST(Geometry, CentreFromRadiusInOtherPlanes) {
  const auto zx = toolpath::geometry::centre_from_radius({0, 7, 0}, {10, 9, 10}, 10, Plane::ZX, Direction::CCW, 0.002);
  ASSERT_TRUE(zx);
  EXPECT_NEAR((*zx - Vector3d(10, 7, 0)).norm(), 0, 1e-12);  // ZX: first axis Z, second X
  const auto yz = toolpath::geometry::centre_from_radius({3, 0, 0}, {3, 10, 0}, 5, Plane::YZ, Direction::CW, 0.002);
  ASSERT_TRUE(yz);
  EXPECT_NEAR((*yz - Vector3d(3, 5, 0)).norm(), 0, 1e-12);
}

TEST(Geometry, FullCircleSweep) {
  const auto arc = toolpath::geometry::make_arc({0, 0, 0}, {0, 0, 0}, {5, 0, 0}, Plane::XY, Direction::CW, std::nullopt);
  EXPECT_EQ(arc.sweep, 360.0);
}

}  // namespace

namespace {

// normalize_degrees leaves fmod out below 360 in magnitude (fmod is exact there): the same degrees,
// bit for bit, as the remainder by fmod for angles of every size and sign.
TEST(Geometry, NormalizeDegreesAsFmod) {
  auto reference = [](double degrees) {
    double r = std::fmod(degrees, 360.0);
    if (r < 0) r += 360.0;
    return r >= 360.0 ? 0.0 : r;
  };
  auto same = [&](double v) {
    SCOPED_TRACE(v);
    const double got = toolpath::geometry::normalize_degrees(v), expected = reference(v);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(expected));
  };
  for (double v : {0.0, -0.0, 359.99999999999994, -359.99999999999994, 360.0, -360.0, 720.0, -1e-300, 1e-300, 180.0,
                   -180.0, 1e20, -1e20})
    same(v);
  std::mt19937_64 rng(25);
  std::uniform_real_distribution<double> angle(-1000.0, 1000.0);
  for (int n = 0; n < 100000; ++n) {
    const double v = angle(rng);
    same(v);
    same(std::atan2(angle(rng), angle(rng)) * 180.0 / 3.14159265358979323846);  // as make_arc's angles come
  }
}

}  // namespace
