// The built-ins at run time (spec sections 3-10). Arguments arrive converted to the declared
// parameter types by the compiler; domain errors carry the call's position.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "machines/pikocnc/script/builtins.hpp"
#include "machines/pikocnc/script/interpreter.hpp"
#include "machines/pikocnc/script/ops.hpp"

namespace pikocnc::script {

namespace {

struct P2 {
  double x, y;
};
P2 point(const Value& v) { return {v.items[0].f, v.items[1].f}; }
Value make_point(P2 p) {
  Value v;
  v.kind = Kind::Record;
  v.items = {Value::real(p.x), Value::real(p.y)};
  return v;
}
Value make_line(P2 s, P2 e) {
  Value v;
  v.kind = Kind::Record;
  v.items = {make_point(s), make_point(e)};
  return v;
}

// Spec 5: LinePar, LineExp and LineInt.
Value line_par(const Value& l, double k, bool extend) {
  const P2 s = point(l.items[0]), e = point(l.items[1]);
  const double dx = e.x - s.x, dy = e.y - s.y, len = std::hypot(dx, dy);
  if (len == 0) return l;
  const double ux = dx / len, uy = dy / len;
  if (extend) return make_line({s.x - k * ux, s.y - k * uy}, {e.x + k * ux, e.y + k * uy});
  return make_line({s.x - k * uy, s.y + k * ux}, {e.x - k * uy, e.y + k * ux});
}

bool line_int(const Value& l1, const Value& l2, Value& pc) {
  const P2 a = point(l1.items[0]), b = point(l1.items[1]), c = point(l2.items[0]), d = point(l2.items[1]);
  const double d1x = b.x - a.x, d1y = b.y - a.y, d2x = d.x - c.x, d2y = d.y - c.y;
  const double cross = d1x * d2y - d1y * d2x;
  if (std::fabs(cross) <= 1e-9 * std::hypot(d1x, d1y) * std::hypot(d2x, d2y) || cross == 0) return false;
  const double ex = c.x - a.x, ey = c.y - a.y;
  const double t = (ex * d2y - ey * d2x) / cross, w = (ex * d1y - ey * d1x) / cross;
  constexpr double tol = 1e-9;
  if (t < -tol || t > 1 + tol || w < -tol || w > 1 + tol) return false;
  pc = make_point({a.x + t * d1x, a.y + t * d1y});
  return true;
}

double rad(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

Value Interpreter::builtin(const Expr& e) {
  step(e.pos);
  Value a[3];  // no built-in takes more; no allocation per call
  const std::size_t argc = e.kids.size();
  const B id = B(e.slot);
  const bool by_ref = id == B::LineInt || id == B::Inc || id == B::Dec;
  for (std::size_t i = 0; i < argc; ++i)
    if (!(by_ref && ((id == B::LineInt && i == 2) || (id != B::LineInt && i == 0)))) a[i] = eval(*e.kids[i]);
  auto num = [&](std::size_t i) {
    const double v = a[i].kind == Kind::Integer ? double(a[i].i) : a[i].f;
    if (!std::isfinite(v)) fail(e.kids[i]->pos, "the value is not a finite number");
    return v;
  };
  auto result = [&](double v) {
    if (!std::isfinite(v)) fail(e.pos, "the result is not a finite number");
    return Value::real(v);
  };
  auto word = [&](Word w) {
    builder_.set(w, num(0));
    return Value{};
  };
  auto domain = [&](bool ok, const char* what) {
    if (!ok) fail(e.pos, fmt::format("{}: argument {} is outside the domain", what, value_text(a[0])));
  };
  try {
    switch (id) {
      case B::SetX: return word(Word::X);
      case B::SetY: return word(Word::Y);
      case B::SetZ: return word(Word::Z);
      case B::SetA: return word(Word::A);
      case B::SetI: return word(Word::I);
      case B::SetJ: return word(Word::J);
      case B::SetR: return word(Word::R);
      case B::SetF: return word(Word::F);
      case B::SetS: return word(Word::S);
      case B::SetP: return word(Word::P);
      case B::SetQ: return word(Word::Q);
      case B::SetT: return word(Word::T);
      case B::SetM: return word(Word::M);
      case B::SetG: builder_.set_g(int(a[0].i)); return {};
      case B::SetComment: builder_.set_comment(a[0].s); return {};
      case B::Write: builder_.write(); return {};
      case B::GetX: return Value::real(builder_.last(Word::X));
      case B::GetY: return Value::real(builder_.last(Word::Y));
      case B::GetZ: return Value::real(builder_.last(Word::Z));
      case B::SetBulge: builder_.bulge(num(0)); return {};
      case B::SetMove: builder_.move(num(0), num(1)); return {};
      case B::SetMoveR: builder_.move_relative(num(0), num(1)); return {};
      case B::SetAngle: builder_.angle(num(0)); return {};
      case B::CirPointX: return result(num(0) * std::cos(rad(num(1))));
      case B::CirPointY: return result(num(0) * std::sin(rad(num(1))));
      case B::SetPT: {
        const P2 p = point(a[0]);
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(e.pos, "the point is not finite");
        builder_.set(Word::X, p.x);
        builder_.set(Word::Y, p.y);
        return {};
      }
      case B::LinePar: return line_par(a[0], num(1), false);
      case B::LineExp: return line_par(a[0], num(1), true);
      case B::LineInt: return Value::boolean(line_int(a[0], a[1], *ref(*e.kids[2])));
      case B::SetArg: dialog_.set_arg(a[0].i, a[1].s, a[2]); return {};
      case B::Arg: return dialog_.arg(a[0].i);
      case B::ArgEdit:
        dialog_.apply(inputs_.args);
        if (inputs_.describe_args) {
          out_ << dialog_.json();
          throw DescribedStop{};
        }
        return {};
      case B::SetArgPic: dialog_.picture(a[0].s); return {};
      case B::ArgShow: dialog_.show(a[0].i); return {};
      case B::ArgNewPage: dialog_.new_page(a[0].s); return {};
      case B::ArgPageTitle: dialog_.page_title(a[0].s); return {};
      case B::ArgSeparator: dialog_.separator(a[0].s); return {};
      case B::MsgOk: diag_ << "MsgOk: " << a[0].s << '\n'; return {};
      case B::Dbg: diag_ << "Dbg: " << a[0].s << '\n'; return {};
      case B::Log: diag_ << "Log: " << a[0].s << '\n'; return {};
      case B::DbgClr: return {};
      case B::MsgYesNo: {
        // Section 10.2: exact text, then the next --answer, then the * default.
        if (auto it = inputs_.answers.find(a[0].s); it != inputs_.answers.end()) return Value::boolean(it->second);
        if (next_answer_ < inputs_.ordered_answers.size()) return Value::boolean(inputs_.ordered_answers[next_answer_++]);
        if (inputs_.default_answer) return Value::boolean(*inputs_.default_answer);
        fail(e.pos, fmt::format("MsgYesNo('{}') needs an answer: give --answer yes|no or \"{}\" = yes|no in [answers]", a[0].s, a[0].s));
      }
      case B::FloatToStr: return Value::text(float_to_str(num(0)));
      case B::Sin: return result(std::sin(num(0)));
      case B::Cos: return result(std::cos(num(0)));
      case B::Tan: return result(std::tan(num(0)));
      case B::ArcSin: domain(std::fabs(num(0)) <= 1, "ArcSin"); return result(std::asin(num(0)));
      case B::ArcCos: domain(std::fabs(num(0)) <= 1, "ArcCos"); return result(std::acos(num(0)));
      case B::ArcTan: return result(std::atan(num(0)));
      case B::Abs:
        if (a[0].kind == Kind::Integer) return apply_unary(a[0].i < 0 ? Un::Neg : Un::Pos, a[0]);
        return result(std::fabs(num(0)));
      case B::Sqr:
        if (a[0].kind == Kind::Integer) return apply_binary(Bin::Mul, a[0], a[0]);
        return result(num(0) * num(0));
      case B::Min:
      case B::Max: {
        const bool less = apply_binary(Bin::Lt, a[0], a[1]).b;
        return (id == B::Min) == less ? a[0] : a[1];
      }
      case B::Sqrt: domain(num(0) >= 0, "Sqrt"); return result(std::sqrt(num(0)));
      case B::Ln: domain(num(0) > 0, "Ln"); return result(std::log(num(0)));
      case B::Exp: return result(std::exp(num(0)));
      case B::Power: return result(std::pow(num(0), num(1)));
      case B::Round: return Value::integer(round_even(num(0)));
      case B::Trunc: return Value::integer(checked_int(num(0)));
      case B::Int: return result(std::trunc(num(0)));
      case B::Frac: return result(num(0) - std::trunc(num(0)));
      case B::Pi: return Value::real(std::numbers::pi);
      case B::IntToStr: return Value::text(std::to_string(a[0].i));
      case B::StrToInt: return convert_to(Value::text(a[0].s), {Kind::Integer});
      case B::StrToFloat: return convert_to(Value::text(a[0].s), {Kind::Float});
      case B::Length: return Value::integer(std::int64_t(a[0].s.size()));
      case B::Copy: {
        // Copy(s, index, count), 1-based; out-of-range parts are cut off as in Delphi.
        const std::int64_t size = std::int64_t(a[0].s.size());
        const std::int64_t from = std::max<std::int64_t>(a[1].i, 1) - 1;
        const std::int64_t count = std::clamp<std::int64_t>(a[2].i, 0, std::max<std::int64_t>(size - from, 0));
        return Value::text(from >= size ? std::string() : a[0].s.substr(std::size_t(from), std::size_t(count)));
      }
      case B::Pos: {
        const auto at = a[1].s.find(a[0].s);
        return Value::integer(a[0].s.empty() || at == std::string::npos ? 0 : std::int64_t(at) + 1);
      }
      case B::UpperCase:
      case B::LowerCase: {
        std::string s = a[0].s;
        for (char& c : s) {
          if (id == B::UpperCase && c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
          if (id == B::LowerCase && c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
        }
        return Value::text(s);
      }
      case B::Trim: {
        const auto first = a[0].s.find_first_not_of(" \t\r\n");
        if (first == std::string::npos) return Value::text({});
        return Value::text(a[0].s.substr(first, a[0].s.find_last_not_of(" \t\r\n") - first + 1));
      }
      case B::Chr:
        if (a[0].i < 0 || a[0].i > 255) fail(e.pos, fmt::format("Chr({}): a character code is 0..255", a[0].i));
        return Value::text(std::string(1, char(a[0].i)));
      case B::Ord:
        if (a[0].kind == Kind::Boolean) return Value::integer(a[0].b);
        if (a[0].kind == Kind::Integer) return a[0];
        if (a[0].kind == Kind::String && a[0].s.size() == 1) return Value::integer(static_cast<unsigned char>(a[0].s[0]));
        fail(e.pos, "Ord needs an Integer, a Boolean or a one-character string");
      case B::Odd: return Value::boolean((a[0].i & 1) != 0);
      case B::Inc:
      case B::Dec: {
        Value* target = ref(*e.kids[0]);
        const Value by = argc > 1 ? a[1] : Value::integer(1);
        *target = apply_binary(id == B::Inc ? Bin::Add : Bin::Sub, *target, by);
        return {};
      }
    }
  } catch (const OpError& x) {
    fail(e.pos, x.what());
  }
  return {};
}

}  // namespace pikocnc::script
