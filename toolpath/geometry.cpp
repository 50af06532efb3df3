#include "toolpath/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "toolpath/value.hpp"

namespace toolpath::geometry {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// cos and sin of an angle in degrees, exact at multiples of 90 (no 6e-17 residue at quadrant cuts).
Eigen::Vector2d unit(double degrees) {
  double quarter = degrees / 90.0;
  double k = std::round(quarter);
  if (std::abs(quarter - k) < 1e-12) {
    switch (static_cast<int>(((static_cast<long long>(k) % 4) + 4) % 4)) {
      case 0: return {1, 0};
      case 1: return {0, 1};
      case 2: return {-1, 0};
      default: return {0, -1};
    }
  }
  return {std::cos(degrees * kDegree), std::sin(degrees * kDegree)};
}

double angle_about(const Eigen::Vector3d& p, const Eigen::Vector3d& c, PlaneAxes a) {
  return normalize_degrees(std::atan2(p[a.second] - c[a.second], p[a.first] - c[a.first]) / kDegree);
}

}  // namespace

std::string_view plane_name(Plane plane) {
  switch (plane) {
    case Plane::XY: return "XY";
    case Plane::YZ: return "YZ";
    case Plane::ZX: return "ZX";
  }
  return "?";
}

std::optional<Plane> parse_plane(std::string_view name) {
  for (Plane p : {Plane::XY, Plane::YZ, Plane::ZX})
    if (iequals(name, plane_name(p))) return p;
  return std::nullopt;
}

double normalize_degrees(double degrees) {
  // fmod gives a value below 360 in magnitude back as it is (it is exact): no call for the angles
  // atan2 gives and their differences.
  double r = std::abs(degrees) < 360.0 ? degrees : std::fmod(degrees, 360.0);
  if (r < 0) r += 360.0;
  return r >= 360.0 ? 0.0 : r;
}

Eigen::Vector2d in_plane(const Eigen::Vector3d& p, Plane plane) {
  const PlaneAxes a = axes(plane);
  return {p[a.first], p[a.second]};
}

double Arc::start_angle() const { return angle_about(start, centre, axes(plane)); }
double Arc::end_angle() const { return angle_about(end, centre, axes(plane)); }
double Arc::rise() const { return end[axes(plane).normal] - start[axes(plane).normal]; }

double Arc::length() const { return std::hypot(radius * sweep * kDegree, rise()); }

Eigen::Vector3d Arc::point_at(double offset) const {
  if (offset <= 0.0) return start;
  if (offset >= sweep) return end;
  const PlaneAxes a = axes(plane);
  const double angle = start_angle() + (direction == Direction::CCW ? offset : -offset);
  const Eigen::Vector2d u = unit(angle);
  Eigen::Vector3d p;
  p[a.first] = centre[a.first] + radius * u.x();
  p[a.second] = centre[a.second] + radius * u.y();
  p[a.normal] = start[a.normal] + rise() * (offset / sweep);
  return p;
}

Arc Arc::piece(double from, double to) const {
  Arc p = *this;
  p.start = point_at(from);
  p.end = point_at(to);
  p.sweep = to - from;
  p.centre[axes(plane).normal] = p.start[axes(plane).normal];
  return p;
}

Arc make_arc(const Eigen::Vector3d& start, const Eigen::Vector3d& end, const Eigen::Vector3d& centre,
             Plane plane, Direction direction, std::optional<double> sweep_hint) {
  const PlaneAxes a = axes(plane);
  Arc arc;
  arc.start = start;
  arc.end = end;
  arc.centre = centre;
  arc.centre[a.normal] = start[a.normal];
  arc.plane = plane;
  arc.direction = direction;
  arc.radius = std::hypot(start[a.first] - centre[a.first], start[a.second] - centre[a.second]);
  const double from = angle_about(start, centre, a);
  const double to = angle_about(end, centre, a);
  double sweep = normalize_degrees(direction == Direction::CCW ? to - from : from - to);
  // Coinciding start and end: a full circle unless the command says the arc is tiny.
  if (sweep < 1e-9 && !(sweep_hint && *sweep_hint < 180.0)) sweep = 360.0;
  arc.sweep = sweep;
  return arc;
}

std::optional<Eigen::Vector3d> centre_from_radius(const Eigen::Vector3d& start, const Eigen::Vector3d& end,
                                                  double r, Plane plane, Direction direction, double tolerance) {
  const Eigen::Vector2d s = in_plane(start, plane), e = in_plane(end, plane);
  const Eigen::Vector2d chord = e - s;
  const double d = chord.norm();
  const double ra = std::abs(r);
  if (d < 1e-12 || d > 2 * ra + tolerance) return std::nullopt;
  const double h2 = ra * ra - d * d / 4;
  const double h = h2 > 0 ? std::sqrt(h2) : 0.0;
  const Eigen::Vector2d left(-chord.y() / d, chord.x() / d);
  // The centre of the minor arc lies left of the chord for a counter-clockwise move.
  const double side = (direction == Direction::CCW ? 1.0 : -1.0) * (r >= 0 ? 1.0 : -1.0);
  const Eigen::Vector2d c = (s + e) / 2 + side * h * left;
  const PlaneAxes a = axes(plane);
  Eigen::Vector3d centre = start;
  centre[a.first] = c.x();
  centre[a.second] = c.y();
  return centre;
}

std::vector<double> quadrant_crossings(const Arc& arc, double tolerance) {
  std::vector<double> out;
  const double s = arc.start_angle();
  double first = arc.direction == Direction::CCW ? (std::floor(s / 90.0) + 1.0) * 90.0 - s
                                                 : s - (std::ceil(s / 90.0) - 1.0) * 90.0;
  for (double offset = first; offset < arc.sweep - tolerance; offset += 90.0)
    if (offset > tolerance) out.push_back(offset);
  return out;
}

int chord_count(const Arc& arc, double max_angle, double max_chord, double max_deviation) {
  double n = 1.0;
  if (max_angle > 0) n = std::max(n, std::ceil(arc.sweep / max_angle - 1e-9));
  if (max_chord > 0 && max_chord < 2.0 * arc.radius) {
    const double theta = 2.0 * std::asin(max_chord / (2.0 * arc.radius)) / kDegree;
    n = std::max(n, std::ceil(arc.sweep / theta - 1e-9));
  }
  if (max_deviation > 0 && max_deviation < arc.radius) {
    // a chord spanning theta lies at most r (1 - cos(theta / 2)) inside the arc
    const double theta = 2.0 * std::acos(1.0 - max_deviation / arc.radius) / kDegree;
    n = std::max(n, std::ceil(arc.sweep / theta - 1e-9));
  }
  return static_cast<int>(std::min(n, 1e6));  // a runaway count (radius 1e300) stays bounded
}

Arc arc_of(const Command& c, const Eigen::Vector3d& start, const Eigen::Vector3d& end, double scale) {
  const Value* plane_word = c.find("arc_plane");
  const Plane plane = (plane_word ? parse_plane(plane_word->text) : std::nullopt).value_or(Plane::XY);
  const PlaneAxes ax = axes(plane);
  Eigen::Vector3d centre = start;
  if (auto xr = c.number("xcenter_rel"), yr = c.number("ycenter_rel"); xr && yr) {
    centre[ax.first] += *xr * scale;
    centre[ax.second] += *yr * scale;
  } else {
    centre[ax.first] = c.number("xcenter").value_or(0.0) * scale;
    centre[ax.second] = c.number("ycenter").value_or(0.0) * scale;
  }
  const Value* direction = c.find("arc_direction");
  return make_arc(start, end, centre, plane, direction && iequals(direction->text, "CW") ? Direction::CW : Direction::CCW,
                  c.number("arc_size"));
}

}  // namespace toolpath::geometry
