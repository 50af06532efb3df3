#include "machines/pikocnc/compensation.hpp"

namespace pikocnc {

void Compensator::set(int side, double radius, Plane plane) {
  side_ = side;
  radius_ = radius;
  plane_ = plane;
}

bool Compensator::in_plane_motion(const Move&) const { return false; }

void Compensator::move(const Move& m, const Frame& frame, Emitter& out, Diagnostics&, std::size_t) {
  out.move(m, frame);
}

void Compensator::flush(Emitter&, Diagnostics&) {}
void Compensator::close_chain(Emitter&, Diagnostics&) {}

}  // namespace pikocnc
