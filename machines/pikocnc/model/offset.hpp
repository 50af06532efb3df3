// Plane geometry of cutter radius compensation (section 8.3): lines and arcs offset to one side,
// positions along them, and the intersections of their carriers (line-line, line-circle,
// circle-circle). Everything is 2-D in the compensation plane's (first, second) axes.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>

namespace pikocnc {

// One offset element. `offset` is signed: > 0 to the left of the direction of travel (G41),
// < 0 to the right (G42).
struct OffsetElement {
  bool arc = false;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  // offset start and end, untrimmed
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
  // line
  Eigen::Vector2d dir = Eigen::Vector2d::UnitX();   // unit direction
  double length = 0.0;
  // arc
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.0;  // after offsetting; <= 0 when the tool does not fit inside the arc
  bool ccw = false;
  double sweep = 0.0;   // degrees, > 0

  // Position along the element: distance from `start` (line) or degrees swept from `start` (arc).
  // The end is at end_param().
  double end_param() const { return arc ? sweep : length; }
  // A parameter difference as a distance along the element.
  double distance(double dt) const;
  // The parameter of `p` (a point on the carrier); for arcs the value nearest to `hint` among the
  // turns, so a point just before the start reads as a small negative angle.
  double param(const Eigen::Vector2d& p, double hint) const;
  Eigen::Vector2d point(double t) const;
  // Unit tangent in the direction of travel at the start and at the end.
  Eigen::Vector2d start_tangent() const;
  Eigen::Vector2d end_tangent() const;
};

// The programmed line a -> b offset by `offset` (see OffsetElement); a and b must differ.
OffsetElement offset_line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double offset);
// The programmed arc a -> b around `centre` (sweep in degrees) offset by `offset`; the offset
// radius is R - offset for a counter-clockwise arc and R + offset for a clockwise one.
OffsetElement offset_arc(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& centre,
                         bool ccw, double sweep, double offset);

// The common points of the carriers of two elements (infinite lines, full circles): 0, 1 or 2.
struct Crossings {
  std::array<Eigen::Vector2d, 2> point;
  std::size_t count = 0;
};
Crossings intersect(const OffsetElement& a, const OffsetElement& b);

// z of the 2-D cross product: > 0 when `b` turns left of `a`.
inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace pikocnc
