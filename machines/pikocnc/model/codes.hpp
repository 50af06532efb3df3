// The one table of every G and M code of the dialect: which modal group it belongs to, which words
// it takes, in which dialect versions it exists. The interpreter dispatches on `Op` by group.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "machines/pikocnc/model/dialect.hpp"
#include "machines/pikocnc/model/lexer.hpp"

namespace pikocnc {

enum class Op : std::uint8_t {
  // motion group
  G0, G0_1, G1, G1_1, G2, G3, G33, G81, G83, G84, G74, G74_1, G80,
  // non-modal motion and settings
  G4, G10, G10_1, G10_2, G25, G125, G28, G30, G43, G43_1, G43_2, G49, G50, G51, G52, G53, G53_1,
  G65, G68, G68_2, G69, G69_1, G76, G92, G92_1, Macro, G115, G116, G117, G120, G234, G235,
  // modal settings
  G7, G8, G17, G18, G19, G20, G21, G40, G41, G42, G54, G55, G56, G57, G58, G59, G90, G91,
  G94, G95, G96, G97, G98, G99,
  // M codes
  M0, M1, M3, M4, M5, M6, M7, M8, M9, M10, M11, M30, M99,
  Unknown,
};

// Modal groups of section 3.1 (NonModal: acts in its line only).
enum class Group : std::uint8_t {
  Motion, Plane, Units, LatheX, Distance, FeedMode, SpindleMode, CycleReturn, Compensation,
  WorkOffset, Tcpc, PauseButton, Transform, NonModal, Macro, Stop, Spindle, Tool, Outputs,
};

struct CodeInfo {
  char letter;
  int number;
  int dot;                // fractional part (G68.2 -> 2); ignored when `any_dot`
  bool any_dot;           // macros and G234: the dot is a parameter
  Op op;
  Group group;
  unsigned char dialects; // bit set of Dialect values
  std::string_view words; // the words the code owns (section 2.2)
  std::string_view description;
};

// The table entry for a code as written, or nullptr when the dialect does not know it.
const CodeInfo* find_code(const CodeWord& code, Dialect dialect);

}  // namespace pikocnc
