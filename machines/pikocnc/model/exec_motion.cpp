// Step 18 of a line: the motion. Straight moves, arcs (section 5), machine moves and homing (4.5),
// threads, probing moves, macros. Canned cycles are in exec_cycles.cpp.
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <utility>

#include "machines/pikocnc/model/interpreter_detail.hpp"

namespace pikocnc {
namespace {

struct Target {
  Eigen::Vector3d p;
  double a, b;
  std::uint32_t programmed = 0;  // bit i: program axis i (X Y Z) was written
};

}  // namespace

void Interpreter::put(Move& m) {
  const bool compensable = !m.in_work && !uncompensable_ && m.kind != MoveKind::Thread;
  if (previewing_) {
    preview_.take(m, compensable, {line_, motion_column_});
  } else if (!compensator_.active()) {
    emitter_.move(m, frame());
  } else {
    compensator_.move(m, frame(), {line_, motion_column_}, compensable, emitter_, diagnostics_);
  }
}

Eigen::Vector3d Interpreter::target(Words& w, bool incremental_words, bool allow_uvw) {
  Eigen::Vector3d t = s_.prog;
  const bool uvw = allow_uvw && options_.dialect == Dialect::V2025;
  std::uint32_t programmed = 0;
  for (int i = 0; i < 3; ++i) {
    const char l = "XYZ"[i], u = "UVW"[i];
    if (w.free(l)) {
      if (uvw && w.free(u)) {
        warn(w.col(u), fmt::format("{} and {} in one line: {} is used", l, u, l));
        w.raw(u);
      }
      const double v = w.len(l);
      t[i] = incremental_words || s_.incremental ? s_.prog[i] + v : v;
      programmed |= 1u << i;
    } else if (uvw && w.free(u)) {
      t[i] = s_.prog[i] + w.len(u);
      programmed |= 1u << i;
    }
  }
  programmed_axes_ = programmed;
  const std::uint32_t affected = transform_changed_axes_ & programmed;
  if (affected) {
    if (affected != transform_changed_axes_)
      warn(motion_column_, "first move after a transformation does not program every axis the transformation moved (section 10.6)");
    transform_changed_axes_ = 0;
  }
  return t;
}

void Interpreter::straight(MoveKind kind, const Eigen::Vector3d& to, double a, double b) {
  // With compensation on, a rapid that writes an axis of the plane approaches the next contour even
  // when the programmed point is where the tool is (its offset point is not).
  const std::uint32_t written = std::exchange(programmed_axes_, 0u);
  bool approach = false;
  if (kind == MoveKind::Rapid && compensator_.active()) {
    const PlaneAxes ax = axes_of(compensator_.plane());
    approach = (written & ((1u << ax.first) | (1u << ax.second))) != 0;
  }
  if ((to - s_.prog).norm() < 1e-12 && a == s_.prog_a && b == s_.prog_b && !approach) return;  // zero length: not emitted
  Move m;
  m.plane_words = approach;
  m.kind = kind;
  m.from = s_.prog;
  m.to = to;
  const Frame& f = frame();
  m.a = a + f.off_a;
  m.b = b + f.off_b;
  m.feed = s_.feed;
  m.pitch = thread_pitch_;
  m.protected_move = probe_protected_;
  s_.prog = to;
  s_.prog_a = a;
  s_.prog_b = b;
  const Eigen::Vector3d work = f.to_work(to);
  const Axes5& base = s_.bases[static_cast<std::size_t>(s_.work_offset)];
  for (int i = 0; i < 3; ++i) s_.tip[static_cast<std::size_t>(i)] = base[static_cast<std::size_t>(i)] + work[i];
  s_.tip[3] = base[3] + m.a;
  s_.tip[4] = base[4] + m.b;
  put(m);
}

void Interpreter::motion(const Resolved& r, Words& w) {
  switch (r.owner) {
    case Op::G53: case Op::G53_1:
      if (r.has(Op::G1) || r.has(Op::G0)) {
        s_.motion = r.has(Op::G1) ? Op::G1 : Op::G0;
        s_.cycle_active = false;
      }
      machine_move(r.owner == Op::G53_1, r.has(Op::G1), w);
      return;
    case Op::G28: home(options_.home1); return;
    case Op::G30: home(options_.home2); return;
    case Op::G65:
      uncompensable_ = true;
      probe(w);
      uncompensable_ = false;
      return;
    case Op::G76:
      uncompensable_ = true;
      lathe_thread(w);
      uncompensable_ = false;
      return;
    case Op::Macro: {
      emitter_.add("@macro");
      emitter_.text("name", fmt::format("G{}", r.macro.number));
      if (r.macro.dot_digits) emitter_.integer("dot_value", r.macro.dot);
      std::string args;
      for (char l : std::string_view("XYZABFPQ")) {
        if (!w.owned(l)) continue;
        const double v = w.raw(l);
        args += fmt::format("{}{}{}", args.empty() ? "" : " ", l, v);
        emitter_.number(fmt::format("arg_{}", static_cast<char>(l | 0x20)), v);
      }
      emitter_.text("args", args);
      return;
    }
    case Op::Unknown: break;
    default: return;  // the line's words belong to a code that allows no motion
  }
  motion_column_ = r.motion != Op::Unknown ? r.column(r.motion) : 1;
  if (r.motion == Op::G80) {
    if (s_.cycle_active) s_.motion = s_.motion_before_cycle;
    s_.cycle_active = false;
    return;
  }
  if (r.motion != Op::Unknown) {
    if (is_cycle(r.motion)) {
      if (!s_.cycle_active) s_.motion_before_cycle = s_.motion;
      s_.cycle_active = true;
    } else {
      s_.cycle_active = false;
    }
    s_.motion = r.motion;
  }
  if (s_.cycle_active) {
    uncompensable_ = true;
    cycle(s_.motion, r.motion != Op::Unknown, w);
    uncompensable_ = false;
    return;
  }
  if (!w.any_free(letters("XYZABUVWIJKR"))) return;
  switch (s_.motion) {
    case Op::G0: case Op::G1: case Op::G0_1: case Op::G1_1: {
      const bool incremental = s_.motion == Op::G0_1 || s_.motion == Op::G1_1;
      const Eigen::Vector3d to = target(w, incremental, !incremental);
      double a = s_.prog_a, b = s_.prog_b;
      if (w.free('A')) {
        emitter_.use_a();
        const double v = w.raw('A');
        a = incremental || s_.incremental ? a + v : v;
      }
      if (w.free('B') && options_.dialect == Dialect::V2025) {
        emitter_.use_b();
        const double v = w.raw('B');
        b = incremental || s_.incremental ? b + v : v;
      }
      const bool rapid = s_.motion == Op::G0 || s_.motion == Op::G0_1;
      if (!rapid && s_.feed <= 0) warn(motion_column_, "feed move without a feed rate (F)");
      straight(rapid ? MoveKind::Rapid : MoveKind::Feed, to, a, b);
      return;
    }
    case Op::G2: case Op::G3: arc(s_.motion == Op::G3, w); return;
    case Op::G33: {
      if (!w.free('K')) fail(motion_column_, "G33 needs K (the thread pitch)");
      const double pitch = w.len_plain('K');
      const Eigen::Vector3d to = target(w, false, false);
      const double feed = s_.feed;
      thread_pitch_ = pitch;
      s_.feed = pitch * s_.spindle;  // nominal feed in rpm mode
      straight(MoveKind::Thread, to, s_.prog_a, s_.prog_b);
      s_.feed = feed;
      return;
    }
    default: return;
  }
}

void Interpreter::arc(bool ccw, Words& w) {
  const Plane plane = options_.dialect == Dialect::V2016 ? Plane::XY : s_.plane;
  const PlaneAxes ax = axes_of(plane);
  const Direction direction = ccw ? Direction::CCW : Direction::CW;
  const Eigen::Vector3d start = s_.prog;
  const Eigen::Vector3d end = target(w, false, false);
  const Eigen::Vector2d s2 = in_plane(start, plane), e2 = in_plane(end, plane);
  Eigen::Vector2d c2;
  const char centre_letters[3] = {'I', 'J', 'K'};
  const char first = centre_letters[ax.first], second = centre_letters[ax.second];
  const bool dialect_k = options_.dialect == Dialect::V2025;
  if (w.free('R')) {
    const double r = w.len_plain('R');
    for (char l : {first, second}) if (w.free(l)) warn(w.col(l), "arc with both a centre and R: R is used");
    const auto c = toolpath::geometry::centre_from_radius(start, end, r, plane, direction, options_.arc_tolerance);
    if (!c) {
      if ((e2 - s2).norm() < 1e-12) fail(w.col('R'), "an arc given by R needs an end point different from its start");
      const std::string msg = fmt::format("arc radius {} does not fit its end points: the chord is {} long (more than 2R + {})",
                                          std::abs(r), (e2 - s2).norm(), options_.arc_tolerance);
      if (options_.strict_arcs) fail(w.col('R'), msg);
      warn(w.col('R'), msg + ": moved in a straight line");
      straight(MoveKind::Feed, end, s_.prog_a, s_.prog_b);
      return;
    }
    c2 = in_plane(*c, plane);
  } else {
    if (!w.free(first) && !w.free(second))
      fail(motion_column_, fmt::format("arc needs a centre ({}, {}) or a radius (R)", first, second));
    c2 = s2;
    if (w.free(first) && (first != 'K' || dialect_k)) c2.x() += w.len_plain(first);
    if (w.free(second) && (second != 'K' || dialect_k)) c2.y() += w.len_plain(second);
  }
  const double r0 = (s2 - c2).norm(), r1 = (e2 - c2).norm();
  if (r0 < 1e-9) fail(motion_column_, "arc with zero radius (its centre is its start point)");
  // An end point off the circle is a wrong program, like an R that cannot reach it (strict_arcs).
  if (std::abs(r1 - r0) > std::max(options_.arc_tolerance, 0.001 * r0)) {
    const std::string msg = fmt::format("arc end point is not on its circle: end radius {}, start radius {} (more than {} apart)",
                                        clean(r1), clean(r0), clean(std::max(options_.arc_tolerance, 0.001 * r0)));
    if (options_.strict_arcs) fail(motion_column_, msg);
    warn(motion_column_, msg + ": the start radius is used");
  }
  Move m;
  m.kind = MoveKind::Arc;
  m.from = start;
  m.to = end;
  m.centre = start;
  m.centre[ax.first] = c2.x();
  m.centre[ax.second] = c2.y();
  m.plane = plane;
  m.direction = direction;
  // equal start and end points: a full circle
  m.sweep = toolpath::geometry::make_arc(start, end, m.centre, plane, direction, std::nullopt).sweep;
  m.feed = s_.feed;
  if (s_.feed <= 0) warn(motion_column_, "arc without a feed rate (F)");
  const Frame& f = frame();
  m.a = s_.prog_a + f.off_a;
  m.b = s_.prog_b + f.off_b;
  s_.prog = end;
  const Eigen::Vector3d work = f.to_work(end);
  const Axes5& base = s_.bases[static_cast<std::size_t>(s_.work_offset)];
  for (int i = 0; i < 3; ++i) s_.tip[static_cast<std::size_t>(i)] = base[static_cast<std::size_t>(i)] + work[i];
  put(m);
}

void Interpreter::machine_move(bool tip_target, bool feed, Words& w) {
  const Axes5& base = s_.bases[static_cast<std::size_t>(s_.work_offset)];
  const Axes5 from_work = work_position();
  for (int i = 0; i < 5; ++i) {
    const char l = "XYZAB"[i];
    if (!w.owned(l)) continue;
    const double v = i < 3 ? w.len(l) : w.raw(l);
    s_.tip[static_cast<std::size_t>(i)] = tip_target ? v : v + s_.tool_offset[static_cast<std::size_t>(i)];
    if (i == 3) emitter_.use_a();
    if (i == 4) emitter_.use_b();
  }
  if (feed && w.owned('F')) s_.feed = w.len_plain('F');
  const Axes5 to_work = work_position();
  recompute_program_position();
  Move m;
  m.kind = feed ? MoveKind::Feed : MoveKind::Rapid;
  m.in_work = true;
  m.from = {from_work[0], from_work[1], from_work[2]};
  m.to = {to_work[0], to_work[1], to_work[2]};
  m.a = to_work[3];
  m.b = to_work[4];
  m.feed = s_.feed;
  (void)base;
  if ((m.to - m.from).norm() < 1e-12 && from_work[3] == to_work[3] && from_work[4] == to_work[4]) return;
  put(m);
}

void Interpreter::home(const Axes5& where) {
  // The tool axis (Z) alone first, then all the others together.
  for (int leg = 0; leg < 2; ++leg) {
    const Axes5 from = work_position();
    for (std::size_t i = 0; i < 5; ++i)
      if ((leg == 0) == (i == 2)) s_.tip[i] = where[i] + s_.tool_offset[i];
    const Axes5 to = work_position();
    Move m;
    m.kind = MoveKind::Rapid;
    m.in_work = true;
    m.from = {from[0], from[1], from[2]};
    m.to = {to[0], to[1], to[2]};
    m.a = to[3];
    m.b = to[4];
    if ((m.to - m.from).norm() > 1e-12 || from[3] != to[3] || from[4] != to[4]) put(m);
  }
  recompute_program_position();
}

}  // namespace pikocnc
