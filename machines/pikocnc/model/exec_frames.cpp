// Step 13 and 14 of a line: work offsets (G54-G59, G10 family), program offsets (G52, G92, G92.1)
// and the transformation stack (G51, G68, G68.2, G69, G69.1), with the position bookkeeping of
// section 4.1: nothing moves, the program position is derived again from the tool position.
#include <fmt/format.h>

#include <cmath>

#include "machines/pikocnc/model/interpreter_detail.hpp"

namespace pikocnc {

const Frame& Interpreter::frame() const {
  if (!frame_dirty_) return frame_;
  frame_dirty_ = false;
  Frame& f = frame_;
  f.identity = s_.transforms.empty();
  f.m = s_.transforms.composite();
  f.off = {s_.program_offset[0], s_.program_offset[1], s_.program_offset[2]};
  f.off_a = s_.program_offset[3];
  f.off_b = s_.program_offset[4];
  return f;
}

Axes5 Interpreter::work_position() const {
  Axes5 w;
  const Axes5& base = s_.bases[static_cast<std::size_t>(s_.work_offset)];
  for (std::size_t i = 0; i < 5; ++i) w[i] = s_.tip[i] - base[i];
  return w;
}

void Interpreter::recompute_program_position() {
  frame_dirty_ = true;
  const Axes5 w = work_position();
  const Eigen::Vector3d p(w[0] - s_.program_offset[0], w[1] - s_.program_offset[1], w[2] - s_.program_offset[2]);
  if (s_.transforms.empty()) {
    s_.prog = p;
  } else {
    const Eigen::Matrix3d a = s_.transforms.composite().linear();
    if (std::abs(a.determinant()) < 1e-12) {
      warn(0, "the transformation is singular (a zero scale factor): the program position is kept");
    } else {
      s_.prog = a.inverse() * (p - s_.transforms.composite().translation());
    }
  }
  s_.prog_a = w[3] - s_.program_offset[3];
  s_.prog_b = w[4] - s_.program_offset[4];
}

void Interpreter::set_tool_offset(const Axes5& offset) {
  for (std::size_t i = 0; i < 5; ++i) s_.tip[i] += offset[i] - s_.tool_offset[i];  // the holder stays put
  s_.tool_offset = offset;
  recompute_program_position();
}

void Interpreter::offsets(const Resolved& r, Words& w) {
  static constexpr Op kBases[] = {Op::G54, Op::G55, Op::G56, Op::G57, Op::G58, Op::G59};
  for (int i = 0; i < 6; ++i) {
    if (!r.has(kBases[i]) || s_.work_offset == i) continue;
    s_.work_offset = i;
    recompute_program_position();
    emitter_.add("@home_number");
    emitter_.integer("home_number", 54 + i);
  }
  auto axis_value = [&](int i) { return i < 3 ? w.len("XYZAB"[i]) : w.raw("XYZAB"[i]); };
  if (r.has(Op::G10) || r.has(Op::G10_1) || r.has(Op::G10_2)) {
    const Op op = r.owner;
    int index = s_.work_offset;
    if (w.owned('P')) {
      const double p = w.raw('P');
      if (p < 54 || p > 59 || p != std::floor(p)) {
        warn(w.col('P'), fmt::format("G10 P{} is not a work offset 54..59: ignored", p));
        return;
      }
      index = static_cast<int>(p) - 54;
    }
    Axes5 from{};
    if (op == Op::G10_1) from = s_.tip;
    if (op == Op::G10_2) {
      if (!w.owned('Q')) fail(r.column(op), "G10.2 needs Q (the PARK number)");
      const int q = int_word(w.raw('Q'));
      const auto it = options_.parks.find(q);
      if (it == options_.parks.end()) {
        warn(w.col('Q'), fmt::format("PARK {} is not configured: G10.2 ignored", q));
        return;
      }
      from = it->second;
    }
    Axes5& base = s_.bases[static_cast<std::size_t>(index)];
    for (int i = 0; i < 5; ++i)
      if (w.owned("XYZAB"[i])) base[static_cast<std::size_t>(i)] = from[static_cast<std::size_t>(i)] + axis_value(i);
    if (index == s_.work_offset) recompute_program_position();
  }
  if (r.owner == Op::G52) {
    for (int i = 0; i < 5; ++i)
      if (w.owned("XYZAB"[i])) s_.program_offset[static_cast<std::size_t>(i)] = axis_value(i);
    recompute_program_position();
  }
  if (r.owner == Op::G92) {
    if (!s_.transforms.empty()) warn(r.column(Op::G92), "G92 under a transformation: offsets computed untransformed");
    const Axes5 here = work_position();
    for (int i = 0; i < 5; ++i)
      if (w.owned("XYZAB"[i])) s_.program_offset[static_cast<std::size_t>(i)] = here[static_cast<std::size_t>(i)] - axis_value(i);
    recompute_program_position();
  }
  if (r.has(Op::G92_1)) {
    s_.program_offset = Axes5{};
    recompute_program_position();
  }
}

void Interpreter::transforms(const Resolved& r, Words& w) {
  if (r.transform_order.empty()) return;
  const Eigen::Vector3d before = s_.prog;
  auto centre = [&] {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i)
      if (w.owned("XYZ"[i])) c[i] = w.len_plain("XYZ"[i]);
    return c;
  };
  for (Op op : r.transform_order) {
    const bool owns = r.owner == op;
    if ((op == Op::G51 || op == Op::G68 || op == Op::G68_2) && !owns) {
      warn(r.column(op), "a second transformation in the same line gets no words: ignored");
      continue;
    }
    switch (op) {
      case Op::G69: s_.transforms.clear(); break;
      case Op::G69_1:
        if (!s_.transforms.pop()) warn(r.column(op), "G69.1 with no transformation active");
        break;
      case Op::G51: {
        Eigen::Vector3d f(1, 1, 1);
        if (w.owned('P')) {
          f.setConstant(w.raw('P'));
          for (char l : {'I', 'J', 'K'}) if (w.owned(l)) w.raw(l);  // P wins over I J K
        } else {
          for (int i = 0; i < 3; ++i) if (w.owned("IJK"[i])) f[i] = w.raw("IJK"[i]);
        }
        s_.transforms.push(scaling(centre(), f));
        break;
      }
      case Op::G68:
        if (!w.owned('R')) fail(r.column(op), "G68 needs R (the angle)");
        s_.transforms.push(rotation(centre(), s_.plane, w.raw('R')));
        break;
      case Op::G68_2: {
        const int mode = w.owned('P') ? int_word(w.raw('P')) : 0;
        const int order = w.owned('Q') ? int_word(w.raw('Q')) : 123;
        Eigen::Vector3d angles = Eigen::Vector3d::Zero();
        for (int i = 0; i < 3; ++i) if (w.owned("IJK"[i])) angles[i] = w.raw("IJK"[i]);
        const auto t = tilted_plane(mode, order, angles, centre());
        if (!t) {
          warn(r.column(op), fmt::format("G68.2 P{} Q{} is not a documented mode: ignored", mode, order));
          break;
        }
        s_.transforms.push(*t);
        break;
      }
      default: break;
    }
  }
  recompute_program_position();
  transform_changed_axes_ = 0;
  for (int i = 0; i < 3; ++i)
    if (std::abs(s_.prog[i] - before[i]) > 1e-9) transform_changed_axes_ |= 1u << i;
}

}  // namespace pikocnc
