// Cutter radius compensation G41/G42 (section 8): offsets chains of working moves in the program
// frame, streaming. An element is held until the next element of the chain arrives (the corner
// between them decides where it ends); moves along the plane normal in between are held with it.
// The end-of-contour rule (the first element is trimmed against the last) needs the chain's last
// element before its first is emitted: the interpreter runs the program ahead (ChainPreview) when
// a rapid approaches a chain, so nothing else is buffered. Rules chosen: docs/pikocnc.md.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "machines/pikocnc/model/diagnostics.hpp"
#include "machines/pikocnc/model/emitter.hpp"
#include "machines/pikocnc/model/motion.hpp"
#include "machines/pikocnc/model/offset.hpp"

namespace pikocnc {

// Where a move was programmed, for messages.
struct SourcePlace {
  std::size_t line = 0;
  std::size_t column = 1;
};

// What the program does after an approach rapid, up to the end of the chain that follows it:
// filled by the interpreter running ahead with the output muted.
struct ChainPreview {
  ChainPreview() = default;
  explicit ChainPreview(Plane p) : plane(p) {}

  Plane plane = Plane::XY;
  bool done = false;
  std::size_t elements = 0;  // working moves with motion in the plane
  Move first, last;
  SourcePlace first_where, last_where;

  // `compensable`: a G0-G3 move the compensation takes (not a cycle, thread or machine move).
  void take(const Move& m, bool compensable, SourcePlace where);
  void end() { done = true; }
};

// True when the move goes somewhere in `plane` (arcs in the plane always do), or is a rapid that
// writes an axis of the plane (an approach, even when it stays where it is).
bool moves_in_plane(const Move& m, Plane plane);

class Compensator {
public:
  // `point_tolerance`: an arc whose offset radius is within it of zero shrinks to a point (the tool
  // radius equals the arc radius on its inside: the tool pivots on the arc's centre).
  Compensator(std::string file_name, double point_tolerance)
      : file_(std::move(file_name)), point_tolerance_(point_tolerance) {}

  // G41 (side +1) or G42 (side -1) with `radius` in `plane`. With `entry_rule` (G18, lathe) a
  // chain starts with its G1 entry move instead of a G0 approach.
  void start(int side, double radius, Plane plane, bool entry_rule, Emitter& out);
  // G40 or the end of the program: the open chain ends where it is.
  void stop(Emitter& out);
  bool active() const { return side_ != 0; }
  Plane plane() const { return plane_; }

  // The next move in the program frame. `compensable` is false for moves the documents do not allow
  // inside a compensated path (cycles, threads, probing, machine moves): they end the chain.
  void move(const Move& m, const Frame& frame, SourcePlace where, bool compensable, Emitter& out, Diagnostics& diag);

  // An approach rapid waits for the interpreter to run ahead, then resolve_approach() places it.
  bool wants_preview() const { return phase_ == Phase::Approaching; }
  void resolve_approach(const ChainPreview& preview, Emitter& out);

private:
  enum class Phase {
    Loose,        // the tool is not on an offset path: the next working move needs an entry
    Approaching,  // an approach rapid holds a hole until the preview places it
    Approached,   // at the start point of the chain that follows
    Entry,        // a G1 entry move waits for the element it leads to
    Chain,        // an element waits for its successor
  };
  struct Held {
    Move move;
    Frame frame;
    SourcePlace where;
  };

  OffsetElement element(const Move& m, SourcePlace where) const;
  void end_chain(Emitter& out);
  void next_element(const Held& h, Emitter& out, Diagnostics& diag);
  void corner(const Held& next, const OffsetElement& e, Emitter& out);
  // Emits the held element from its start parameter to `end_param` into its hole.
  void finish_pending(double end_param, const Eigen::Vector2d& end_point, Emitter& out);
  void finish_entry(const Eigen::Vector2d& end_point, bool compensated, Emitter& out);
  void release_between(Emitter& out);
  void emit(Move m, const Frame& frame, const Eigen::Vector3d& to, bool compensated, Emitter& out);
  Eigen::Vector3d lift(const Eigen::Vector2d& p, double normal_value) const;
  Eigen::Vector2d flat(const Eigen::Vector3d& p) const { return in_plane(p, plane_); }
  [[noreturn]] void fail(SourcePlace where, const std::string& message) const;

  std::string file_;
  double point_tolerance_;
  int side_ = 0;
  double offset_ = 0.0;  // signed: > 0 left
  Plane plane_ = Plane::XY;
  bool entry_rule_ = false;
  Phase phase_ = Phase::Loose;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();  // where the tool is (program frame)
  bool position_known_ = false;
  Held pending_;                 // the approach rapid, the entry move or the waiting element
  OffsetElement pending_elem_;
  double pending_start_ = 0.0;   // parameter where the waiting element starts (after its corner)
  std::vector<Held> between_;    // moves along the normal after the waiting element
  // the chain that was approached: the preview's closing point
  std::size_t chain_elements_ = 0, preview_elements_ = 0;
  bool closing_ = false;
  Eigen::Vector2d closing_point_ = Eigen::Vector2d::Zero();
  double first_start_ = 0.0;     // parameter where the approached chain's first element starts
  std::size_t warned_line_ = 0;  // one "not compensated" warning per line
};

}  // namespace pikocnc
