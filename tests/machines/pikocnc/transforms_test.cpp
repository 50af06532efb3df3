// Transformation vectors of section 10.
#include <gtest/gtest.h>

#include "machines/pikocnc/model/transforms.hpp"

namespace {

using Eigen::Vector3d;
using pikocnc::Plane;

TEST(PikoTransforms, DocumentVectors) {
  const Vector3d p(10, 20, 5);
  auto near = [](const Vector3d& a, const Vector3d& b) { return (a - b).norm() < 1e-9; };
  EXPECT_TRUE(near(*pikocnc::tilted_plane(1, 123, {90, 0, 0}, {0, 0, -60}) * p, {10, -5, -40}));
  EXPECT_TRUE(near(*pikocnc::tilted_plane(1, 123, {90, 0, 90}, {180, 0, -60}) * p, {185, 10, -40}));
  // P0 is applied about fixed axes: Rz(K) Rx(J) Rz(I)
  EXPECT_TRUE(near(*pikocnc::tilted_plane(0, 0, {90, 90, 0}, {0, 0, 0}) * Vector3d(10, 0, 0), {0, 0, 10}));
  // Q312: Z by K, then X by I, then Y by J
  EXPECT_TRUE(near(*pikocnc::tilted_plane(1, 312, {90, 0, 90}, {0, 0, 0}) * Vector3d(1, 0, 0), {0, 0, 1}));
  EXPECT_FALSE(pikocnc::tilted_plane(1, 124, {0, 0, 0}, {0, 0, 0}));
  EXPECT_FALSE(pikocnc::tilted_plane(1, 112, {0, 0, 0}, {0, 0, 0}));
  EXPECT_FALSE(pikocnc::tilted_plane(2, 123, {0, 0, 0}, {0, 0, 0}));
  EXPECT_TRUE(near(pikocnc::rotation({20, 10, 0}, Plane::XY, 35) * Vector3d(30, 10, 0), {28.191520442889917, 15.735764363510461, 0}));
  EXPECT_TRUE(near(pikocnc::scaling({40, 20, 0}, {1.6, 1, 1}) * Vector3d(0, 0, 0), {-24, 0, 0}));

  pikocnc::TransformStack stack;
  stack.push(*pikocnc::tilted_plane(1, 123, {90, 0, 0}, {0, 0, -60}));
  stack.push(pikocnc::rotation({0, 0, 0}, Plane::XY, 10));
  EXPECT_TRUE(near(stack.composite() * Vector3d(10, 0, 0), {9.848077530122081, 0, -58.263518223330699}));
  stack.pop();
  EXPECT_TRUE(near(stack.composite() * Vector3d(10, 0, 0), {10, 0, -60}));
  stack.clear();
  EXPECT_TRUE(near(stack.composite() * Vector3d(10, 0, 0), {10, 0, 0}));
}

}  // namespace
