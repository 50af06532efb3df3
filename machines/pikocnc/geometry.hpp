// Arc geometry in a working plane, with Eigen: centre from R, sweep, angles.
#pragma once

#include <Eigen/Dense>
#include <optional>

#include "toolpath/geometry.hpp"

namespace pikocnc {

// G17, G18, G19: the planes, their in-plane axes (first, second) and normal (helix) axis, and the
// arc directions are the stream's (toolpath/geometry.hpp), so the model and the filters cannot
// disagree on a plane.
using Plane = toolpath::geometry::Plane;
using PlaneAxes = toolpath::geometry::PlaneAxes;
using Direction = toolpath::geometry::Direction;

inline PlaneAxes axes_of(Plane p) { return toolpath::geometry::axes(p); }
using toolpath::geometry::plane_name;

constexpr double kPi = 3.14159265358979323846;

using toolpath::geometry::in_plane;

// Swept angle (radians, > 0) from `start` to `end` around `centre`, turning counter-clockwise when
// `ccw`. Equal start and end angles give a full circle.
double sweep_angle(const Eigen::Vector2d& start, const Eigen::Vector2d& end, const Eigen::Vector2d& centre, bool ccw);

// Angle of `p` around `centre` in degrees, in [0, 360).
double angle_degrees(const Eigen::Vector2d& p, const Eigen::Vector2d& centre);

// Rounds to 1e-9 (a nanometre) and turns -0 into 0, so printed values are short and stable.
double clean(double v);

// A word's value as an integer (a code, a count, a table number): truncated, and saturated so that
// a huge value stays huge and is rejected by the caller's range check (a plain cast is undefined).
inline int int_word(double v) {
  if (!(v == v)) return 0;
  if (v >= 2147483647.0) return 2147483647;
  if (v <= -2147483648.0) return -2147483647 - 1;
  return static_cast<int>(v);
}

}  // namespace pikocnc
