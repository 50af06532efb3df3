#include "machines/pikocnc/model/compensation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "toolpath/error.hpp"

namespace pikocnc {
namespace {

constexpr double kSamePoint = 1e-7;  // mm: offset points closer than this are one point
constexpr double kMinMotion = 1e-9;  // mm: shorter moves are not emitted
// Moves along the plane normal held behind one waiting element; beyond this the contour is ended.
constexpr std::size_t kMaxBetween = 100000;

}  // namespace

bool moves_in_plane(const Move& m, Plane plane) {
  if ((m.kind == MoveKind::Arc && m.plane == plane) || m.plane_words) return true;
  return (in_plane(m.to, plane) - in_plane(m.from, plane)).norm() > kMinMotion;
}

void ChainPreview::take(const Move& m, bool compensable, SourcePlace where) {
  if (done) return;
  if (!compensable || (m.kind == MoveKind::Arc && m.plane != plane)) {
    done = true;
    return;
  }
  if (!moves_in_plane(m, plane)) return;
  if (m.kind == MoveKind::Rapid) {
    done = true;
    return;
  }
  if (elements == 0) {
    first = m;
    first_where = where;
  }
  last = m;
  last_where = where;
  ++elements;
}

void Compensator::fail(SourcePlace where, const std::string& message) const {
  throw toolpath::InputError({file_, where.line, where.column}, message);
}

Eigen::Vector3d Compensator::lift(const Eigen::Vector2d& p, double normal_value) const {
  const PlaneAxes a = axes_of(plane_);
  Eigen::Vector3d r;
  r[a.first] = p.x();
  r[a.second] = p.y();
  r[a.normal] = normal_value;
  return r;
}

void Compensator::start(int side, double radius, Plane plane, bool entry_rule, Emitter& out) {
  if (active()) end_chain(out);  // a new side or radius starts a new chain
  else position_known_ = false;
  side_ = side;
  offset_ = side * radius;
  plane_ = plane;
  entry_rule_ = entry_rule;
  phase_ = Phase::Loose;
}

void Compensator::stop(Emitter& out) {
  if (!active()) return;
  end_chain(out);
  side_ = 0;
  position_known_ = false;
}

OffsetElement Compensator::element(const Move& m, SourcePlace where) const {
  const Eigen::Vector2d a = flat(m.from), b = flat(m.to);
  if (m.kind != MoveKind::Arc) return offset_line(a, b, offset_);
  const Eigen::Vector2d c = flat(m.centre);
  const OffsetElement e = offset_arc(a, b, c, m.direction == Direction::CCW, m.sweep, offset_);
  if (e.radius < -point_tolerance_)
    fail(where, fmt::format("arc radius {} is smaller than the compensation radius {} on the inside of the arc: "
                            "the tool does not fit (section 8.1)",
                            clean((a - c).norm()), clean(std::abs(offset_))));
  return e;
}

void Compensator::emit(Move m, const Frame& frame, const Eigen::Vector3d& to, bool compensated, Emitter& out) {
  if (m.kind != MoveKind::Arc && (to - position_).norm() < kMinMotion) return;
  m.programmed = m.to;
  m.from = position_;
  m.to = to;
  m.compensated = compensated;
  position_ = to;
  out.move(m, frame);
}

void Compensator::move(const Move& m, const Frame& frame, SourcePlace where, bool compensable, Emitter& out,
                       Diagnostics& diag) {
  if (!compensable || (m.kind == MoveKind::Arc && m.plane != plane_)) {
    end_chain(out);
    if (warned_line_ != where.line) {
      warned_line_ = where.line;
      diag.add(where.line, where.column,
               "only G0, G1, G2 and G3 in the compensation plane are compensated (section 8.1): this move is not");
    }
    out.move(m, frame);
    position_ = m.to;
    position_known_ = !m.in_work;
    return;
  }
  if (!position_known_) {
    position_ = m.from;
    position_known_ = true;
  }
  if (phase_ == Phase::Approaching) resolve_approach(ChainPreview{plane_}, out);  // not previewed: no chain
  const int normal = axes_of(plane_).normal;
  if (!moves_in_plane(m, plane_)) {
    if (phase_ == Phase::Entry || phase_ == Phase::Chain) {
      if (between_.size() < kMaxBetween) {
        out.reserve();
        between_.push_back({m, frame, where});
        return;
      }
      diag.add(where.line, where.column,
               fmt::format("more than {} moves along the plane normal in a compensated contour: the contour ends here", kMaxBetween));
      end_chain(out);
    }
    // along the normal at the current (offset) position
    const bool moved = (flat(position_) - flat(m.to)).norm() > kMinMotion;
    emit(m, frame, lift(flat(position_), m.to[normal]), moved, out);
    return;
  }
  if (m.kind == MoveKind::Rapid) {
    end_chain(out);
    if (entry_rule_) {  // G18: rapids stay on the programmed path; a G1 entry move leads in
      emit(m, frame, m.to, false, out);
      return;
    }
    out.reserve();
    pending_ = {m, frame, where};
    phase_ = Phase::Approaching;
    return;
  }
  next_element({m, frame, where}, out, diag);
}

void Compensator::resolve_approach(const ChainPreview& preview, Emitter& out) {
  phase_ = Phase::Loose;
  Eigen::Vector2d target = flat(pending_.move.to);
  bool moved = false;
  if (preview.elements > 0) {
    const OffsetElement f = element(preview.first, preview.first_where);
    target = f.start;
    first_start_ = 0.0;
    closing_ = false;
    if (preview.elements > 1) {
      // The end-of-contour rule: the first and the last element cut each other where they cross.
      const OffsetElement l = element(preview.last, preview.last_where);
      const Crossings x = intersect(f, l);
      const Eigen::Vector2d first_start = flat(preview.first.from), first_end = flat(preview.first.to);
      std::optional<double> best;
      for (std::size_t i = 0; i < x.count; ++i) {
        const Eigen::Vector2d& p = x.point[i];
        const double tf = f.param(p, 0.0), tl = l.param(p, l.end_param());
        if (f.distance(tf) < -kSamePoint || f.distance(f.end_param() - tf) <= kSamePoint) continue;
        if (l.distance(tl) <= kSamePoint || l.distance(l.end_param() - tl) < -kSamePoint) continue;
        // two elements also cross at their own corner: that crossing is not the closing one
        if (preview.elements == 2 && (p - first_end).norm() < (p - first_start).norm()) continue;
        if (!best || tf < *best) {
          best = tf;
          closing_point_ = p;
        }
      }
      if (best) {
        closing_ = true;
        first_start_ = *best;
        target = closing_point_;
      }
    }
    preview_elements_ = preview.elements;
    moved = true;
    phase_ = Phase::Approached;
  }
  out.begin_fill();
  emit(pending_.move, pending_.frame, lift(target, pending_.move.to[axes_of(plane_).normal]), moved, out);
  out.end_fill();
}

void Compensator::next_element(const Held& h, Emitter& out, Diagnostics& diag) {
  const OffsetElement e = element(h.move, h.where);
  const int normal = axes_of(plane_).normal;
  if (e.arc && e.radius <= point_tolerance_) {
    // The arc's radius is the tool's on its inside: the tool only turns on the centre, which is
    // where the offset neighbours end and start. What is left is the arc's move along the normal.
    Move pivot = h.move;
    pivot.kind = MoveKind::Feed;
    pivot.from = pivot.to;
    if (phase_ == Phase::Entry || phase_ == Phase::Chain) {
      out.reserve();
      between_.push_back({pivot, h.frame, h.where});
    } else {
      emit(pivot, h.frame, lift(flat(position_), h.move.to[normal]), true, out);
    }
    return;
  }
  switch (phase_) {
    case Phase::Chain:
      corner(h, e, out);
      ++chain_elements_;
      return;
    case Phase::Approached:  // the approach rapid already went to this element's start
      pending_start_ = first_start_;
      break;
    case Phase::Entry:  // the entry move ends where the element's offset path starts
      finish_entry(e.start, true, out);
      pending_start_ = 0.0;
      break;
    case Phase::Loose:
    case Phase::Approaching:
      if (h.move.kind != MoveKind::Arc) {
        if (!entry_rule_)
          diag.add(h.where.line, h.where.column,
                   "compensated contour without a G0 approach: this move is its entry move (section 8.2 rule)");
        out.reserve();
        pending_ = h;
        phase_ = Phase::Entry;
        return;
      }
      diag.add(h.where.line, h.where.column,
               "compensated contour starts with an arc: a straight feed to its offset start is inserted");
      {
        Move bridge = h.move;
        bridge.kind = MoveKind::Feed;
        bridge.to = h.move.from;
        emit(bridge, h.frame, lift(e.start, h.move.from[normal]), true, out);
      }
      pending_start_ = 0.0;
      break;
  }
  if (phase_ != Phase::Approached) closing_ = false;
  out.reserve();
  pending_ = h;
  pending_elem_ = e;
  chain_elements_ = 1;
  phase_ = Phase::Chain;
}

void Compensator::corner(const Held& next, const OffsetElement& e, Emitter& out) {
  const OffsetElement& a = pending_elem_;
  const Eigen::Vector2d corner_point = flat(next.move.from);  // the pending end, unless an arc shrank to a point
  double a_end = a.end_param();
  Eigen::Vector2d a_point = a.end;
  double b_start = 0.0;
  bool joining_arc = false;
  if ((a.end - e.start).norm() >= kSamePoint) {
    if (offset_ * cross2(a.end_tangent(), e.start_tangent()) > 0) {
      // inside corner: the offset elements overlap; both end where they cross
      const Crossings x = intersect(a, e);
      if (x.count == 0)
        fail(next.where, "the offset elements do not meet at this inside corner: the compensation radius is too large "
                         "for it (section 8.1)");
      Eigen::Vector2d p = x.point[0];
      if (x.count == 2 && (x.point[1] - corner_point).norm() < (p - corner_point).norm()) p = x.point[1];
      a_end = a.param(p, a.end_param());
      a_point = p;
      b_start = e.param(p, 0.0);
      if (e.distance(e.end_param() - b_start) < -kSamePoint)
        fail(next.where, "element too short for the compensation radius: its offset path disappears at the inside "
                         "corner (section 8.1)");
    } else {
      joining_arc = true;  // outside corner: an arc of the compensation radius around the corner
    }
  }
  finish_pending(a_end, a_point, out);
  if (joining_arc) {
    Move arc = next.move;
    arc.kind = MoveKind::Arc;
    arc.plane = plane_;
    arc.direction = offset_ < 0 ? Direction::CCW : Direction::CW;
    arc.centre = lift(corner_point, position_[axes_of(plane_).normal]);
    const Eigen::Vector3d from = lift(a.end, 0.0), to = lift(e.start, 0.0), around = lift(corner_point, 0.0);
    // a corner turns by less than a full circle, even where its ends meet (sweep hint 0)
    arc.sweep = toolpath::geometry::make_arc(from, to, around, plane_, arc.direction, 0.0).sweep;
    arc.to = next.move.from;
    emit(arc, next.frame, lift(e.start, position_[axes_of(plane_).normal]), true, out);
  }
  out.reserve();
  pending_ = next;
  pending_elem_ = e;
  pending_start_ = b_start;
}

void Compensator::finish_pending(double end_param, const Eigen::Vector2d& end_point, Emitter& out) {
  const OffsetElement& e = pending_elem_;
  const double span = end_param - pending_start_;
  if (e.distance(span) < -kSamePoint)
    fail(pending_.where, "element too short for the compensation radius: its offset path reverses (section 8.1)");
  out.begin_fill();
  if (e.distance(span) > kMinMotion) {
    Move m = pending_.move;
    const Eigen::Vector3d to = lift(end_point, m.to[axes_of(plane_).normal]);
    if (m.kind == MoveKind::Arc) {
      m.centre = lift(e.centre, position_[axes_of(plane_).normal]);
      m.sweep = span;
    }
    emit(m, pending_.frame, to, true, out);
  }
  out.end_fill();
  release_between(out);
}

void Compensator::finish_entry(const Eigen::Vector2d& end_point, bool compensated, Emitter& out) {
  out.begin_fill();
  emit(pending_.move, pending_.frame, lift(end_point, pending_.move.to[axes_of(plane_).normal]), compensated, out);
  out.end_fill();
  release_between(out);
}

void Compensator::release_between(Emitter& out) {
  const int normal = axes_of(plane_).normal;
  for (const Held& h : between_) {
    out.begin_fill();
    const bool moved = (flat(position_) - flat(h.move.to)).norm() > kMinMotion;
    emit(h.move, h.frame, lift(flat(position_), h.move.to[normal]), moved, out);
    out.end_fill();
  }
  between_.clear();
}

void Compensator::end_chain(Emitter& out) {
  switch (phase_) {
    case Phase::Approaching:
      out.begin_fill();
      emit(pending_.move, pending_.frame, pending_.move.to, false, out);
      out.end_fill();
      break;
    case Phase::Entry:  // an entry move with nothing after it stays on its programmed path
      finish_entry(flat(pending_.move.to), false, out);
      break;
    case Phase::Chain: {
      const OffsetElement& e = pending_elem_;
      if (closing_ && chain_elements_ == preview_elements_ && chain_elements_ > 1)
        finish_pending(e.param(closing_point_, e.end_param()), closing_point_, out);
      else
        finish_pending(e.end_param(), e.end, out);
      break;
    }
    case Phase::Loose:
    case Phase::Approached:
      break;
  }
  phase_ = Phase::Loose;
  closing_ = false;
  chain_elements_ = preview_elements_ = 0;
}

}  // namespace pikocnc
