// R-form arc centres (the PikoCNC manual's section 5.3 vectors) and the sweeps they give.
#include <gtest/gtest.h>

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
