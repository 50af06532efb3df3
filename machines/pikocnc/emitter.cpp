#include "machines/pikocnc/emitter.hpp"

#include <cmath>
#include <string>
#include <utility>

namespace pikocnc {

using toolpath::Command;
using toolpath::Value;

toolpath::Command& Emitter::add(std::string_view name) {
  if (tail_ == queue_.size()) {
    queue_.emplace_back();
    lines_.push_back(0);
  }
  Command& c = queue_[tail_];
  lines_[tail_] = line_;
  ++tail_;
  c.name.assign(name);
  c.index = next_index_++;
  c.depth = 1;
  c.parameters.clear();
  c.trace.clear();
  if (attach_ && !line_attached_ && line_ > 0) {
    c.trace.push_back({toolpath::TraceLine::Kind::Output, std::string(line_text_)});
    line_attached_ = true;
  }
  return c;
}

bool Emitter::pop(toolpath::Command& out, std::size_t& line) {
  if (head_ == tail_) return false;
  std::swap(out, queue_[head_]);
  line = lines_[head_];
  if (++head_ == tail_) head_ = tail_ = 0;
  return true;
}

void Emitter::number(Command& c, std::string_view name, double v) {
  c.parameters.push_back({std::string(name), Value::make_numeric(clean(v))});
}
void Emitter::integer(Command& c, std::string_view name, long long v) {
  c.parameters.push_back({std::string(name), Value::make_integer(v)});
}
void Emitter::logical(Command& c, std::string_view name, bool v) {
  c.parameters.push_back({std::string(name), Value::make_logical(v)});
}
void Emitter::text(Command& c, std::string_view name, std::string_view v) {
  c.parameters.push_back({std::string(name), Value::make_string(std::string(v))});
}
void Emitter::word(Command& c, std::string_view name, std::string_view v) {
  c.parameters.push_back({std::string(name), Value::make_enum(std::string(v))});
}

void Emitter::positions(Command& c, const Eigen::Vector3d& p, double a, double b) {
  number(c, "xpos", p.x());
  number(c, "ypos", p.y());
  number(c, "zpos", p.z());
  if (with_a_) number(c, "apos", a);
  if (with_b_) number(c, "bpos", b);
}

void Emitter::straight(const Move& m, const Eigen::Vector3d& to, bool from_arc) {
  const bool rapid = m.kind == MoveKind::Rapid;
  Command& c = add(rapid ? "@rapid_move" : m.kind == MoveKind::Thread ? "@thread_move" : "@line");
  positions(c, to, m.a, m.b);
  if (!rapid) number(c, "feed", m.feed);
  if (m.kind == MoveKind::Thread) number(c, "pitch", m.pitch);
  if (from_arc) logical(c, "from_arc", true);
  if (m.protected_move) logical(c, "protected", true);
}

void Emitter::move(const Move& m, const Frame& frame) {
  if (m.kind != MoveKind::Arc) {
    straight(m, m.in_work ? m.to : frame.to_work(m.to), false);
    return;
  }
  // An arc stays an arc when the frame keeps its plane a circle in one of the main planes.
  const PlaneAxes ax = axes_of(m.plane);
  const Eigen::Matrix3d a = frame.identity ? Eigen::Matrix3d::Identity() : Eigen::Matrix3d(frame.m.linear());
  const Eigen::Vector3d u = a.col(ax.first), v = a.col(ax.second), n = a.col(ax.normal);
  const double scale = u.norm();
  const Eigen::Vector3d normal = u.cross(v);
  const double eps = 1e-9;
  int k = -1;
  for (int i = 0; i < 3; ++i)
    if (std::abs(std::abs(normal[i]) - scale * scale) <= eps * (1 + scale * scale)) k = i;
  const double helix = (m.to - m.from)[ax.normal];
  const bool circle = std::abs(v.norm() - scale) <= eps * (1 + scale) && std::abs(u.dot(v)) <= eps * (1 + scale * scale);
  const bool helix_ok = std::abs(helix) < 1e-12 || (k >= 0 && n.cross(Eigen::Vector3d::Unit(k)).norm() <= eps * (1 + n.norm()));
  if (!circle || k < 0 || !helix_ok) {
    chords(m, frame);
    return;
  }
  const Plane plane = k == 2 ? Plane::XY : k == 1 ? Plane::ZX : Plane::YZ;
  const bool ccw = m.ccw != (normal[k] < 0);
  const Eigen::Vector3d from = frame.to_work(m.from), to = frame.to_work(m.to), centre = frame.to_work(m.centre);
  const Eigen::Vector2d s2 = in_plane(from, plane), e2 = in_plane(to, plane), c2 = in_plane(centre, plane);
  Command& c = add("@arc");
  positions(c, to, m.a, m.b);
  number(c, "feed", m.feed);
  number(c, "xcenter", centre.x());
  number(c, "ycenter", centre.y());
  number(c, "zcenter", centre.z());
  number(c, "xcenter_rel", centre.x() - from.x());
  number(c, "ycenter_rel", centre.y() - from.y());
  number(c, "zcenter_rel", centre.z() - from.z());
  number(c, "radius", (s2 - c2).norm());
  number(c, "start_angle", angle_degrees(s2, c2));
  number(c, "end_angle", angle_degrees(e2, c2));
  number(c, "arc_size", m.sweep * 180.0 / kPi);
  word(c, "arc_direction", ccw ? "CCW" : "CW");
  word(c, "arc_plane", plane_name(plane));
  if (m.compensated) logical(c, "compensated", true);
}

void Emitter::chords(const Move& m, const Frame& frame) {
  // The arc in the program frame, cut into chords short enough for the tolerance after scaling.
  const PlaneAxes ax = axes_of(m.plane);
  const Eigen::Vector2d s2 = in_plane(m.from, m.plane), c2 = in_plane(m.centre, m.plane);
  const double r = (s2 - c2).norm();
  const double stretch = frame.identity ? 1.0 : frame.m.linear().norm();
  const double rr = std::max(r * stretch, 1e-9);
  const double tol = std::min(chord_tolerance_, rr);
  const double step = 2 * std::acos(1 - tol / rr);
  const int n = std::max(1, static_cast<int>(std::ceil(m.sweep / std::max(step, 1e-6))));
  const int count = std::min(n, 100000);
  const double a0 = std::atan2(s2.y() - c2.y(), s2.x() - c2.x());
  const double dir = m.ccw ? 1.0 : -1.0;
  Move piece = m;
  piece.kind = MoveKind::Feed;
  for (int i = 1; i <= count; ++i) {
    Eigen::Vector3d p;
    if (i == count) {
      p = m.to;
    } else {
      const double t = static_cast<double>(i) / count;
      const double ang = a0 + dir * m.sweep * t;
      p = m.from;
      p[ax.first] = c2.x() + r * std::cos(ang);
      p[ax.second] = c2.y() + r * std::sin(ang);
      p[ax.normal] = m.from[ax.normal] + (m.to[ax.normal] - m.from[ax.normal]) * t;
    }
    straight(piece, frame.to_work(p), true);
  }
}

}  // namespace pikocnc
