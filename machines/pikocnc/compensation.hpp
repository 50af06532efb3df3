// Cutter radius compensation G41/G42 (section 8): offsets chains of working moves in the program
// frame. A chain is buffered until it ends, because its first element is trimmed against its last.
#pragma once

#include <cstddef>
#include <vector>

#include "machines/pikocnc/diagnostics.hpp"
#include "machines/pikocnc/emitter.hpp"
#include "machines/pikocnc/motion.hpp"

namespace pikocnc {

class Compensator {
public:
  // side: +1 left (G41), -1 right (G42), 0 off (G40).
  void set(int side, double radius, Plane plane);
  int side() const { return side_; }
  // Takes the next move (program frame); emits what is final.
  void move(const Move& m, const Frame& frame, Emitter& out, Diagnostics& diag, std::size_t line);
  // Ends the open chain (end of program, machine moves): everything buffered is emitted.
  void flush(Emitter& out, Diagnostics& diag);
  bool idle() const { return side_ == 0 && items_.empty(); }

private:
  struct Item {
    Move move;
    Frame frame;
    std::size_t slot;  // emitter queue position reserved for it
    std::size_t line;
  };
  void close_chain(Emitter& out, Diagnostics& diag);
  bool in_plane_motion(const Move& m) const;

  int side_ = 0;
  double radius_ = 0.0;
  Plane plane_ = Plane::XY;
  std::vector<Item> items_;     // the approach rapid and the chain's moves
  bool chain_open_ = false;
  bool cancel_pending_ = false; // G40 seen: the next move leaves the contour
  Eigen::Vector3d last_offset_end_ = Eigen::Vector3d::Zero();
  bool have_offset_end_ = false;
};

}  // namespace pikocnc
