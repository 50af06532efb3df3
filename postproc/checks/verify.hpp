// Closed-loop verification (`postproc verify`): a job is posted, the NC program is read back with
// a controller model of the registry (machines/registry/), and the motion it makes is compared with
// the motion of the toolpath the post received (after the PRP filters). docs/pikocnc.md, "verify".
//
// Both sides become the same kind of events (rapid, feed, arc, dwell, tool, spindle), normalised
// alike: moves shorter than the tolerance are dropped, consecutive collinear moves of one kind and
// feed are joined, spindle events that change nothing are dropped. Then they are compared in order.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "machines/registry/controller.hpp"
#include "postproc/engine/engine.hpp"
#include "prp/prp.hpp"
#include "toolpath/command.hpp"
#include "toolpath/diagnostic.hpp"
#include "toolpath/geometry.hpp"


namespace postproc::verify {

enum class MotionKind : std::uint8_t { Rapid, Feed, Arc, Dwell, Tool, Spindle, Other };

struct Motion {
  MotionKind kind = MotionKind::Rapid;
  // Moves: end point, and which of its axes are known (a move after an unknown start may leave an
  // axis where it was); `from` is the start, valid when every axis of it is known.
  Eigen::Vector3d from = Eigen::Vector3d::Zero();
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
  std::array<bool, 3> known{true, true, true};
  bool from_known = false;
  double feed = 0.0;                // Feed, Arc
  toolpath::geometry::Arc arc;      // Arc (its start and end are `from` and `to`)
  double seconds = 0.0;             // Dwell
  std::int64_t tool = 0;            // Tool
  int spindle = 0;                  // Spindle: 1 CW (M3), -1 CCW (M4), 0 off
  double speed = 0.0;               // Spindle
  // Expected only: a move the program may leave out. @end_program's move to the end position: many
  // posts send the machine home instead (G28, G53), which the models do not place in the work frame.
  bool optional = false;
  // Expected only: a tool change's approach in X Y, which a program may make together with the move
  // down to the approach height that follows it, in one block (`G0 X20. Y0. Z30.`).
  bool approach = false;
  std::string name;                 // the command that made it ("@line"), for reports
  std::size_t where = 0;            // expected: command index in the stream; actual: NC line
};

class MotionSource {
public:
  virtual ~MotionSource() = default;
  virtual bool next(Motion& out) = 0;
};

struct Tolerances {
  double position = 0.001;  // mm: end points, centres, radii (and the arc length of sweeps)
  double feed = 0.001;      // mm/min
  double seconds = 0.001;   // dwell
};

// The toolpath side. Collects the commands the post received (Engine's RunOptions::posted), then
// yields their motion with subroutine calls and loops expanded (a body called N times, or in a
// loop of N, runs N times). The commands wait in temporary files, not in memory: memory does not
// grow with the job. Throws std::runtime_error when no temporary file can be made.
class ExpectedMotion {
public:
  // `profile`: how the controller's cycles move where controllers differ (tapping).
  explicit ExpectedMotion(const prp::MachineParameters& machine, const machines::VerifyProfile& profile = {});
  ~ExpectedMotion();
  void add(const toolpath::Command& command);
  // Throws std::runtime_error naming the command when the stream has something verify cannot model,
  // and when the calls and loops would run more than `max_commands` commands (a runaway count).
  static constexpr std::uint64_t default_max_commands = 1'000'000'000;
  std::unique_ptr<MotionSource> motion(std::uint64_t max_commands = default_max_commands);

private:
  struct Data;
  std::unique_ptr<Data> data_;
};

// The NC side: the motion a controller's model makes for an NC program, read for verify (the
// programmed path: cutter compensation off). Events carry their NC line. The model's warnings go to
// `warnings` when the program ends; its errors are thrown (toolpath::InputError).
// `observe` (when set) sees every command the model makes, in order, with its NC line.
std::unique_ptr<MotionSource> nc_motion(const std::filesystem::path& program, const machines::Controller& controller,
                                        std::string_view dialect, const machines::ReadOptions& options,
                                        std::ostream& warnings,
                                        std::function<void(const toolpath::Command&, std::size_t)> observe = nullptr);

// The toolpath side as the controller's programs can say it (verify_profile.cpp). Under
// VerifyProfile::planar_speeds: moves projected on X Y from the program origin, feeds turned into the
// speeds the post writes, tool changes dropped, the spindle only on or off; without tool_changes:
// tool changes dropped. `source` must outlive the result.
std::unique_ptr<MotionSource> as_programmed(MotionSource& source, const machines::VerifyProfile& profile);

// Drops moves shorter than the tolerance, joins collinear moves, drops spindle events that change
// nothing. `source` must outlive the result.
std::unique_ptr<MotionSource> normalised(MotionSource& source, const Tolerances& tolerances);

struct Divergence {
  std::size_t ordinal = 0;             // 1-based number of the event pair that differs
  std::string what;                    // "end point differs by 0.5 mm", "the NC program ends early", ...
  std::optional<Motion> expected, actual;
};

struct Result {
  std::size_t compared = 0;            // event pairs that matched
  std::optional<Divergence> divergence;
};

// Compares two normalised sources event by event; stops at the first divergence. An optional
// expected move is matched when the program makes it (alone, or as the end of a longer move in its
// line), and passed over when it does not. A dwell the program adds where the toolpath has none moves
// nothing and is passed over; a dwell the toolpath asks for must be in the program.
Result compare(MotionSource& expected, MotionSource& actual, const Tolerances& tolerances);

// One line for a report: "rapid to X1 Y2 Z3", "arc CCW XY to ... centre ... R5 sweep 90", ...
std::string describe(const Motion& motion);

// The cycle time of the program as the controller model runs it (prp::TimeEstimate, spec 3.15:
// its moves at their feeds, rapids at the machine file's rapid_feed, dwells, time_factor,
// block_time and change_tool_time), in all and per tool, in the order the tools are used.
struct CycleTime {
  struct Tool {
    std::int64_t number = 0;  // 0: before the first tool change
    double seconds = 0;
  };
  double seconds = 0;
  std::vector<Tool> tools;
  bool rapid_feed_missing = false;  // rapids were not timed: the machine file has no rapid_feed
};

// "3 min 12 s (T3 1 min 40 s, T7 1 min 32 s)".
std::string describe(const CycleTime& time);

// What a program does that no machine should, whatever the toolpath says (verify_state.cpp;
// docs/pikocnc.md, "Machine-state checks"), found as the model runs the program. Each kind is
// reported once, at its first NC line, with how often it happened.
struct Finding {
  toolpath::Severity severity = toolpath::Severity::Warning;  // Error: scrap; Warning: suspect
  std::size_t line = 0;                                        // NC line of the first one
  std::size_t count = 0;
  std::string what;
};

class StateChecks {
public:
  // `profile`: a planar_speeds machine (2XAxisCNC) moves only at speeds, with the spindle on or off:
  // the spindle and feed checks do not apply.
  // `rotary`: the machine's rotary axes with their travel (prp::MachineParameters::rotary_limits).
  explicit StateChecks(const machines::VerifyProfile& profile, std::vector<prp::RotaryLimits> rotary = {})
      : rotary_(std::move(rotary)), planar_(profile.planar_speeds) {}
  void command(const toolpath::Command& c, std::size_t line);  // the model's commands, in order
  const std::vector<Finding>& findings() const { return findings_; }
  bool any_error() const;

private:
  void find(toolpath::Severity severity, std::size_t line, std::string what);

  void rotary_travel(const toolpath::Command& c, std::size_t line);

  std::vector<Finding> findings_;
  std::vector<prp::RotaryLimits> rotary_;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  std::optional<double> plunge_from_;  // the Z the last downward feed started from
  bool planar_ = false;
  bool spindle_on_ = false, compensation_changed_ = false, machine_moved_ = false;
};

struct JobReport {
  Result result;
  std::vector<Finding> findings;   // of the program read back (up to a divergence)
  CycleTime cycle_time;            // of the program read back (up to a divergence)
  std::filesystem::path program;   // the NC program that was read back (removed unless kept)
  std::string expected_command;    // "command #21 @arc" of the expected side of a divergence
  std::string nc_line;             // "NAME.NC:42: G2 X40. Y5. I0. J5." of the actual side
};

// Posts `job` with `engine` (the caller builds it, so that it can report the machine file's
// warnings first), reads the main NC program back and compares. The program is written to
// `keep_program` when given, else to a temporary folder that is removed. Throws what the engine and
// the readers throw (errors in the inputs). The stream's warnings (RunOptions::warnings) go to
// `warnings` when given.
// The NC program is read with `controller` as `dialect` (one of its names); `read.answers` are the
// run's answers, for a controller whose program depends on them.
JobReport verify_job(const Engine& engine, const std::string& job, const Tolerances& tolerances,
                     const std::optional<std::filesystem::path>& keep_program, const machines::Controller& controller,
                     std::string_view dialect, const machines::ReadOptions& read, std::ostream* warnings = nullptr);

}  // namespace postproc::verify
