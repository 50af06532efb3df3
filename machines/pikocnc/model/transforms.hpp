// The transformation stack of G51, G68, G68.2 (section 10): T1(T2(...Tn(p))), newest innermost.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "machines/pikocnc/model/geometry.hpp"

namespace pikocnc {

using Transform = Eigen::Affine3d;

// G51: c + S (p - c).
Transform scaling(const Eigen::Vector3d& centre, const Eigen::Vector3d& factors);
// G68: c + R_axis(angle) (p - c), axis = the normal of `plane`, angle in degrees.
Transform rotation(const Eigen::Vector3d& centre, Plane plane, double degrees);
// G68.2: shift + rotations about the fixed axes. mode 0: Rz(K) Rx(J) Rz(I); mode 1: in the order of
// `order` (123, 132, 213, 231, 312, 321), I about X, J about Y, K about Z. nullopt for a bad P or Q.
std::optional<Transform> tilted_plane(int mode, int order, const Eigen::Vector3d& ijk_degrees,
                                      const Eigen::Vector3d& shift);

class TransformStack {
public:
  void push(const Transform& t);
  bool pop();  // false when empty
  void clear();
  bool empty() const { return stack_.empty(); }
  std::size_t depth() const { return stack_.size(); }
  const Transform& composite() const { return composite_; }

private:
  std::vector<Transform> stack_;
  Transform composite_ = Transform::Identity();
};

}  // namespace pikocnc
