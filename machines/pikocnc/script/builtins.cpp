// The built-in signatures (spec sections 3-9): names, argument types, results.
#include "machines/pikocnc/script/builtins.hpp"

#include <algorithm>
#include <map>
#include <string>

#include "machines/pikocnc/script/compiled.hpp"

namespace pikocnc::script {

namespace {

const Type V{Kind::Void}, I{Kind::Integer}, F{Kind::Float}, Bo{Kind::Boolean}, S{Kind::String}, Va{Kind::Variant};
const Type Byte{Kind::Integer, 1}, Card{Kind::Integer, 2};
const Type Pt{Kind::Record, 0, kTPoint}, Ln{Kind::Record, 0, kTLine};

std::vector<Builtin> table() {
  std::vector<Builtin> t = {
      {"SetX", B::SetX, V, {F}}, {"SetY", B::SetY, V, {F}}, {"SetZ", B::SetZ, V, {F}}, {"SetA", B::SetA, V, {F}},
      {"SetI", B::SetI, V, {F}}, {"SetJ", B::SetJ, V, {F}}, {"SetR", B::SetR, V, {F}}, {"SetF", B::SetF, V, {F}},
      {"SetS", B::SetS, V, {F}}, {"SetT", B::SetT, V, {Byte}}, {"SetP", B::SetP, V, {F}}, {"SetQ", B::SetQ, V, {F}},
      {"SetM", B::SetM, V, {Byte}}, {"SetG", B::SetG, V, {Byte}}, {"SetComment", B::SetComment, V, {S}},
      {"Write", B::Write, V, {}}, {"GetX", B::GetX, F, {}}, {"GetY", B::GetY, F, {}}, {"GetZ", B::GetZ, F, {}},
      {"SetBulge", B::SetBulge, V, {F}}, {"SetMove", B::SetMove, V, {F, F}}, {"SetMoveR", B::SetMoveR, V, {F, F}},
      {"SetAngle", B::SetAngle, V, {F}}, {"CirPointX", B::CirPointX, F, {F, F}}, {"CirPointY", B::CirPointY, F, {F, F}},
      {"SetPT", B::SetPT, V, {Pt}}, {"LinePar", B::LinePar, Ln, {Ln, F}}, {"LineInt", B::LineInt, Bo, {Ln, Ln, Pt}, 3, true},
      {"LineExp", B::LineExp, Ln, {Ln, F}},
      {"SetArg", B::SetArg, V, {Card, S, Va}}, {"Arg", B::Arg, Va, {Card}}, {"ArgEdit", B::ArgEdit, V, {}},
      {"SetArgPic", B::SetArgPic, V, {S}}, {"ArgShow", B::ArgShow, V, {Card}}, {"ArgNewPage", B::ArgNewPage, V, {S}},
      {"ArgPageTitle", B::ArgPageTitle, V, {S}}, {"ArgSeparator", B::ArgSeparator, V, {S}},
      {"MsgOk", B::MsgOk, V, {S}}, {"MsgYesNo", B::MsgYesNo, Bo, {S}}, {"Dbg", B::Dbg, V, {S}},
      {"Dbg_clr", B::DbgClr, V, {}}, {"Log", B::Log, V, {S}}, {"FloatToStr", B::FloatToStr, S, {F}},
      {"Sin", B::Sin, F, {F}}, {"Cos", B::Cos, F, {F}}, {"Tan", B::Tan, F, {F}}, {"ArcSin", B::ArcSin, F, {F}},
      {"ArcCos", B::ArcCos, F, {F}}, {"ArcTan", B::ArcTan, F, {F}}, {"Abs", B::Abs, F, {F}, 1, false, true},
      {"Sqr", B::Sqr, F, {F}, 1, false, true}, {"Sqrt", B::Sqrt, F, {F}}, {"Ln", B::Ln, F, {F}}, {"Exp", B::Exp, F, {F}},
      {"Round", B::Round, I, {F}}, {"Trunc", B::Trunc, I, {F}}, {"Int", B::Int, F, {F}}, {"Frac", B::Frac, F, {F}},
      {"Pi", B::Pi, F, {}}, {"Power", B::Power, F, {F, F}}, {"Min", B::Min, F, {F, F}, 2, false, true},
      {"Max", B::Max, F, {F, F}, 2, false, true},
      {"IntToStr", B::IntToStr, S, {I}}, {"StrToInt", B::StrToInt, I, {S}}, {"StrToFloat", B::StrToFloat, F, {S}},
      {"Length", B::Length, I, {S}}, {"Copy", B::Copy, S, {S, I, I}}, {"Pos", B::Pos, I, {S, S}},
      {"UpperCase", B::UpperCase, S, {S}}, {"LowerCase", B::LowerCase, S, {S}}, {"Trim", B::Trim, S, {S}},
      {"Chr", B::Chr, S, {I}}, {"Ord", B::Ord, I, {Va}}, {"Odd", B::Odd, Bo, {I}},
      {"Inc", B::Inc, V, {I, I}, 1, false}, {"Dec", B::Dec, V, {I, I}, 1, false},
  };
  for (auto& b : t)
    if (b.min_args == 0 && !b.params.empty() && b.id != B::Inc && b.id != B::Dec) b.min_args = std::uint8_t(b.params.size());
  return t;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return out;
}

}  // namespace

const Builtin* find_builtin(std::string_view name) {
  static const auto all = [] {
    std::map<std::string, Builtin, std::less<>> m;
    for (auto& b : table()) m.emplace(lower(b.name), b);
    return m;
  }();
  auto it = all.find(lower(name));
  return it == all.end() ? nullptr : &it->second;
}

const std::vector<Predefined>& predefined_constants() {
  static const std::vector<Predefined> all = {
      {"MAT_SIZE_X", false}, {"MAT_SIZE_Y", false}, {"MAT_SIZE_Z", false},  {"ACT_POS_X", false},
      {"ACT_POS_Y", false},  {"ACT_POS_Z", false},  {"ACT_POS_X_M", false}, {"ACT_POS_Y_M", false},
      {"ACT_POS_Z_M", false}, {"ACT_F", false},     {"ACT_S", false},       {"ACT_ZRAPID", false},
      {"ACT_F_Z", false},    {"TAB_SIZE_X", false}, {"TAB_SIZE_Y", false},  {"RUN_CNT", true},
  };
  return all;
}

int find_predefined(std::string_view name) {
  const std::string key = lower(name);
  const auto& all = predefined_constants();
  for (std::size_t i = 0; i < all.size(); ++i)
    if (lower(all[i].name) == key) return int(i);
  return -1;
}

}  // namespace pikocnc::script
