// Canned cycles G81, G83, G84, G74, G74.1 (section 6), expanded into their documented steps; the
// lathe threading cycle G76 (6.6) and the probing cycles of G65 (section 11).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "machines/pikocnc/model/interpreter_detail.hpp"

namespace pikocnc {

void Interpreter::cycle_rapid_z(double z) {
  Eigen::Vector3d p = s_.prog;
  p.z() = z;
  straight(MoveKind::Rapid, p, s_.prog_a, s_.prog_b);
}

void Interpreter::cycle_feed_z(double z) {
  Eigen::Vector3d p = s_.prog;
  p.z() = z;
  straight(MoveKind::Feed, p, s_.prog_a, s_.prog_b);
}

void Interpreter::cycle(Op op, bool programmed, Words& w) {
  if (w.free('Z')) {
    s_.cycle_z = w.len_plain('Z');  // Z and R are absolute levels, also in G91
    s_.cycle_has_z = true;
  }
  if (w.free('R')) {
    s_.cycle_r = w.len_plain('R');
    s_.cycle_has_r = true;
  }
  if ((op == Op::G83 || op == Op::G84) && w.free('Q')) {
    s_.cycle_q = w.len_plain('Q');
    s_.cycle_has_q = true;
  }
  if ((op == Op::G74 || op == Op::G74_1) && w.free('P')) s_.cycle_p = w.raw('P');
  const bool hole_words = w.free('X') || w.free('Y') || (options_.dialect == Dialect::V2025 && (w.free('U') || w.free('V')));
  if (!programmed && !hole_words) return;
  if (programmed && (op == Op::G74 || op == Op::G74_1)) emitter_.add("@override_reset");
  w.r.cycle_in_line = true;
  if (w.r.has(Op::G98) || !s_.clearance_known) {  // the travel height is the Z where G98 is read
    s_.clearance_z = s_.prog.z();
    s_.clearance_known = true;
  }
  Eigen::Vector3d hole = s_.prog;
  const bool uv = options_.dialect == Dialect::V2025;
  for (int i = 0; i < 2; ++i) {
    const char l = "XY"[i], u = "UV"[i];
    if (w.free(l)) {
      const double v = w.len(l);
      hole[i] = s_.incremental ? s_.prog[i] + v : v;
    } else if (uv && w.free(u)) {
      hole[i] = s_.prog[i] + w.len(u);
    }
  }
  if (!s_.cycle_has_z) {
    warn(1, "canned cycle without a Z depth: hole skipped");
    return;
  }
  if (!s_.cycle_has_r) {
    warn(1, "canned cycle without R: R is the clearance height");
    s_.cycle_r = s_.clearance_z;
    s_.cycle_has_r = true;
  }
  if (op == Op::G84 && !s_.cycle_has_q) fail(1, "G84 needs Q (the fast retract distance above the bottom)");
  cycle_hole(op, hole);
}

void Interpreter::cycle_hole(Op op, const Eigen::Vector3d& hole) {
  const double r = s_.cycle_r, z = s_.cycle_z, clearance = s_.clearance_z;
  const double down = z < r ? -1.0 : 1.0;
  const double travel = s_.return_to_r ? r : clearance;
  Eigen::Vector3d at = hole;
  at.z() = s_.prog.z();
  straight(MoveKind::Rapid, at, s_.prog_a, s_.prog_b);  // XY at the current height
  switch (op) {
    case Op::G81:
      cycle_rapid_z(r);
      cycle_feed_z(z);
      cycle_rapid_z(r);
      if (!s_.return_to_r) cycle_rapid_z(clearance);
      break;
    case Op::G83: {
      cycle_rapid_z(r);
      const double q = s_.cycle_q;
      if (!s_.cycle_has_q || q <= 0) {
        warn(1, "G83 without a positive Q: drilled in one pass");
        cycle_feed_z(z);
        cycle_rapid_z(r);
      } else {
        if (std::abs(z - r) / q > 1e6) fail(1, "G83 Q is so small that the hole needs more than a million pecks");
        for (long n = 0;; ++n) {
          cycle_rapid_z(r + down * static_cast<double>(n) * q);
          double next = r + down * static_cast<double>(n + 1) * q;
          const bool last = down < 0 ? next <= z : next >= z;
          if (last) next = z;
          cycle_feed_z(next);
          cycle_rapid_z(r);
          if (last) break;
        }
      }
      if (!s_.return_to_r) cycle_rapid_z(clearance);
      break;
    }
    case Op::G84:
      cycle_rapid_z(r);
      cycle_feed_z(z);
      cycle_rapid_z(z - down * s_.cycle_q);
      cycle_feed_z(travel);
      break;
    case Op::G74: case Op::G74_1: {
      const int forward = op == Op::G74 ? 3 : 4, reverse = op == Op::G74 ? 4 : 3;
      spindle_event(forward);
      cycle_rapid_z(r);
      cycle_feed_z(z);
      spindle_event(5);
      if (s_.cycle_p > 0) {
        emitter_.add("@delay");
        emitter_.number("delay_period", s_.cycle_p);
      }
      spindle_event(reverse);
      cycle_feed_z(r);
      if (!s_.return_to_r) cycle_rapid_z(clearance);
      spindle_event(5);
      break;
    }
    default: break;
  }
}

void Interpreter::lathe_thread(Words& w) {
  for (char l : {'P', 'Z', 'I', 'J', 'K'})
    if (!w.owned(l)) fail(w.r.column(Op::G76), fmt::format("G76 needs {}", l));
  const double pitch = w.len_plain('P');
  const double xs = s_.prog.x(), zs = s_.prog.z();
  const double z_word = w.len_plain('Z');
  const double z_end = s_.incremental ? zs + z_word : z_word;
  const double half = s_.diameter ? 0.5 : 1.0;
  const double r0 = w.len_plain('I') * half;
  const double step = w.len_plain('J'), depth = w.len_plain('K');
  const double angle = w.owned('Q') ? w.raw('Q') * std::numbers::pi / 180.0 : 0.0;
  const double taper = w.owned('R') ? w.len_plain('R') * half : 0.0;
  if (step <= 0 || depth <= 0) {
    warn(w.col('J'), "G76 needs positive J and K: no motion");
    return;
  }
  const double side = xs > r0 ? -1.0 : 1.0;
  const double away = zs > z_end ? 1.0 : zs < z_end ? -1.0 : 0.0;
  const double pass_count = std::ceil(depth / step - 1e-12);
  if (!(pass_count <= 100000)) fail(w.col('J'), "G76 J is so small that the thread needs more than 100000 passes");
  const long passes = static_cast<long>(pass_count);
  for (long k = 1; k <= passes; ++k) {
    const double d = std::min(static_cast<double>(k) * step, depth);
    auto go = [&](MoveKind kind, double x, double z) {
      Eigen::Vector3d p = s_.prog;
      p.x() = x;
      p.z() = z;
      straight(kind, p, s_.prog_a, s_.prog_b);
    };
    go(MoveKind::Rapid, xs, zs + d * std::tan(angle) * away);
    go(MoveKind::Rapid, r0 + side * d + taper, s_.prog.z());
    const double feed = s_.feed;
    s_.feed = pitch * s_.spindle;
    Eigen::Vector3d p = s_.prog;
    p.x() = r0 + side * d;
    p.z() = z_end;
    thread_pitch_ = pitch;
    straight(MoveKind::Thread, p, s_.prog_a, s_.prog_b);
    s_.feed = feed;
    go(MoveKind::Rapid, xs, z_end);
    go(MoveKind::Rapid, xs, zs);
  }
}

void Interpreter::probe(Words& w) {
  if (!w.owned('P')) fail(w.r.column(Op::G65), "G65 needs P (the probing cycle number)");
  const int cycle = int_word(w.raw('P'));
  if (cycle == 9810) {  // protected positioning: a feed move that stops on contact
    Eigen::Vector3d to = s_.prog;
    for (int i = 0; i < 3; ++i)
      if (w.owned("XYZ"[i])) {
        const double v = w.len("XYZ"[i]);
        to[i] = s_.incremental ? s_.prog[i] + v : v;
      }
    const double feed = s_.feed;
    if (w.owned('F')) s_.feed = w.len_plain('F');
    probe_protected_ = true;
    straight(MoveKind::Feed, to, s_.prog_a, s_.prog_b);
    probe_protected_ = false;
    s_.feed = feed;
    return;
  }
  static constexpr int kKnown[] = {9801, 9802, 9803, 9811, 9812, 9814, 9815, 9816};
  if (std::find(std::begin(kKnown), std::end(kKnown), cycle) == std::end(kKnown)) {
    warn(w.col('P'), fmt::format("G65 P{} is not a documented probing cycle: ignored", cycle));
    return;
  }
  emitter_.add("@probe");
  emitter_.integer("cycle", cycle);
  std::string args;
  for (char l : std::string_view("XYZDQRSWF")) {
    if (!w.owned(l)) continue;
    const double v = w.raw(l);
    args += fmt::format("{}{}{}", args.empty() ? "" : " ", l, v);
  }
  emitter_.text("args", args);
  // With S the measured base S := active base + error; the simulator measures no error.
  if (!w.b.has('S')) return;
  const int s = int_word(w.b.get('S'));
  if (s < 1 || s > 6) {
    warn(w.col('S'), fmt::format("G65 S{} is not a work offset 1..6: no correction", s));
    return;
  }
  emitter_.integer("corrects_base", 53 + s);
  bool axis[2] = {false, false};
  if (cycle == 9811 || cycle == 9812) {
    axis[0] = w.b.has('X');
    axis[1] = w.b.has('Y');
  } else if (cycle == 9814 || cycle == 9815 || cycle == 9816) {
    axis[0] = axis[1] = true;
  }
  const Axes5 active = s_.bases[static_cast<std::size_t>(s_.work_offset)];
  for (std::size_t i = 0; i < 2; ++i)
    if (axis[i]) s_.bases[static_cast<std::size_t>(s - 1)][i] = active[i];
  if (cycle == 9811 && w.b.has('Z')) s_.bases[static_cast<std::size_t>(s - 1)][2] = active[2];
}

}  // namespace pikocnc
