#include "machines/pikocnc/model/offset.hpp"

#include <cmath>
#include <numbers>

namespace pikocnc {
namespace {

Eigen::Vector2d left_of(const Eigen::Vector2d& d) { return {-d.y(), d.x()}; }

// Tolerance for "the carriers touch": a tangent line or circle meets in one point.
constexpr double kTouch = 1e-9;

constexpr double kDegree = std::numbers::pi / 180.0;

}  // namespace

double OffsetElement::param(const Eigen::Vector2d& p, double hint) const {
  if (!arc) return (p - start).dot(dir);
  const Eigen::Vector2d s = start - centre, q = p - centre;
  double a = std::atan2(cross2(s, q), s.dot(q)) / kDegree;  // signed angle from start, counter-clockwise
  if (!ccw) a = -a;
  while (a - hint > 180.0) a -= 360.0;
  while (hint - a > 180.0) a += 360.0;
  return a;
}

double OffsetElement::distance(double dt) const { return arc ? dt * kDegree * radius : dt; }

Eigen::Vector2d OffsetElement::point(double t) const {
  if (!arc) return start + t * dir;
  const Eigen::Vector2d s = start - centre;
  const double a = (ccw ? t : -t) * kDegree;
  const double c = std::cos(a), si = std::sin(a);
  return centre + Eigen::Vector2d(c * s.x() - si * s.y(), si * s.x() + c * s.y());
}

Eigen::Vector2d OffsetElement::start_tangent() const {
  if (!arc) return dir;
  const Eigen::Vector2d l = left_of((start - centre).normalized());
  return ccw ? l : Eigen::Vector2d(-l);
}

Eigen::Vector2d OffsetElement::end_tangent() const {
  if (!arc) return dir;
  const Eigen::Vector2d l = left_of((end - centre).normalized());
  return ccw ? l : Eigen::Vector2d(-l);
}

OffsetElement offset_line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double offset) {
  OffsetElement e;
  e.length = (b - a).norm();
  e.dir = (b - a) / e.length;
  const Eigen::Vector2d shift = offset * left_of(e.dir);
  e.start = a + shift;
  e.end = b + shift;
  return e;
}

OffsetElement offset_arc(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& centre,
                         bool ccw, double sweep, double offset) {
  OffsetElement e;
  e.arc = true;
  e.centre = centre;
  e.ccw = ccw;
  e.sweep = sweep;
  const double r = (a - centre).norm();
  e.radius = r - (ccw ? offset : -offset);
  // The end keeps the programmed end's angle even when the programmed end radius differs slightly.
  const double k = e.radius / r;
  e.start = centre + (a - centre) * k;
  const Eigen::Vector2d be = b - centre;
  const double rb = be.norm();
  e.end = rb > 0 ? Eigen::Vector2d(centre + be * (e.radius / rb)) : e.start;
  return e;
}

Crossings intersect(const OffsetElement& a, const OffsetElement& b) {
  Crossings out;
  if (!a.arc && !b.arc) {
    const double den = cross2(a.dir, b.dir);
    if (std::abs(den) < 1e-12) return out;  // parallel
    const double t = cross2(b.start - a.start, b.dir) / den;
    out.point[0] = a.start + t * a.dir;
    out.count = 1;
    return out;
  }
  if (a.arc != b.arc) {
    const OffsetElement& line = a.arc ? b : a;
    const OffsetElement& circle = a.arc ? a : b;
    // foot of the perpendicular from the centre, then +- along the line
    const double t = (circle.centre - line.start).dot(line.dir);
    const Eigen::Vector2d foot = line.start + t * line.dir;
    const double d = (circle.centre - foot).norm();
    const double r = circle.radius;
    if (d > r + kTouch) return out;
    const double h = d >= r ? 0.0 : std::sqrt(r * r - d * d);
    out.point[0] = foot - h * line.dir;
    out.point[1] = foot + h * line.dir;
    out.count = h > 0 ? 2 : 1;
    return out;
  }
  const Eigen::Vector2d delta = b.centre - a.centre;
  const double d = delta.norm();
  if (d < 1e-12) return out;  // concentric
  const double ra = a.radius, rb = b.radius;
  if (d > ra + rb + kTouch || d < std::abs(ra - rb) - kTouch) return out;
  const double x = (d * d + ra * ra - rb * rb) / (2 * d);
  const double h2 = ra * ra - x * x;
  const double h = h2 > 0 ? std::sqrt(h2) : 0.0;
  const Eigen::Vector2d u = delta / d;
  const Eigen::Vector2d base = a.centre + x * u;
  out.point[0] = base - h * left_of(u);
  out.point[1] = base + h * left_of(u);
  out.count = h > 0 ? 2 : 1;
  return out;
}

}  // namespace pikocnc
