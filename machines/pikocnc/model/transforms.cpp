#include "machines/pikocnc/model/transforms.hpp"

#include <cmath>
#include <numbers>

namespace pikocnc {
namespace {

Eigen::Matrix3d about(int axis, double degrees) {
  const Eigen::Vector3d unit = Eigen::Vector3d::Unit(axis);
  return Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, unit).toRotationMatrix();
}

}  // namespace

Transform scaling(const Eigen::Vector3d& centre, const Eigen::Vector3d& factors) {
  Transform t = Transform::Identity();
  t.linear() = factors.asDiagonal();
  t.translation() = centre - t.linear() * centre;
  return t;
}

Transform rotation(const Eigen::Vector3d& centre, Plane plane, double degrees) {
  Transform t = Transform::Identity();
  t.linear() = about(axes_of(plane).normal, degrees);
  t.translation() = centre - t.linear() * centre;
  return t;
}

std::optional<Transform> tilted_plane(int mode, int order, const Eigen::Vector3d& ijk, const Eigen::Vector3d& shift) {
  Eigen::Matrix3d r;
  if (mode == 0) {
    r = about(2, ijk.z()) * about(0, ijk.y()) * about(2, ijk.x());
  } else if (mode == 1) {
    const int digits[3] = {order / 100, order / 10 % 10, order % 10};
    bool seen[4] = {false, false, false, false};
    for (int d : digits) {
      if (d < 1 || d > 3 || seen[d]) return std::nullopt;
      seen[d] = true;
    }
    if (order < 100 || order > 999) return std::nullopt;
    r = Eigen::Matrix3d::Identity();
    for (int d : digits) r = about(d - 1, ijk[d - 1]) * r;  // each later rotation applies after
  } else {
    return std::nullopt;
  }
  Transform t = Transform::Identity();
  t.linear() = r;
  t.translation() = shift;
  return t;
}

void TransformStack::push(const Transform& t) {
  stack_.push_back(t);
  composite_ = composite_ * t;
}

bool TransformStack::pop() {
  if (stack_.empty()) return false;
  stack_.pop_back();
  composite_ = Transform::Identity();
  for (const auto& t : stack_) composite_ = composite_ * t;
  return true;
}

void TransformStack::clear() {
  stack_.clear();
  composite_ = Transform::Identity();
}

}  // namespace pikocnc
