// The PikoCNC controller model: executes a program line by line in the order of section 2.3 and
// hands motion and events to the emitter. One instance reads one program.
#pragma once

#include <array>
#include <bitset>
#include <cstddef>
#include <istream>
#include <memory>
#include <string>
#include <vector>

#include "machines/ncmodel/line_reader.hpp"
#include "machines/pikocnc/model/codes.hpp"
#include "machines/pikocnc/model/compensation.hpp"
#include "machines/pikocnc/model/diagnostics.hpp"
#include "machines/pikocnc/model/emitter.hpp"
#include "machines/pikocnc/model/lexer.hpp"
#include "machines/pikocnc/model/motion.hpp"
#include "machines/pikocnc/model/options.hpp"

namespace pikocnc {

// The modal state of section 3 and the persistent values of section 3.2.
struct State {
  Op motion = Op::G0;
  Op motion_before_cycle = Op::G0;
  bool cycle_active = false;
  Plane plane = Plane::XY;
  bool inch = false;
  bool diameter = false;
  bool incremental = false;
  bool per_rev = false;
  bool css = false;
  double css_limit = 0.0;
  bool return_to_r = false;  // G99
  double clearance_z = 0.0;
  bool clearance_known = false;
  int compensation = 40;
  double compensation_radius = 0.0;
  int work_offset = 0;  // 0..5 = G54..G59
  double feed = 0.0;
  double spindle = 0.0;
  int spindle_m = 5;    // 3, 4 or 5
  int tool = 0;
  int selected_tool = -1;
  bool c_m7 = false, c_m8 = false, c_m10 = false;
  bool pause_allowed = true;
  bool tcpc = false;
  int tcpc_slot = 0;
  // canned-cycle words remembered between blocks
  double cycle_z = 0.0, cycle_r = 0.0, cycle_q = 0.0, cycle_p = 0.0;
  bool cycle_has_z = false, cycle_has_r = false, cycle_has_q = false;
  // positions: the tool tip in machine coordinates is the truth; the program position follows it
  Axes5 tip{};
  Eigen::Vector3d prog = Eigen::Vector3d::Zero();
  double prog_a = 0.0, prog_b = 0.0;
  Axes5 program_offset{};  // G52 / G92 registers
  std::array<Axes5, 6> bases{};
  Axes5 tool_offset{};
  TransformStack transforms;
};

class Interpreter {
public:
  Interpreter(std::istream& in, std::string file_name, Options options);

  // Executes lines until at least one command is queued or the program is over; false at the end.
  bool run();
  Emitter& emitter() { return emitter_; }
  const Diagnostics& diagnostics() const { return diagnostics_; }
  const std::string& file_name() const { return file_; }

private:
  // One block being executed: its words with ownership and unit conversion (section 2.2, 4.6).
  struct Words;
  struct Resolved;
  struct ResolvedDeleter {
    void operator()(Resolved* r) const;
  };

  void execute(const Block& block);
  void finish(std::string_view end_code);
  void warn_open_loops();
  [[noreturn]] void fail(std::size_t column, const std::string& message) const;
  void warn(std::size_t column, std::string message);

  // exec_settings.cpp: steps 3-17
  void feed_and_spindle(const Resolved& r, Words& w);
  void tool_and_m_codes(const Resolved& r, Words& w);
  void offsets(const Resolved& r, Words& w);
  void transforms(const Resolved& r, Words& w);
  void misc_modes(const Resolved& r, Words& w);
  void set_tool_offset(const Axes5& offset);
  void recompute_program_position();
  const Frame& frame() const;  // cached; rebuilt after offsets or transforms change
  Axes5 work_position() const;

  // exec_motion.cpp: step 18
  void motion(const Resolved& r, Words& w);
  Eigen::Vector3d target(Words& w, bool incremental_words, bool allow_uvw);
  void straight(MoveKind kind, const Eigen::Vector3d& to, double a, double b);
  void arc(bool ccw, Words& w);
  void machine_move(bool tip_target, bool feed, Words& w);
  void home(const Axes5& where);
  void probe(Words& w);
  void lathe_thread(Words& w);
  void put(Move& m);  // to the compensation stage or straight to the emitter
  // Runs the program ahead, output muted, to see the chain an approach rapid leads to (the
  // compensation's end-of-contour rule needs its last element), then goes back.
  void preview_chain();

  // exec_cycles.cpp
  void cycle(Op op, bool programmed, Words& w);
  void cycle_hole(Op op, const Eigen::Vector3d& hole);
  void cycle_rapid_z(double z);
  void cycle_feed_z(double z);
  void spindle_event(int m);

  Options options_;
  std::string file_;
  ncmodel::LineReader lines_;
  Diagnostics diagnostics_;
  Diagnostics quiet_{0};
  Emitter emitter_;
  Compensator compensator_;
  bool uncompensable_ = false;  // the moves being made are a cycle's or a probe's
  bool previewing_ = false;
  ChainPreview preview_;
  State s_;
  Block block_;
  std::unique_ptr<Resolved, ResolvedDeleter> resolved_;  // reused for every line
  std::size_t line_ = 0;
  std::size_t executed_ = 0;
  bool started_ = false;
  bool finished_ = false;
  bool g115_seen_ = false;
  ncmodel::LineReader::Mark program_start_;
  int restarts_left_ = 0;
  struct Loop {
    ncmodel::LineReader::Mark body;
    long long remaining;
    std::size_t line;
    std::size_t column;  // of the G25, for the warning when no G125 closes it
  };
  std::vector<Loop> loops_;
  bool probe_protected_ = false;
  mutable Frame frame_;
  mutable bool frame_dirty_ = true;
  double thread_pitch_ = 0.0;
  std::size_t motion_column_ = 1;  // column of the line's motion code, for errors of modal moves
  std::uint32_t transform_changed_axes_ = 0;  // program axes to program in the next move (section 10.6)
  std::uint32_t programmed_axes_ = 0;         // program axes the line's move wrote (bit i: X Y Z)
};

}  // namespace pikocnc
