// The working planes and arc directions under the model's names (they are the stream's), and how
// the model rounds printed values and reads integer words.
#pragma once

#include <Eigen/Dense>

#include <cmath>

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

using toolpath::geometry::in_plane;

// Rounds to 1e-9 (a nanometre) and turns -0 into 0, so printed values are short and stable.
// Inline: every number of every command goes through it.
inline double clean(double v) {
  const double scaled = v * 1e9;
  double rounded;
  if (std::abs(scaled) < 1e15) {
    constexpr double kShift = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
    rounded = (scaled + kShift) - kShift;
  } else {
    rounded = std::round(scaled);
  }
  if (rounded == scaled) return v == 0.0 ? 0.0 : v;  // already short: keep it as it is
  const double r = rounded / 1e9;
  return r == 0.0 ? 0.0 : r;
}

// A word's value as an integer (a code, a count, a table number): truncated, and saturated so that
// a huge value stays huge and is rejected by the caller's range check (a plain cast is undefined).
inline int int_word(double v) {
  if (!(v == v)) return 0;
  if (v >= 2147483647.0) return 2147483647;
  if (v <= -2147483648.0) return -2147483647 - 1;
  return static_cast<int>(v);
}

}  // namespace pikocnc
