#include "machines/ncmodel/motion_out.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "machines/ncmodel/block_text.hpp"
#include "toolpath/short_text.hpp"
#include "toolpath/value.hpp"

namespace ncmodel {

namespace geo = toolpath::geometry;
using toolpath::Command;
using toolpath::Value;
using K = toolpath::ParamKey;

double clean(double v) {
  const double r = round_half_away(v * 1e9) / 1e9;
  return r == 0 ? 0.0 : r;
}

void MotionOut::finish_command() {
  if (current_) current_->parameters.resize(fill_);
  current_ = nullptr;
}

void MotionOut::add(std::string_view name) {
  finish_command();
  if (tail_ == queue_.size()) queue_.emplace_back().keep_name_on_heap();  // take() swaps it with the consumer's
  Command& c = queue_[tail_++];
  shelf_.rename(c, name);
  c.index = made_++;  // numbered in stream order, from 0
  c.depth = 1;
  c.line = 0;
  c.trace.clear();
  current_ = &c;
  fill_ = 0;
}

// As Command::set on a cleared command: the parameters of a command are all different, so
// filling slots in order gives the same parameters in the same order. Inline (every value of every
// command comes here; the callers are all in this file), the vector's growth out of line.
[[gnu::noinline]] toolpath::Parameter& MotionOut::new_slot() { return current_->parameters.emplace_back(); }

[[gnu::always_inline]] inline Value& MotionOut::slot(K key, toolpath::ValueKind kind) {
  auto& params = current_->parameters;
  // fill_ never passes the size: comparing iterators spares dividing by a Parameter's size.
  const auto at = params.begin() + static_cast<std::ptrdiff_t>(fill_);
  toolpath::Parameter& p = at != params.end() ? *at : new_slot();
  ++fill_;
  // A recycled slot mostly has the name already: that test inline, the renaming a call.
  if (p.key != key || !toolpath::same_short_text(p.name, toolpath::param_name(key))) [[unlikely]]
    p.rename(key);
  p.line = p.column = 0;
  p.value.kind = kind;
  p.value.flag = toolpath::ChangeFlag::None;
  return p.value;
}

[[gnu::always_inline]] inline void MotionOut::number(K key, double v) {
  slot(key, toolpath::ValueKind::Numeric).numeric = clean(v);
}
void MotionOut::word(K key, std::string_view w) { slot(key, toolpath::ValueKind::Enum).text.assign(w); }

bool MotionOut::take(Command& out) {
  finish_command();
  if (head_ == tail_) return false;
  swap(out, queue_[head_]);
  if (++head_ == tail_) head_ = tail_ = 0;
  return true;
}

void MotionOut::position_words(const Eigen::Vector3d& p) {
  number(K::xpos, p.x());
  number(K::ypos, p.y());
  number(K::zpos, p.z());
  static constexpr std::array<K, 3> kRotary = {K::apos, K::bpos, K::cpos};
  for (std::size_t i = 0; i < 3; ++i)
    if (rotary_[i]) number(kRotary[i], *rotary_[i]);
}

void MotionOut::rapid(const Eigen::Vector3d& to) {
  add("@rapid_move");
  position_words(to);
  position_ = to;
}

void MotionOut::line(const Eigen::Vector3d& to, double feed) {
  add("@line");
  position_words(to);
  number(K::feed, feed);
  position_ = to;
}

void MotionOut::arc(const Eigen::Vector3d& to, const Eigen::Vector3d& centre, geo::Plane plane, bool ccw, double feed) {
  const geo::Arc a = geo::make_arc(position_, to, centre, plane, ccw ? geo::Direction::CCW : geo::Direction::CW, 360.0);
  add("@arc");
  position_words(to);
  number(K::feed, feed);
  Eigen::Vector3d centre3 = centre;
  centre3[geo::axes(plane).normal] = position_[geo::axes(plane).normal];
  number(K::xcenter, centre3.x());
  number(K::ycenter, centre3.y());
  number(K::zcenter, centre3.z());
  number(K::radius, a.radius);
  number(K::arc_size, a.sweep);
  word(K::arc_direction, ccw ? "CCW" : "CW");
  word(K::arc_plane, geo::plane_name(plane));
  position_ = to;
}

void MotionOut::dwell(double seconds) {
  add("@delay");
  number(K::delay_period, seconds);
}

void MotionOut::spindle(int m, double speed) {
  speed_ = speed;
  if (m == 5) {
    if (spindle_ != 5) add("@stop_tool");
  } else {
    add("@start_tool");
    number(K::spin, speed);
    word(K::spin_direction, m == 4 ? "CCW" : "CW");
  }
  spindle_ = m;
}

void MotionOut::speed(double speed) {
  speed_ = speed;
  if (spindle_ != 5) {
    add("@m_feed_spin");
    number(K::spin, speed);
  }
}

void MotionOut::tool_change(std::optional<double> number_, const std::optional<std::string>& name) {
  if (spindle_ != 5) {  // a tool change stops the spindle on every control (M6 runs M5 first)
    add("@stop_tool");
    spindle_ = 5;
  }
  add("@change_tool");
  slot(K::tool_number, toolpath::ValueKind::Integer).integer = number_ ? static_cast<std::int64_t>(*number_) : 0;
  if (name) slot(K::tool_name, toolpath::ValueKind::String).text.assign(*name);
}

void MotionOut::message(std::string text) {
  add("@message");
  slot(K::message, toolpath::ValueKind::String).text.assign(text);
}

void MotionOut::compensation(std::string_view side) {
  add("@compensation");
  word(K::side, side);
}

void MotionOut::machine_move(const std::array<std::optional<double>, 3>& axes,
                             const std::array<std::optional<double>, 3>& rotary) {
  add("@machine_move");
  static constexpr std::array<K, 3> kNames = {K::xpos, K::ypos, K::zpos}, kRotary = {K::apos, K::bpos, K::cpos};
  for (std::size_t i = 0; i < 3; ++i)
    if (axes[i]) number(kNames[i], *axes[i]);
  for (std::size_t i = 0; i < 3; ++i)
    if (rotary[i]) {
      rotary_[i] = *rotary[i];
      number(kRotary[i], *rotary[i]);
    }
}

void MotionOut::end_program() {
  add("@end_program");
  position_words(position_);
}

void MotionOut::hole(const Hole& h) {
  auto to_z = [&](bool fast, double z, double feed) {
    Eigen::Vector3d p = position_;
    p.z() = z;
    if (fast) rapid(p);
    else line(p, feed);
  };
  const double out_feed = h.feed_out > 0 ? h.feed_out : h.feed;
  to_z(true, h.approach, 0);
  switch (h.kind) {
    case Hole::Kind::Drill:
      to_z(false, h.depth, h.feed);
      if (h.dwell > 0) dwell(h.dwell);
      break;
    case Hole::Kind::Peck:
    case Hole::Kind::ChipBreak: {
      double step = std::max(h.first_step, 1e-3);
      double depth = h.approach, previous = h.approach;
      for (int n = 0;; ++n) {
        if (n > 100000) throw std::runtime_error("the cycle makes more than 100000 steps");
        const double next = std::max(depth - step, h.depth);
        if (n > 0 && h.kind == Hole::Kind::Peck) to_z(true, previous, 0);
        to_z(false, next, h.feed);
        depth = next;
        if (depth <= h.depth + 1e-9) break;
        previous = depth;
        to_z(true, h.kind == Hole::Kind::Peck ? h.approach : depth + h.chip_lift, 0);
        if (h.step > 0 && n == 0) step = h.step;
        if (h.step_reduction > 0) step = std::max(step - h.step_reduction, h.step_reduction);
      }
      if (h.dwell > 0) dwell(h.dwell);
      break;
    }
    case Hole::Kind::Tap:
    case Hole::Kind::Bore:
      to_z(false, h.depth, h.feed);
      if (h.dwell > 0) dwell(h.dwell);
      to_z(false, h.approach, out_feed);
      break;
    case Hole::Kind::BoreSpindleStop: {
      to_z(false, h.depth, h.feed);
      if (h.dwell > 0) dwell(h.dwell);
      const int was = spindle_;
      spindle(5, speed_);
      to_z(true, h.retract, 0);
      if (was != 5) spindle(was, speed_);
      return;
    }
  }
  to_z(true, h.retract, 0);
}

}  // namespace ncmodel
