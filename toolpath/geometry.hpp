// Arc and plane math for the stream filters: circular and helical arcs in the three main planes,
// points along them, pieces of them, and how many chords approximate one.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "toolpath/command.hpp"

namespace toolpath::geometry {

// Arc planes with their right-handed axis order (G17 XY, G19 YZ, G18 ZX): angles are measured in
// the plane from its first axis towards its second, CCW seen from the normal's positive side.
enum class Plane : std::uint8_t { XY, YZ, ZX };
enum class Direction : std::uint8_t { CW, CCW };

struct PlaneAxes {
  int first, second, normal;  // indices into x y z
};
// Inline: the arc filter asks for every arc.
constexpr PlaneAxes axes(Plane plane) {
  switch (plane) {
    case Plane::XY: return {0, 1, 2};
    case Plane::YZ: return {1, 2, 0};
    case Plane::ZX: return {2, 0, 1};
  }
  return {0, 1, 2};
}
std::string_view plane_name(Plane plane);
std::optional<Plane> parse_plane(std::string_view name);  // case-insensitive XY / YZ / ZX

// Degrees in [0, 360).
double normalize_degrees(double degrees);

// The in-plane coordinates (first, second axis) of `p`.
Eigen::Vector2d in_plane(const Eigen::Vector3d& p, Plane plane);

// A circular arc, helical when start and end differ along the plane's normal (the normal
// coordinate then changes linearly with the angle).
struct Arc {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d end = Eigen::Vector3d::Zero();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // its normal coordinate is the start's
  double radius = 0.0;
  double sweep = 0.0;  // degrees swept, in (0, 360]
  Plane plane = Plane::XY;
  Direction direction = Direction::CCW;

  // The angle of the start and end points about the centre, in [0, 360).
  double start_angle() const;
  double end_angle() const;
  // Travel along the normal axis, end minus start.
  double rise() const;
  // Length along the (helical) path.
  double length() const;
  // The point `offset` degrees along the arc from its start (0 .. sweep); exact at both ends.
  Eigen::Vector3d point_at(double offset) const;
  // The piece between two offsets (0 <= from < to <= sweep), with its own start, end and sweep.
  Arc piece(double from, double to) const;
};

// Builds an arc from its start and end points, centre (in-plane coordinates used), direction and
// plane. The sweep is taken from the points; `sweep_hint` (the command's arc_size) decides between
// a full circle and a vanishing arc when start and end coincide in the plane.
Arc make_arc(const Eigen::Vector3d& start, const Eigen::Vector3d& end, const Eigen::Vector3d& centre,
             Plane plane, Direction direction, std::optional<double> sweep_hint);

// The centre of an R-form arc of radius |r| from `start` to `end` in `plane`: for r > 0 the arc of
// at most 180 degrees, for r < 0 the larger one. The centre's normal coordinate is the start's.
// nullopt when start and end coincide in the plane or lie more than 2|r| + `tolerance` apart
// (within the tolerance the half circle is used).
std::optional<Eigen::Vector3d> centre_from_radius(const Eigen::Vector3d& start, const Eigen::Vector3d& end,
                                                  double r, Plane plane, Direction direction, double tolerance);

// The arc an @arc command draws from `start` to `end`: its plane (`arc_plane`, XY when absent),
// direction (`arc_direction`), centre and sweep hint (`arc_size`). The centre is taken relative to
// the start (`xcenter_rel`/`ycenter_rel`, in-plane) where the command has it: a CAM system rounds
// the absolute centre and the relative one separately, and the relative one fits the start point.
// Else `xcenter`/`ycenter`. Centre lengths are multiplied by `scale` (25.4: an inch job in mm).
Arc arc_of(const Command& c, const Eigen::Vector3d& start, const Eigen::Vector3d& end, double scale = 1.0);

// Offsets (degrees from the start) where the arc crosses a multiple of 90 degrees, strictly
// inside the arc (a crossing within `tolerance` degrees of either end does not count).
std::vector<double> quadrant_crossings(const Arc& arc, double tolerance = 1e-6);

// Number of equal chords needed so that no chord spans more than `max_angle` degrees nor is
// longer than `max_chord` (either limit ignored when not positive); at least 1.
int chord_count(const Arc& arc, double max_angle, double max_chord, double max_deviation = 0.0);

}  // namespace toolpath::geometry
