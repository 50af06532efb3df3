#include "machines/ncmodel/motion_out.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "toolpath/value.hpp"

namespace ncmodel {

namespace geo = toolpath::geometry;
using toolpath::Command;
using toolpath::Value;

namespace {

// Rounds to a nanometre, -0 to 0: printed values short and stable.
double clean(double v) {
  const double r = std::round(v * 1e9) / 1e9;
  return r == 0 ? 0.0 : r;
}

}  // namespace

void MotionOut::number(Command& c, std::string_view name, double v) { c.set(name, Value::make_numeric(clean(v))); }

Command& MotionOut::add(std::string_view name) {
  queue_.emplace_back();
  queue_.back().name = std::string(name);
  queue_.back().index = made_++;  // numbered in stream order, from 0
  return queue_.back();
}

void MotionOut::position_words(Command& c, const Eigen::Vector3d& p) {
  number(c, "xpos", p.x());
  number(c, "ypos", p.y());
  number(c, "zpos", p.z());
}

void MotionOut::rapid(const Eigen::Vector3d& to) {
  position_words(add("@rapid_move"), to);
  position_ = to;
}

void MotionOut::line(const Eigen::Vector3d& to, double feed) {
  Command& c = add("@line");
  position_words(c, to);
  number(c, "feed", feed);
  position_ = to;
}

void MotionOut::arc(const Eigen::Vector3d& to, const Eigen::Vector3d& centre, geo::Plane plane, bool ccw, double feed) {
  const geo::Arc a = geo::make_arc(position_, to, centre, plane, ccw ? geo::Direction::CCW : geo::Direction::CW, 360.0);
  Command& c = add("@arc");
  position_words(c, to);
  number(c, "feed", feed);
  Eigen::Vector3d centre3 = centre;
  centre3[geo::axes(plane).normal] = position_[geo::axes(plane).normal];
  number(c, "xcenter", centre3.x());
  number(c, "ycenter", centre3.y());
  number(c, "zcenter", centre3.z());
  number(c, "radius", a.radius);
  number(c, "arc_size", a.sweep);
  c.set("arc_direction", Value::make_enum(ccw ? "CCW" : "CW"));
  c.set("arc_plane", Value::make_enum(std::string(geo::plane_name(plane))));
  position_ = to;
}

void MotionOut::dwell(double seconds) { number(add("@delay"), "delay_period", seconds); }

void MotionOut::spindle(int m, double speed) {
  speed_ = speed;
  if (m == 5) {
    if (spindle_ != 5) add("@stop_tool");
  } else {
    Command& c = add("@start_tool");
    number(c, "spin", speed);
    c.set("spin_direction", Value::make_enum(m == 4 ? "CCW" : "CW"));
  }
  spindle_ = m;
}

void MotionOut::speed(double speed) {
  speed_ = speed;
  if (spindle_ != 5) number(add("@m_feed_spin"), "spin", speed);
}

void MotionOut::tool_change(std::optional<double> number_, const std::optional<std::string>& name) {
  Command& c = add("@change_tool");
  c.set("tool_number", Value::make_integer(number_ ? static_cast<std::int64_t>(*number_) : 0));
  if (name) c.set("tool_name", Value::make_string(*name));
}

void MotionOut::message(std::string text) { add("@message").set("message", Value::make_string(std::move(text))); }

void MotionOut::compensation(std::string_view side) {
  add("@compensation").set("side", Value::make_enum(std::string(side)));
}

void MotionOut::machine_move(const std::array<std::optional<double>, 3>& axes) {
  Command& c = add("@machine_move");
  static constexpr std::array<std::string_view, 3> kNames = {"xpos", "ypos", "zpos"};
  for (std::size_t i = 0; i < 3; ++i)
    if (axes[i]) number(c, kNames[i], *axes[i]);
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
