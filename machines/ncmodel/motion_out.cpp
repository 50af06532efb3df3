#include "machines/ncmodel/motion_out.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "toolpath/value.hpp"

namespace ncmodel {

namespace geo = toolpath::geometry;
using toolpath::Command;
using toolpath::Value;
using K = toolpath::ParamKey;

namespace {

// Rounds to a nanometre, -0 to 0: printed values short and stable.
double clean(double v) {
  const double r = std::round(v * 1e9) / 1e9;
  return r == 0 ? 0.0 : r;
}

}  // namespace

void MotionOut::number(Command& c, toolpath::ParamKey key, double v) { c.set(key, Value::make_numeric(clean(v))); }

Command& MotionOut::add(std::string_view name) {
  if (spare_.empty()) {
    queue_.emplace_back();
  } else {
    queue_.push_back(std::move(spare_.back()));
    spare_.pop_back();
    queue_.back().clear();
  }
  Command& c = queue_.back();
  c.name.assign(name);
  c.index = made_++;  // numbered in stream order, from 0
  return c;
}

bool MotionOut::take(Command& out) {
  if (queue_.empty()) return false;
  std::swap(out, queue_.front());
  if (spare_.size() < 64) spare_.push_back(std::move(queue_.front()));
  queue_.pop_front();
  return true;
}

void MotionOut::position_words(Command& c, const Eigen::Vector3d& p) {
  number(c, K::xpos, p.x());
  number(c, K::ypos, p.y());
  number(c, K::zpos, p.z());
  static constexpr std::array<K, 3> kRotary = {K::apos, K::bpos, K::cpos};
  for (std::size_t i = 0; i < 3; ++i)
    if (rotary_[i]) number(c, kRotary[i], *rotary_[i]);
}

void MotionOut::rapid(const Eigen::Vector3d& to) {
  position_words(add("@rapid_move"), to);
  position_ = to;
}

void MotionOut::line(const Eigen::Vector3d& to, double feed) {
  Command& c = add("@line");
  position_words(c, to);
  number(c, K::feed, feed);
  position_ = to;
}

void MotionOut::arc(const Eigen::Vector3d& to, const Eigen::Vector3d& centre, geo::Plane plane, bool ccw, double feed) {
  const geo::Arc a = geo::make_arc(position_, to, centre, plane, ccw ? geo::Direction::CCW : geo::Direction::CW, 360.0);
  Command& c = add("@arc");
  position_words(c, to);
  number(c, K::feed, feed);
  Eigen::Vector3d centre3 = centre;
  centre3[geo::axes(plane).normal] = position_[geo::axes(plane).normal];
  number(c, K::xcenter, centre3.x());
  number(c, K::ycenter, centre3.y());
  number(c, K::zcenter, centre3.z());
  number(c, K::radius, a.radius);
  number(c, K::arc_size, a.sweep);
  c.set(K::arc_direction, Value::make_enum(ccw ? "CCW" : "CW"));
  c.set(K::arc_plane, Value::make_enum(std::string(geo::plane_name(plane))));
  position_ = to;
}

void MotionOut::dwell(double seconds) { number(add("@delay"), K::delay_period, seconds); }

void MotionOut::spindle(int m, double speed) {
  speed_ = speed;
  if (m == 5) {
    if (spindle_ != 5) add("@stop_tool");
  } else {
    Command& c = add("@start_tool");
    number(c, K::spin, speed);
    c.set(K::spin_direction, Value::make_enum(m == 4 ? "CCW" : "CW"));
  }
  spindle_ = m;
}

void MotionOut::speed(double speed) {
  speed_ = speed;
  if (spindle_ != 5) number(add("@m_feed_spin"), K::spin, speed);
}

void MotionOut::tool_change(std::optional<double> number_, const std::optional<std::string>& name) {
  if (spindle_ != 5) {  // a tool change stops the spindle on every control (M6 runs M5 first)
    add("@stop_tool");
    spindle_ = 5;
  }
  Command& c = add("@change_tool");
  c.set(K::tool_number, Value::make_integer(number_ ? static_cast<std::int64_t>(*number_) : 0));
  if (name) c.set(K::tool_name, Value::make_string(*name));
}

void MotionOut::message(std::string text) { add("@message").set(K::message, Value::make_string(std::move(text))); }

void MotionOut::compensation(std::string_view side) {
  add("@compensation").set(K::side, Value::make_enum(std::string(side)));
}

void MotionOut::machine_move(const std::array<std::optional<double>, 3>& axes,
                             const std::array<std::optional<double>, 3>& rotary) {
  Command& c = add("@machine_move");
  static constexpr std::array<K, 3> kNames = {K::xpos, K::ypos, K::zpos}, kRotary = {K::apos, K::bpos, K::cpos};
  for (std::size_t i = 0; i < 3; ++i)
    if (axes[i]) number(c, kNames[i], *axes[i]);
  for (std::size_t i = 0; i < 3; ++i)
    if (rotary[i]) {
      rotary_[i] = *rotary[i];
      number(c, kRotary[i], *rotary[i]);
    }
}

void MotionOut::end_program() { position_words(add("@end_program"), position_); }

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
