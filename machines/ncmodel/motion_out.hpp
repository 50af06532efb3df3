// What a controller model makes of a program, as neutral stream commands: moves from the tool's
// position, arcs, dwells, spindle and tool events, and drilling cycles expanded hole by hole. Shared
// by the models that execute a program block by block (Sinumerik, the ISO family), so that a cycle
// or an arc means the same motion in each; the stream's conventions are those of the PikoCNC model
// (an arc's xcenter ycenter zcenter are the centre's X Y Z).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "toolpath/command.hpp"
#include "toolpath/geometry.hpp"
#include "toolpath/param_key.hpp"
#include "toolpath/parameter_shelf.hpp"

namespace ncmodel {

// Rounds to a nanometre, halves away from zero (as std::round), and -0 to 0: the values the
// commands carry, short and stable when printed. Without a libm call for every value.
double clean(double v);

class MotionOut {
public:
  bool empty() const { return head_ == tail_; }
  // Moves the oldest command made into `out`; `out`'s old buffers are kept for a later command, so
  // a long program allocates nothing per command. False when none waits.
  bool take(toolpath::Command& out);
  const Eigen::Vector3d& position() const { return position_; }
  // Rotary axes A B C (0 1 2), degrees: once a program names one, every move carries its angle
  // (apos, bpos, cpos), as a 4-axis toolpath does. nullopt: not used yet.
  const std::optional<double>& rotary(int axis) const { return rotary_[static_cast<std::size_t>(axis)]; }
  void set_rotary(int axis, double degrees) { rotary_[static_cast<std::size_t>(axis)] = degrees; }

  void rapid(const Eigen::Vector3d& to);
  void line(const Eigen::Vector3d& to, double feed);
  // An arc from the position to `to` about `centre` (its normal coordinate is ignored); a full
  // circle when they coincide in the plane.
  void arc(const Eigen::Vector3d& to, const Eigen::Vector3d& centre, toolpath::geometry::Plane plane, bool ccw,
           double feed);
  void dwell(double seconds);
  // M3 (CW), M4 (CCW) or M5; a new speed while it runs.
  void spindle(int m, double speed);
  void speed(double speed);
  int spindle_state() const { return spindle_; }
  void tool_change(std::optional<double> number, const std::optional<std::string>& name);
  void message(std::string text);
  void compensation(std::string_view side);  // COMP_LEFT, COMP_RIGHT, COMP_OFF
  // A move in machine coordinates: where that is in the work frame the program does not say, so the
  // position stays; the command carries the axes it names (nullopt: not moved). A rotary axis named
  // is turned there (`G53 A0`: no work offset shifts a rotary axis in these programs) and carried
  // as apos/bpos/cpos.
  void machine_move(const std::array<std::optional<double>, 3>& axes,
                    const std::array<std::optional<double>, 3>& rotary = {});
  void end_program();

  // One hole of a drilling cycle at the current X Y: a rapid to `approach` (the R level), then by
  // kind down to `depth`, and a rapid to `retract` at the end.
  struct Hole {
    enum class Kind { Drill, Peck, ChipBreak, Tap, Bore, BoreSpindleStop };
    Kind kind = Kind::Drill;
    double approach = 0, depth = 0, retract = 0;
    double first_step = 0;      // Peck, ChipBreak: the first step's depth below `approach`'s level
    double step = 0;            // the following steps (0: as the first)
    double step_reduction = 0;  // each step shorter by this, down to it (Sinumerik's DAM)
    double chip_lift = 1.0;     // ChipBreak: the lift after each step
    double dwell = 0;           // at the bottom, seconds
    double feed = 0, feed_out = 0;  // feed_out: Tap and Bore (0: feed)
  };
  // Throws std::runtime_error when the steps never reach the depth (more than 100000 of them).
  void hole(const Hole& h);

private:
  // Starts a command at the end of the queue; number() and word() add its parameters in order,
  // into the slots a recycled command already has (mostly named so: no clearing, no lookup).
  void add(std::string_view name);
  toolpath::Value& slot(toolpath::ParamKey key, toolpath::ValueKind kind);
  toolpath::Parameter& new_slot();
  void number(toolpath::ParamKey key, double v);
  void word(toolpath::ParamKey key, std::string_view w);
  void finish_command();  // cuts the command being filled to the parameters it was given
  void position_words(const Eigen::Vector3d& p);

  // Commands from head_ to tail_ wait; the vector is reused from the start once they are taken,
  // so its commands keep their buffers (what take() swapped in from the consumer).
  std::vector<toolpath::Command> queue_;
  std::size_t head_ = 0, tail_ = 0;
  toolpath::Command* current_ = nullptr;
  std::size_t fill_ = 0;
  // A recycled command mostly held another shape (an @arc comes back for a @line): the shelf
  // keeps the parameter vectors by command name, so that their slots are named already.
  toolpath::ParameterShelf shelf_;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  int spindle_ = 5;
  double speed_ = 0;
  std::size_t made_ = 0;  // commands made so far
  std::array<std::optional<double>, 3> rotary_;
};

}  // namespace ncmodel
