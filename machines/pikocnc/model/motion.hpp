// What the interpreter produces before it becomes stream commands: moves in the program frame and
// the frame (transform stack + program offset) that maps them to work coordinates.
#pragma once

#include <Eigen/Dense>
#include <cstddef>

#include "machines/pikocnc/model/geometry.hpp"
#include "machines/pikocnc/model/transforms.hpp"

namespace pikocnc {

// p_base = Off + M(p_prog) for X Y Z; A and B only take the offset (section 4.1).
struct Frame {
  Transform m = Transform::Identity();
  bool identity = true;
  Eigen::Vector3d off = Eigen::Vector3d::Zero();
  double off_a = 0.0, off_b = 0.0;

  Eigen::Vector3d to_work(const Eigen::Vector3d& p) const { return identity ? Eigen::Vector3d(p + off) : Eigen::Vector3d(off + m * p); }
};

enum class MoveKind : unsigned char { Rapid, Feed, Arc, Thread };

struct Move {
  MoveKind kind = MoveKind::Rapid;
  Eigen::Vector3d from = Eigen::Vector3d::Zero();  // program frame, or work frame when `in_work`
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  double a = 0.0, b = 0.0;                         // work A, B at the end
  // arcs: centre (its normal coordinate is the start's), plane, direction and degrees swept, in
  // (0, 360], as the stream's arcs have them (arc_of)
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Plane plane = Plane::XY;
  Direction direction = Direction::CW;
  double sweep = 0.0;
  double feed = 0.0;
  double pitch = 0.0;          // Thread
  bool in_work = false;        // machine moves (G53, G28, G30): already in work coordinates
  bool protected_move = false; // G65 P9810
  bool plane_words = false;    // a rapid that writes an axis of the compensation plane
  bool compensated = false;    // geometry moved by G41/G42
  Eigen::Vector3d programmed = Eigen::Vector3d::Zero();  // compensated: the programmed end point
};

// An arc move as the stream's arc from `from` to `to`: its radius is the start's distance from the
// centre, its sweep the move's (which decides a full circle, not the points).
inline toolpath::geometry::Arc arc_of(const Move& m) {
  return {.start = m.from,
          .end = m.to,
          .centre = m.centre,
          .radius = (in_plane(m.from, m.plane) - in_plane(m.centre, m.plane)).norm(),
          .sweep = m.sweep,
          .plane = m.plane,
          .direction = m.direction};
}

}  // namespace pikocnc
