#include "machines/pikocnc/model/codes.hpp"

#include <array>
#include <iterator>

namespace pikocnc {
namespace {

constexpr unsigned char k16 = static_cast<unsigned char>(Dialect::V2016);
constexpr unsigned char k25 = static_cast<unsigned char>(Dialect::V2025);
constexpr unsigned char kBoth = k16 | k25;

// letter, number, dot, any_dot, op, group, dialects, owned words, description
constexpr CodeInfo kCodes[] = {
    {'G', 0, 0, false, Op::G0, Group::Motion, kBoth, "XYZABUVW", "rapid positioning"},
    {'G', 0, 1, false, Op::G0_1, Group::Motion, k25, "XYZAB", "rapid, incremental words"},
    {'G', 1, 0, false, Op::G1, Group::Motion, kBoth, "XYZABUVW", "linear feed"},
    {'G', 1, 1, false, Op::G1_1, Group::Motion, k25, "XYZAB", "linear feed, incremental words"},
    {'G', 2, 0, false, Op::G2, Group::Motion, kBoth, "XYZIJKR", "clockwise arc"},
    {'G', 3, 0, false, Op::G3, Group::Motion, kBoth, "XYZIJKR", "counter-clockwise arc"},
    {'G', 4, 0, false, Op::G4, Group::NonModal, kBoth, "P", "dwell P seconds"},
    {'G', 7, 0, false, Op::G7, Group::LatheX, k25, "", "lathe diameter mode"},
    {'G', 8, 0, false, Op::G8, Group::LatheX, k25, "", "lathe radius mode"},
    {'G', 10, 0, false, Op::G10, Group::NonModal, k25, "XYZABP", "set a work offset to machine values"},
    {'G', 10, 1, false, Op::G10_1, Group::NonModal, k25, "XYZABP", "set a work offset from the tool position"},
    {'G', 10, 2, false, Op::G10_2, Group::NonModal, k25, "XYZABPQ", "set a work offset from a park position"},
    {'G', 17, 0, false, Op::G17, Group::Plane, k25, "", "XY plane"},
    {'G', 18, 0, false, Op::G18, Group::Plane, k25, "", "ZX plane"},
    {'G', 19, 0, false, Op::G19, Group::Plane, k25, "", "YZ plane"},
    {'G', 20, 0, false, Op::G20, Group::Units, kBoth, "", "inch"},
    {'G', 21, 0, false, Op::G21, Group::Units, kBoth, "", "millimetre"},
    {'G', 25, 0, false, Op::G25, Group::NonModal, k25, "R", "loop start, R passes"},
    {'G', 28, 0, false, Op::G28, Group::NonModal, kBoth, "XYZABUVW", "rapid to HOME1"},
    {'G', 30, 0, false, Op::G30, Group::NonModal, kBoth, "XYZABUVW", "rapid to HOME2"},
    {'G', 33, 0, false, Op::G33, Group::Motion, k25, "XYZK", "spindle-synchronised thread move"},
    {'G', 40, 0, false, Op::G40, Group::Compensation, kBoth, "", "cutter compensation off"},
    {'G', 41, 0, false, Op::G41, Group::Compensation, kBoth, "R", "cutter compensation left"},
    {'G', 42, 0, false, Op::G42, Group::Compensation, kBoth, "R", "cutter compensation right"},
    {'G', 43, 0, false, Op::G43, Group::NonModal, k25, "XYZABTH", "replace tool offsets (MDI)"},
    {'G', 43, 1, false, Op::G43_1, Group::NonModal, k25, "XYZABTH", "add to tool offsets (MDI)"},
    {'G', 43, 2, false, Op::G43_2, Group::NonModal, k25, "XYZABTH", "subtract from tool offsets (MDI)"},
    {'G', 49, 0, false, Op::G49, Group::NonModal, k25, "", "zero tool offsets (MDI)"},
    {'G', 50, 0, false, Op::G50, Group::NonModal, k25, "S", "spindle limit in CSS"},
    {'G', 51, 0, false, Op::G51, Group::Transform, k25, "XYZIJKP", "scaling"},
    {'G', 52, 0, false, Op::G52, Group::NonModal, k25, "XYZAB", "set program offset"},
    {'G', 53, 0, false, Op::G53, Group::NonModal, k25, "XYZAB", "machine move (holder)"},
    {'G', 53, 1, false, Op::G53_1, Group::NonModal, k25, "XYZAB", "machine move (tool tip)"},
    {'G', 54, 0, false, Op::G54, Group::WorkOffset, k25, "", "work offset 1"},
    {'G', 55, 0, false, Op::G55, Group::WorkOffset, k25, "", "work offset 2"},
    {'G', 56, 0, false, Op::G56, Group::WorkOffset, k25, "", "work offset 3"},
    {'G', 57, 0, false, Op::G57, Group::WorkOffset, k25, "", "work offset 4"},
    {'G', 58, 0, false, Op::G58, Group::WorkOffset, k25, "", "work offset 5"},
    {'G', 59, 0, false, Op::G59, Group::WorkOffset, k25, "", "work offset 6"},
    {'G', 65, 0, false, Op::G65, Group::NonModal, k25, "XYZABDPQRSWF", "touch-probe cycle"},
    {'G', 68, 0, false, Op::G68, Group::Transform, k25, "XYZR", "rotation"},
    {'G', 68, 2, false, Op::G68_2, Group::Transform, k25, "XYZPQIJK", "tilted working plane"},
    {'G', 69, 0, false, Op::G69, Group::Transform, k25, "", "cancel all transformations"},
    {'G', 69, 1, false, Op::G69_1, Group::Transform, k25, "", "cancel the last transformation"},
    {'G', 74, 0, false, Op::G74, Group::Motion, k25, "XYZRPUV", "tapping, right-hand, compensating holder"},
    {'G', 74, 1, false, Op::G74_1, Group::Motion, k25, "XYZRPUV", "tapping, left-hand, compensating holder"},
    {'G', 76, 0, false, Op::G76, Group::NonModal, k25, "PZIJKQR", "lathe threading cycle"},
    {'G', 80, 0, false, Op::G80, Group::Motion, kBoth, "", "cancel canned cycle"},
    {'G', 81, 0, false, Op::G81, Group::Motion, kBoth, "XYZRUV", "drilling cycle"},
    {'G', 83, 0, false, Op::G83, Group::Motion, kBoth, "XYZRQUV", "peck drilling cycle"},
    {'G', 84, 0, false, Op::G84, Group::Motion, kBoth, "XYZRQUV", "tapping cycle, self-reversing head"},
    {'G', 90, 0, false, Op::G90, Group::Distance, kBoth, "", "absolute"},
    {'G', 91, 0, false, Op::G91, Group::Distance, kBoth, "", "incremental"},
    {'G', 92, 0, false, Op::G92, Group::NonModal, k25, "XYZAB", "set program offset from the position"},
    {'G', 92, 1, false, Op::G92_1, Group::NonModal, k25, "", "clear program offsets"},
    {'G', 94, 0, false, Op::G94, Group::FeedMode, k25, "", "feed per minute"},
    {'G', 95, 0, false, Op::G95, Group::FeedMode, k25, "", "feed per revolution"},
    {'G', 96, 0, false, Op::G96, Group::SpindleMode, k25, "", "constant surface speed"},
    {'G', 97, 0, false, Op::G97, Group::SpindleMode, k25, "", "spindle rpm"},
    {'G', 98, 0, false, Op::G98, Group::CycleReturn, kBoth, "", "cycle return to the clearance Z"},
    {'G', 99, 0, false, Op::G99, Group::CycleReturn, kBoth, "", "cycle return to R"},
    {'G', 115, 0, false, Op::G115, Group::NonModal, kBoth, "", "no automatic approach"},
    {'G', 116, 0, false, Op::G116, Group::PauseButton, kBoth, "", "pause button allowed"},
    {'G', 117, 0, false, Op::G117, Group::PauseButton, kBoth, "", "pause button blocked"},
    {'G', 120, 0, false, Op::G120, Group::NonModal, k25, "", "show the line's comment on screen"},
    {'G', 125, 0, false, Op::G125, Group::NonModal, k25, "", "loop end"},
    {'G', 234, 0, true, Op::G234, Group::Tcpc, k25, "", "TCPC on, dot = kinematics slot"},
    {'G', 235, 0, false, Op::G235, Group::Tcpc, k25, "", "TCPC off"},
    {'M', 0, 0, false, Op::M0, Group::Stop, kBoth, "", "program stop (pause)"},
    {'M', 1, 0, false, Op::M1, Group::Stop, k25, "", "optional stop"},
    {'M', 3, 0, false, Op::M3, Group::Spindle, kBoth, "", "spindle clockwise"},
    {'M', 4, 0, false, Op::M4, Group::Spindle, kBoth, "", "spindle counter-clockwise"},
    {'M', 5, 0, false, Op::M5, Group::Spindle, kBoth, "", "spindle off"},
    {'M', 6, 0, false, Op::M6, Group::Tool, kBoth, "", "tool change"},
    {'M', 7, 0, false, Op::M7, Group::Outputs, kBoth, "", "set C_M7"},
    {'M', 8, 0, false, Op::M8, Group::Outputs, kBoth, "", "coolant on (C_M8)"},
    {'M', 9, 0, false, Op::M9, Group::Outputs, kBoth, "", "clear C_M7 and C_M8"},
    {'M', 10, 0, false, Op::M10, Group::Outputs, kBoth, "", "set C_M10"},
    {'M', 11, 0, false, Op::M11, Group::Outputs, kBoth, "", "clear C_M10"},
    {'M', 30, 0, false, Op::M30, Group::Stop, kBoth, "", "end of program"},
    {'M', 99, 0, false, Op::M99, Group::Stop, kBoth, "", "restart the program"},
};

// G100..G110 (2016, words P Q) and G100..G114 (2025, words X Y Z A B F P Q): user macros.
constexpr CodeInfo kMacro2016{'G', 100, 0, true, Op::Macro, Group::Macro, k16, "PQ", "user macro"};
constexpr CodeInfo kMacro2025{'G', 100, 0, true, Op::Macro, Group::Macro, k25, "XYZABFPQ", "user macro"};

// Direct lookup by number * 10 + dot, built once from the table.
struct Index {
  std::array<const CodeInfo*, 2360> g{};
  std::array<const CodeInfo*, 1000> m{};
  Index() {
    for (const CodeInfo& c : kCodes) {
      const std::size_t key = static_cast<std::size_t>(c.number * 10 + c.dot);
      (c.letter == 'G' ? g[key] : m[key]) = &c;
    }
  }
};

const Index& index() {
  static const Index built;
  return built;
}

}  // namespace

const CodeInfo* find_code(const CodeWord& code, Dialect dialect) {
  const auto bit = static_cast<unsigned char>(dialect);
  if (code.letter == 'G' && code.number >= 100 && code.number <= 114) {
    if (dialect == Dialect::V2016) return code.number > 110 || code.dot_digits > 0 ? nullptr : &kMacro2016;
    return &kMacro2025;
  }
  const Index& idx = index();
  const CodeInfo* c = nullptr;
  if (code.letter == 'G' && code.number == 234) {
    c = idx.g[2340];
  } else if (code.dot_digits <= 1) {
    const std::size_t key = static_cast<std::size_t>(code.number) * 10 + static_cast<std::size_t>(code.dot);
    if (code.letter == 'G' && key < idx.g.size()) c = idx.g[key];
    if (code.letter == 'M' && key < idx.m.size() && code.dot_digits == 0) c = idx.m[key];
  }
  return c && (c->dialects & bit) ? c : nullptr;
}

}  // namespace pikocnc
