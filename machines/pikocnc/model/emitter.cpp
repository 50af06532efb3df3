#include "machines/pikocnc/model/emitter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "toolpath/error.hpp"
#include "toolpath/short_text.hpp"

namespace pikocnc {

using toolpath::Command;
using toolpath::Value;

void Emitter::finish_command() {
  if (current_) current_->parameters.resize(fill_);
  current_ = nullptr;
}

void Emitter::add(std::string_view name) {
  finish_command();
  if (++built_ > budget_)
    throw toolpath::InputError({file_, line_, 1}, fmt::format("more than {} commands made: runaway loop or cycle stopped", budget_));
  if (muted_) {
    current_ = &scratch_;
    fill_ = 0;
    return;
  }
  if (tail_ == queue_.size()) {
    queue_.emplace_back().keep_name_on_heap();  // pop() swaps it with the consumer's command
    lines_.push_back(0);
  }
  Command& c = queue_[tail_];
  lines_[tail_] = line_;
  ++tail_;
  shelf_.rename(c, name);  // an @arc refilled from a @line takes the parameters an @arc last had
  c.depth = 1;
  c.trace.clear();
  current_ = &c;
  fill_ = 0;
  if (attach_ && !line_attached_ && line_ > 0) {
    c.trace.push_back({toolpath::TraceLine::Kind::Output, std::string(line_text_)});
    line_attached_ = true;
  }
}

bool Emitter::pop(toolpath::Command& out, std::size_t& line) {
  finish_command();
  if (empty()) return false;
  swap(out, queue_[head_]);
  out.index = next_index_++;
  line = lines_[head_];
  if (++head_ == tail_) {
    for (Hole& h : holes_) h.pos -= head_;  // holes waiting at the end move to the front too
    head_ = tail_ = 0;
  }
  return true;
}

void Emitter::reserve() {
  finish_command();
  if (muted_) return;
  const bool wants = attach_ && !line_attached_ && line_ > 0;
  holes_.push_back({tail_, line_, wants, wants ? std::string(line_text_) : std::string()});
  if (wants) line_attached_ = true;  // the hole's first command will carry the text
}

void Emitter::begin_fill() {
  finish_command();
  fill_start_ = tail_;
  saved_line_ = line_;
  saved_text_ = line_text_;
  saved_attached_ = line_attached_;
  if (muted_ || holes_.empty()) return;
  const Hole& h = holes_.front();
  line_ = h.line;
  line_text_ = h.text;
  line_attached_ = !h.wants_text;
}

void Emitter::end_fill() {
  finish_command();
  line_ = saved_line_;
  line_text_ = saved_text_;
  line_attached_ = saved_attached_;
  if (muted_ || holes_.empty()) return;
  const std::size_t pos = holes_.front().pos, added = tail_ - fill_start_;
  const auto at = static_cast<std::ptrdiff_t>(pos), mid = static_cast<std::ptrdiff_t>(fill_start_),
             end = static_cast<std::ptrdiff_t>(tail_);
  std::rotate(queue_.begin() + at, queue_.begin() + mid, queue_.begin() + end);
  std::rotate(lines_.begin() + at, lines_.begin() + mid, lines_.begin() + end);
  holes_.erase(holes_.begin());
  for (Hole& h : holes_) h.pos += added;
}

void Emitter::mute(bool on) {
  finish_command();
  muted_ = on;
}

toolpath::Parameter& Emitter::new_slot() { return current_->parameters.emplace_back(); }
void Emitter::rename(toolpath::Parameter& p, std::string_view name) { p.rename(name); }

void Emitter::positions(const Eigen::Vector3d& p, double a, double b) {
  number("xpos", p.x());
  number("ypos", p.y());
  number("zpos", p.z());
  if (with_a_) number("apos", a);
  if (with_b_) number("bpos", b);
}

void Emitter::straight(const Move& m, const Eigen::Vector3d& to, bool from_arc) {
  const bool rapid = m.kind == MoveKind::Rapid;
  add(rapid ? "@rapid_move" : m.kind == MoveKind::Thread ? "@thread_move" : "@line");
  positions(to, m.a, m.b);
  if (!rapid) number("feed", m.feed);
  if (m.kind == MoveKind::Thread) number("pitch", m.pitch);
  if (from_arc) logical("from_arc", true);
  if (m.protected_move) logical("protected", true);
}

void Emitter::move(const Move& m, const Frame& frame) {
  if (m.kind != MoveKind::Arc) {
    straight(m, m.in_work ? m.to : frame.to_work(m.to), false);
    if (m.compensated) compensation_marks(m, frame);
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
  const bool ccw = (m.direction == Direction::CCW) != (normal[k] < 0);  // a mirror turns the other way
  const Eigen::Vector3d from = frame.to_work(m.from), to = frame.to_work(m.to), centre = frame.to_work(m.centre);
  const toolpath::geometry::Arc arc{.start = from,
                                    .end = to,
                                    .centre = centre,
                                    .radius = (in_plane(from, plane) - in_plane(centre, plane)).norm(),
                                    .sweep = m.sweep,
                                    .plane = plane,
                                    .direction = ccw ? Direction::CCW : Direction::CW};
  add("@arc");
  positions(to, m.a, m.b);
  number("feed", m.feed);
  number("xcenter", centre.x());
  number("ycenter", centre.y());
  number("zcenter", centre.z());
  number("xcenter_rel", centre.x() - from.x());
  number("ycenter_rel", centre.y() - from.y());
  number("zcenter_rel", centre.z() - from.z());
  number("radius", arc.radius);
  number("start_angle", arc.start_angle());
  number("end_angle", arc.end_angle());
  number("arc_size", arc.sweep);
  word("arc_direction", ccw ? "CCW" : "CW");
  word("arc_plane", plane_name(plane));
  if (m.compensated) compensation_marks(m, frame);
}

void Emitter::compensation_marks(const Move& m, const Frame& frame) {
  logical("compensated", true);
  const Eigen::Vector3d p = frame.to_work(m.programmed);
  number("prog_xpos", p.x());
  number("prog_ypos", p.y());
  number("prog_zpos", p.z());
}

void Emitter::chords(const Move& m, const Frame& frame) {
  // The arc in the program frame, cut into equal chords that keep within the tolerance after the
  // frame stretches them: in the program frame a chord may deviate by the tolerance over the
  // stretch. At most half a turn each, so an arc smaller than the tolerance keeps its turn; a zero
  // tolerance asks for the finest chords, the nanometre the output is rounded to.
  const toolpath::geometry::Arc arc = arc_of(m);
  const double stretch = frame.identity ? 1.0 : frame.m.linear().norm();
  const double deviation = std::max(chord_tolerance_, 1e-9) / stretch;
  const int count = std::min(toolpath::geometry::chord_count(arc, 180.0, 0.0, deviation), 100000);
  Move piece = m;
  piece.kind = MoveKind::Feed;
  for (int i = 1; i <= count; ++i) {
    // i == count: the offset is the sweep, and point_at gives the end exactly
    straight(piece, frame.to_work(arc.point_at(arc.sweep * (static_cast<double>(i) / count))), true);
    if (m.compensated) compensation_marks(m, frame);
  }
}

}  // namespace pikocnc
