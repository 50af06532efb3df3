// The routines and constants PikoCNC gives a script (spec sections 3-9): their signatures for the
// compiler, their implementations for the interpreter (builtins.cpp).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "machines/pikocnc/script/value.hpp"

namespace pikocnc::script {

enum class B : std::uint8_t {
  // line builder (3)
  SetX, SetY, SetZ, SetA, SetI, SetJ, SetR, SetF, SetS, SetT, SetP, SetQ, SetM, SetG, SetComment, Write,
  GetX, GetY, GetZ,
  // path helpers (4) and geometry (5)
  SetBulge, SetMove, SetMoveR, SetAngle, CirPointX, CirPointY, SetPT, LinePar, LineInt, LineExp,
  // arguments (6)
  SetArg, Arg, ArgEdit, SetArgPic, ArgShow, ArgNewPage, ArgPageTitle, ArgSeparator,
  // messages (7)
  MsgOk, MsgYesNo, Dbg, DbgClr, Log, FloatToStr,
  // math (8)
  Sin, Cos, Tan, ArcSin, ArcCos, ArcTan, Abs, Sqr, Sqrt, Ln, Exp, Round, Trunc, Int, Frac, Pi, Power, Min, Max,
  // strings (8)
  IntToStr, StrToInt, StrToFloat, Length, Copy, Pos, UpperCase, LowerCase, Trim, Chr, Ord, Odd, Inc, Dec,
};

struct Builtin {
  std::string_view name;
  B id;
  Type result;                // Void for procedures
  std::vector<Type> params;   // Variant accepts anything; Float accepts Integer too
  std::uint8_t min_args = 0;  // optional trailing arguments (Inc, Dec)
  bool last_by_ref = false;   // LineInt's pc, Inc/Dec's variable
  bool numeric_same = false;  // Abs, Sqr, Min, Max: Integer in, Integer out
};

// The built-in routine of that name (case-insensitive), or nullptr.
const Builtin* find_builtin(std::string_view name);

// The predefined read-only constants of section 9, in a fixed order.
struct Predefined {
  std::string_view name;
  bool integer;  // RUN_CNT
};
const std::vector<Predefined>& predefined_constants();
int find_predefined(std::string_view name);  // index, or -1

}  // namespace pikocnc::script
