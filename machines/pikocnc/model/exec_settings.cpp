// Steps 3-17 of a line (section 2.3): feed and spindle, tool, M codes, dwell, modes, offsets and
// transformations. None of them moves the machine; offsets and transforms re-derive the program
// position from the unchanged tool position (section 4.1).
#include <fmt/format.h>

#include <cmath>

#include "machines/pikocnc/model/interpreter_detail.hpp"

namespace pikocnc {

void Interpreter::feed_and_spindle(const Resolved& r, Words& w) {
  bool changed = false;
  if (r.has(Op::G94) || r.has(Op::G95)) {
    const bool per_rev = r.has(Op::G95);
    changed |= per_rev != s_.per_rev;
    s_.per_rev = per_rev;
  }
  if (w.has('F') && !w.owned('F')) {
    s_.feed = w.len_plain('F');
    if (s_.feed <= 0) warn(w.col('F'), "F is not positive");
  }
  if (r.has(Op::G96) || r.has(Op::G97)) {
    const bool css = r.has(Op::G96);
    changed |= css != s_.css;
    s_.css = css;
  }
  if (r.has(Op::G50)) {
    if (!w.has('S')) fail(r.column(Op::G50), "G50 needs S (the spindle limit in rpm)");
    s_.css_limit = w.raw('S');
    changed = true;
  } else if (w.has('S') && !w.owned('S')) {
    const double s = w.raw('S');
    changed |= s != s_.spindle;
    s_.spindle = s;
  }
  if (!changed) return;
  emitter_.add("@m_feed_spin");
  emitter_.word("feed_unit", s_.per_rev ? "MM_REV" : "MM_MIN");
  emitter_.number("feed", s_.feed);
  emitter_.word("spin_unit", s_.css ? "CSS" : "RPM");
  emitter_.number("spin", s_.spindle);
  if (s_.css_limit > 0) emitter_.number("spin_limit", s_.css_limit);
}

void Interpreter::spindle_event(int m) {
  s_.spindle_m = m;
  if (m == 5) {
    emitter_.add("@stop_tool");
    emitter_.integer("mcode", 5);
    return;
  }
  emitter_.add("@start_tool");
  emitter_.word("spin_direction", m == 3 ? "CW" : "CCW");
  emitter_.number("spin", s_.spindle);
  emitter_.integer("mcode", m);
}

void Interpreter::tool_and_m_codes(const Resolved& r, Words& w) {
  const bool g43 = r.has(Op::G43) || r.has(Op::G43_1) || r.has(Op::G43_2);
  if (w.has('T') && !g43) {
    s_.selected_tool = int_word(w.raw('T'));
    if (s_.selected_tool < 0) warn(w.col('T'), "negative tool number");
  }
  if (r.has(Op::M6)) {
    if (!w.has('T')) warn(r.column(Op::M6), "M6 without T in its line (the documents require `M6 T..`)");
    if (s_.selected_tool < 0) {
      warn(r.column(Op::M6), "M6 with no tool selected: ignored");
    } else {
      if (options_.macro_m_codes.count(6)) {
        emitter_.add("@macro");
        emitter_.text("name", "M6");
        emitter_.integer("arg_t", s_.selected_tool);
      }
      s_.tool = s_.selected_tool;
      emitter_.add("@change_tool");
      emitter_.integer("tool_number", s_.tool);
      const auto it = options_.tools.find(s_.tool);
      set_tool_offset(it == options_.tools.end() ? Axes5{} : it->second.offset);
    }
  }
  for (Op op : {Op::M3, Op::M4, Op::M5}) {
    if (!r.has(op)) continue;
    const int m = op == Op::M3 ? 3 : op == Op::M4 ? 4 : 5;
    if (options_.macro_m_codes.count(m)) {
      emitter_.add("@macro");
      emitter_.text("name", fmt::format("M{}", m));
      if (m == 3) emitter_.number("arg_s", s_.spindle);
    }
    spindle_event(m);
  }
  static constexpr Op kOutputs[] = {Op::M7, Op::M8, Op::M9, Op::M10, Op::M11};
  static constexpr int kNumbers[] = {7, 8, 9, 10, 11};
  for (int i = 0; i < 5; ++i) {
    if (!r.has(kOutputs[i])) continue;
    switch (kNumbers[i]) {
      case 7: s_.c_m7 = true; break;
      case 8: s_.c_m8 = true; break;
      case 9: s_.c_m7 = s_.c_m8 = false; break;
      case 10: s_.c_m10 = true; break;
      case 11: s_.c_m10 = false; break;
    }
    emitter_.add("@coolant");
    emitter_.integer("mcode", kNumbers[i]);
    emitter_.logical("c_m7", s_.c_m7);
    emitter_.logical("c_m8", s_.c_m8);
    emitter_.logical("c_m10", s_.c_m10);
  }
  if (r.has(Op::G4)) {  // 8. dwell, P in seconds
    if (!w.has('P')) {
      warn(r.column(Op::G4), "G4 without P: no dwell");
    } else if (const double p = w.raw('P'); p < 0) {
      warn(w.col('P'), "G4 with a negative P: no dwell");
    } else {
      emitter_.add("@delay");
      emitter_.number("delay_period", p);
    }
  }
}

void Interpreter::misc_modes(const Resolved& r, Words& w) {
  if (r.has(Op::G17)) s_.plane = Plane::XY;
  if (r.has(Op::G18)) s_.plane = Plane::ZX;
  if (r.has(Op::G19)) s_.plane = Plane::YZ;
  // 11. cutter compensation
  if (r.has(Op::G40)) {
    s_.compensation = 40;
    if (previewing_) preview_.end();
    else compensator_.stop(emitter_);
  }
  if (r.has(Op::G41) || r.has(Op::G42)) {
    const bool left = r.has(Op::G41);
    const std::size_t column = r.column(left ? Op::G41 : Op::G42);
    s_.compensation = left ? 41 : 42;
    if (w.has('R')) {
      s_.compensation_radius = w.len_plain('R');
    } else {
      const auto it = options_.tools.find(s_.tool);
      s_.compensation_radius = it == options_.tools.end() ? 0.0 : it->second.radius;
      if (it == options_.tools.end())
        warn(column, fmt::format("no R and no radius for tool {} in the tool table: radius 0", s_.tool));
    }
    if (s_.compensation_radius < 0) warn(w.col('R'), "negative compensation radius: the path moves to the other side");
    // The 2016 dialect has only the XY plane; in G18 (lathe) a G1 entry move leads into the path.
    // Options::cutter_compensation = false (postproc verify) keeps the programmed path.
    const Plane plane = options_.dialect == Dialect::V2016 ? Plane::XY : s_.plane;
    if (previewing_) preview_.end();
    else if (options_.cutter_compensation) compensator_.start(left ? 1 : -1, s_.compensation_radius, plane, plane == Plane::ZX, emitter_);
  }
  // 12. tool offsets, MDI only
  const bool g43 = r.has(Op::G43) || r.has(Op::G43_1) || r.has(Op::G43_2);
  if (g43 || r.has(Op::G49)) {
    const Op op = r.has(Op::G49) ? Op::G49 : r.has(Op::G43) ? Op::G43 : r.has(Op::G43_1) ? Op::G43_1 : Op::G43_2;
    if (!options_.mdi) {
      warn(r.column(op), "G43, G43.1, G43.2 and G49 work only from MDI: ignored in a program");
      for (char l : std::string_view("XYZABTH")) if (w.owned(l)) w.raw(l);
    } else if (op == Op::G49) {
      set_tool_offset(Axes5{});
    } else {
      Axes5 next = s_.tool_offset;
      auto table = [&](int tool) {
        const auto it = options_.tools.find(tool);
        return it == options_.tools.end() ? Axes5{} : it->second.offset;
      };
      if (op == Op::G43 && w.owned('T')) {
        s_.tool = int_word(w.raw('T'));
        next = table(s_.tool);
        emitter_.add("@change_tool");
        emitter_.integer("tool_number", s_.tool);
        emitter_.logical("silent", true);
      }
      if (op == Op::G43 && w.owned('H')) next = table(int_word(w.raw('H')));
      bool any_axis = false;
      for (int i = 0; i < 5; ++i) {
        const char l = "XYZAB"[i];
        if (!w.owned(l)) continue;
        any_axis = true;
        const double v = i < 3 ? w.len(l) : w.raw(l);
        next[static_cast<std::size_t>(i)] = op == Op::G43 ? v : op == Op::G43_1 ? next[static_cast<std::size_t>(i)] + v
                                                                               : next[static_cast<std::size_t>(i)] - v;
      }
      if (op == Op::G43 && !any_axis && !w.owned('T') && !w.owned('H')) next = table(s_.tool);
      set_tool_offset(next);
    }
  }
  // 15. distance mode, cycle return
  if (r.has(Op::G90)) s_.incremental = false;
  if (r.has(Op::G91)) s_.incremental = true;
  if (r.has(Op::G98)) s_.return_to_r = false;
  if (r.has(Op::G99)) s_.return_to_r = true;
  // 16. TCPC, pause button, automatic approach
  if (r.has(Op::G234) || r.has(Op::G235)) {
    s_.tcpc = r.has(Op::G234);
    s_.tcpc_slot = s_.tcpc ? r.tcpc.dot : 0;
    emitter_.add("@tcpc");
    emitter_.logical("tcpc_on", s_.tcpc);
    emitter_.integer("slot", s_.tcpc_slot);
  }
  if (r.has(Op::G116) || r.has(Op::G117)) {
    s_.pause_allowed = r.has(Op::G116);
    emitter_.add("@pause_button");
    emitter_.logical("allowed", s_.pause_allowed);
  }
  if (r.has(Op::G115)) g115_seen_ = true;
  // 17. on-screen message
  if (r.has(Op::G120)) {
    emitter_.add("@message");
    emitter_.text("message", w.b.has_comment ? w.b.comment : std::string_view());
    emitter_.logical("screen", true);
  }
}

}  // namespace pikocnc
