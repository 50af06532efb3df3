// The toolpath side of `postproc verify`: the motion the commands a post received stand for.
//
// What each command means (the reading every post for a 3-axis mill shares):
//   @rapid_move, @line, @arc   the move itself
//   @delay                     a dwell of delay_period seconds
//   @change_tool               spindle stop, the tool, the spindle start (tool_direction, spin), then a
//                              rapid to xnext ynext at the current height and down to znext
//   @turn_change_tool          the same on a lathe (spin_direction), then a rapid to xnext znext in
//                              one move
//   @start_tool / @stop_tool   spindle on / off;  @m_feed_spin, @feed_spin: a new spindle speed
//   @drill ... @end_drill      the canned cycle, hole by hole (drilling, peck, tapping)
//   @end_program               spindle stop, lift to the end height, then the end position in X Y
//   @call_proc, @proc, @loop   expanded before the commands get here (verify_expansion.cpp)
#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "postproc/checks/verify_modeller.hpp"
#include "prp/prp.hpp"
#include "toolpath/value.hpp"

namespace postproc::verify {
namespace {

using toolpath::Command;
using toolpath::iequals;
namespace geo = toolpath::geometry;

double number_or(const Command& c, std::string_view name, double fallback) { return number(c, name).value_or(fallback); }

std::string word(const Command& c, std::string_view name) {
  const toolpath::Value* v = c.find(name);
  return v ? v->text : std::string();
}

bool logical(const Command& c, std::string_view name) {
  const toolpath::Value* v = c.find(name);
  if (!v) return false;
  if (v->kind == toolpath::ValueKind::Logical) return v->logical;
  return v->as_number() != 0;
}

// Commands without motion of their own (they only set variables, or write comments).
bool silent(const Command& c) {
  for (std::string_view n : {"@start_of_file", "@def_tool", "@machine_plane", "@start_program", "@start_of_job",
                             "@end_of_job", "@message", "@compensation", "@absolute_mode", "@relative_mode",
                             "@home_number", "@tool_path_info", "@end_of_file", "@end_job_procs", "@home_data"})
    if (is(c, n)) return true;
  return false;
}

// Turns commands into motion, keeping the tool's position (per axis: known or not).
class Modeller {
public:
  Modeller(const prp::MachineParameters& machine, const machines::VerifyProfile& profile, std::deque<Motion>& out)
      : machine_(machine), profile_(profile), out_(out) {}

  void command(const Command& c) {
    if (is(c, "@start_of_file")) scale_ = logical(c, "inch_system") ? 25.4 : 1.0;
    if (silent(c)) return;
    if (is(c, "@rapid_move")) return move(c, MotionKind::Rapid, point(c, "xpos", "ypos", "zpos"), 0.0);
    if (is(c, "@line")) return move(c, MotionKind::Feed, point(c, "xpos", "ypos", "zpos"), feed(c));
    if (is(c, "@arc")) return arc(c);
    if (is(c, "@delay")) {
      Motion m = base(c, MotionKind::Dwell);
      m.seconds = number_or(c, "delay_period", 0.0);
      return emit(m);
    }
    if (is(c, "@change_tool")) return change_tool(c);
    if (is(c, "@turn_change_tool")) return turn_change_tool(c);
    if (is(c, "@start_tool")) return spindle(c, direction(c), number_or(c, "spin", 0.0));
    if (is(c, "@stop_tool")) return spindle(c, 0, 0.0);
    if (is(c, "@m_feed_spin") || is(c, "@feed_spin")) {
      if (auto s = number(c, "spin"); s && spindle_ != 0) spindle(c, spindle_, *s);
      return;
    }
    if (is(c, "@drill")) return drill(c);
    if (is(c, "@drill_point")) {
      if (!logical(c, "first_drill")) hole(c, point(c, "xpos", "ypos", "zpos"));
      return;
    }
    if (is(c, "@end_drill")) return;
    if (is(c, "@end_program")) return end_program(c);
    throw std::runtime_error(fmt::format("command #{} {}: verify does not model this command", c.index, c.name));
  }

private:
  Motion base(const Command& c, MotionKind kind) const {
    Motion m;
    m.kind = kind;
    m.name = c.name;
    m.where = c.index;
    return m;
  }

  Eigen::Vector3d point(const Command& c, std::string_view x, std::string_view y, std::string_view z) const {
    Eigen::Vector3d p = position_;
    if (auto v = number(c, x)) p.x() = *v * scale_;
    if (auto v = number(c, y)) p.y() = *v * scale_;
    if (auto v = number(c, z)) p.z() = *v * scale_;
    return p;
  }

  double feed(const Command& c) const { return number_or(c, "feed", 0.0) * scale_; }

  static int direction(const Command& c) { return iequals(word(c, "tool_direction"), "CCW") ? -1 : 1; }

  void emit(const Motion& m) { out_.push_back(m); }

  // A straight move to `to`; the axes it names become known.
  void move(const Command& c, MotionKind kind, const Eigen::Vector3d& to, double feed,
            std::array<bool, 3> sets = {true, true, true}) {
    // The controller models start at X0 Y0 Z0: a first move to there is no move for them (a tool
    // change that approaches X0 Y0 writes `G0 X0. Y0.`, which they drop), so it is none here either.
    if (!moved_ && (to - position_).norm() <= 1e-9) {
      for (int i = 0; i < 3; ++i) known_[i] = known_[i] || sets[i];
      return;
    }
    moved_ = true;
    Motion m = base(c, kind);
    m.from = position_;
    m.from_known = known_[0] && known_[1] && known_[2];
    m.to = to;
    for (int i = 0; i < 3; ++i) m.known[i] = known_[i] || sets[i];
    m.feed = feed;
    position_ = to;
    known_ = m.known;
    emit(m);
  }

  void arc(const Command& c) {
    if (!(known_[0] && known_[1] && known_[2]))
      throw std::runtime_error(fmt::format("command #{} @arc: the arc starts where the tool's position is not known", c.index));
    const Eigen::Vector3d end = point(c, "xpos", "ypos", "zpos");
    Motion m = base(c, MotionKind::Arc);
    m.from = position_;
    m.from_known = true;
    m.to = end;
    m.feed = feed(c);
    m.arc = geo::arc_of(c, position_, end, scale_);
    position_ = end;
    moved_ = true;
    emit(m);
  }

  void spindle(const Command& c, int state, double speed) {
    Motion m = base(c, MotionKind::Spindle);
    m.spindle = state;
    m.speed = state ? speed : 0.0;
    spindle_ = state;
    if (state) speed_ = speed;
    emit(m);
  }

  void change_tool(const Command& c) {
    spindle(c, 0, 0.0);
    Motion t = base(c, MotionKind::Tool);
    const double tool = number_or(c, "tool_number", 0);
    t.tool = std::abs(tool) <= 1e15 ? static_cast<std::int64_t>(tool) : -1;  // no undefined conversion
    emit(t);
    if (double s = number_or(c, "spin", 0.0); s > 0) spindle(c, direction(c), s);
    auto xn = number(c, "xnext"), yn = number(c, "ynext"), zn = number(c, "znext");
    const std::size_t before = out_.size();
    if (xn && yn) {
      Eigen::Vector3d p = position_;
      p.x() = *xn * scale_;
      p.y() = *yn * scale_;
      move(c, MotionKind::Rapid, p, 0.0, {true, true, false});
    }
    // The approach in X Y, then down: a program may make both in one block (Motion::approach).
    if (zn && out_.size() > before && out_.back().kind == MotionKind::Rapid) out_.back().approach = true;
    if (zn) {
      Eigen::Vector3d p = position_;
      p.z() = *zn * scale_;
      move(c, MotionKind::Rapid, p, 0.0, {false, false, true});
    }
    // Where the tool goes next is the toolpath's to say (its next moves); many posts leave the
    // approach to them (Motion::optional).
    for (std::size_t i = before; i < out_.size(); ++i) out_[i].optional = true;
  }

  void turn_change_tool(const Command& c) {
    spindle(c, 0, 0.0);
    Motion t = base(c, MotionKind::Tool);
    const double tool = number_or(c, "tool_number", 0);
    t.tool = std::abs(tool) <= 1e15 ? static_cast<std::int64_t>(tool) : -1;
    emit(t);
    if (double s = number_or(c, "spin", 0.0); s > 0) spindle(c, iequals(word(c, "spin_direction"), "CCW") ? -1 : 1, s);
    auto xn = number(c, "xnext"), zn = number(c, "znext");
    if (xn && zn) {
      Eigen::Vector3d p = position_;
      p.x() = *xn * scale_;
      p.z() = *zn * scale_;
      move(c, MotionKind::Rapid, p, 0.0, {true, false, true});
    }
  }

  // The end position is optional (Motion::optional): a post may home the machine instead.
  void end_program(const Command& c) {
    spindle(c, 0, 0.0);
    auto x = number(c, "xpos"), y = number(c, "ypos"), z = number(c, "zpos");
    const std::size_t before = out_.size();
    if (z) {
      Eigen::Vector3d p = position_;
      p.z() = *z * scale_;
      move(c, MotionKind::Rapid, p, 0.0, {false, false, true});
    }
    if (x && y) {
      Eigen::Vector3d p = position_;
      p.x() = *x * scale_;
      p.y() = *y * scale_;
      move(c, MotionKind::Rapid, p, 0.0, {true, true, false});
    }
    for (std::size_t i = before; i < out_.size(); ++i) out_[i].optional = true;
  }

  // The cycle of a @drill, by the base type of its PRP record: the tool goes to the first hole at
  // the clearance height and drills it; @drill_point brings the others.
  void drill(const Command& c) {
    std::string name = word(c, "drill_type");
    const prp::Record* record = machine_.drill_cycle(name);
    cycle_ = record ? record->base : name;
    for (auto& ch : cycle_) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    static constexpr std::string_view kModelled[] = {"DRILLING", "F_DRILL", "PECK", "TAPPING", "BORING", "R_BORING", "F_BORING"};
    if (std::find(std::begin(kModelled), std::end(kModelled), cycle_) == std::end(kModelled))
      throw std::runtime_error(fmt::format("command #{} @drill: verify models the cycle bases DRILLING, F_DRILL, PECK, "
                                           "TAPPING, BORING, R_BORING and F_BORING, not `{}`", c.index, name));
    dwell_ = 0;
    if (cycle_ == "F_DRILL" || cycle_ == "F_BORING")  // the record's dwell parameter, as the engine takes it
      if (const auto dwell = record ? prp::dwell_parameter(*record) : std::nullopt) dwell_ = number_or(c, *dwell, 0.0);
    clearance_ = number_or(c, "drill_clearance_z", 0.0) * scale_;
    upper_ = number_or(c, "drill_upper_z", 0.0) * scale_;
    lower_ = number_or(c, "drill_lower_z", 0.0) * scale_;
    step_ = number_or(c, "down_step", 0.0) * scale_;
    cycle_feed_ = feed(c);
    Eigen::Vector3d first = point(c, "xpos", "ypos", "zpos");
    first.z() = clearance_;
    move(c, MotionKind::Rapid, first, 0.0);
    hole(c, first);
  }

  void hole(const Command& c, Eigen::Vector3d at) {
    const double travel = std::abs(clearance_ - upper_) < 0.0005 ? upper_ : clearance_;
    at.z() = position_.z();
    move(c, MotionKind::Rapid, at, 0.0);
    auto to_z = [&](MotionKind kind, double z) {
      Eigen::Vector3d p = position_;
      p.z() = z;
      move(c, kind, p, kind == MotionKind::Rapid ? 0.0 : cycle_feed_);
    };
    to_z(MotionKind::Rapid, upper_);
    auto dwell = [&] {
      if (dwell_ <= 0) return;
      Motion m = base(c, MotionKind::Dwell);
      m.seconds = dwell_;
      emit(m);
    };
    if (cycle_ == "TAPPING" || cycle_ == "BORING" || cycle_ == "F_BORING") {
      to_z(MotionKind::Feed, lower_);
      dwell();
      // Tapping: a control's G84 feeds out to R, then rapids; a tapping head's feeds out all the way.
      if (cycle_ == "TAPPING" && !profile_.tap_feeds_out_to_r) {
        to_z(MotionKind::Feed, travel);
        return;
      }
      to_z(MotionKind::Feed, upper_);
      to_z(MotionKind::Rapid, travel);
      return;
    }
    if (cycle_ == "R_BORING") {  // out at rapid with the spindle stopped, then on again
      to_z(MotionKind::Feed, lower_);
      const int running = spindle_;
      const double speed = speed_;
      spindle(c, 0, speed);
      to_z(MotionKind::Rapid, travel);
      spindle(c, running, speed);
      return;
    }
    if (cycle_ == "PECK" && step_ > 0) {
      for (int n = 0;; ++n) {
        const double depth = std::max(upper_ - (n + 1) * step_, lower_);
        if (n > 0) to_z(MotionKind::Rapid, upper_ - n * step_);
        to_z(MotionKind::Feed, depth);
        to_z(MotionKind::Rapid, upper_);
        if (depth <= lower_) break;
      }
    } else {
      to_z(MotionKind::Feed, lower_);
      dwell();
      to_z(MotionKind::Rapid, upper_);
    }
    to_z(MotionKind::Rapid, travel);
  }

  const prp::MachineParameters& machine_;
  machines::VerifyProfile profile_;
  std::deque<Motion>& out_;
  double scale_ = 1.0;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  std::array<bool, 3> known_{false, false, false};
  bool moved_ = false;  // a move was emitted (until then the position is the controllers' start, 0 0 0)
  int spindle_ = 0;
  double speed_ = 0;
  std::string cycle_;
  double clearance_ = 0, upper_ = 0, lower_ = 0, step_ = 0, cycle_feed_ = 0, dwell_ = 0;
};

}  // namespace

struct CommandModel::State {
  Modeller modeller;
};

CommandModel::CommandModel(const prp::MachineParameters& machine, const machines::VerifyProfile& profile,
                           std::deque<Motion>& out)
    : state_(std::make_unique<State>(State{Modeller(machine, profile, out)})) {}
CommandModel::~CommandModel() = default;
void CommandModel::command(const Command& c) { state_->modeller.command(c); }

}  // namespace postproc::verify
