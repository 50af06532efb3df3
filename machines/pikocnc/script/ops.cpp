// Operators and conversions on run-time values (spec 2.3, 2.4, 7).
#include "machines/pikocnc/script/ops.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace pikocnc::script {

namespace {

constexpr std::int64_t kMin = std::numeric_limits<std::int32_t>::min();
constexpr std::int64_t kMax = std::numeric_limits<std::int32_t>::max();
constexpr std::size_t kMaxString = 16u << 20;  // a doubling loop must fail, not eat the memory

std::int64_t fit(std::int64_t v) {
  if (v < kMin || v > kMax) throw OpError(fmt::format("integer overflow ({} does not fit an Integer)", v));
  return v;
}

double num(const Value& v) {
  if (v.kind == Kind::Integer) return double(v.i);
  if (v.kind == Kind::Float) return v.f;
  throw OpError(fmt::format("a number was expected, got {}", kind_name(v.kind)));
}

double finite(double v) {
  if (!std::isfinite(v)) throw OpError("floating-point overflow (the result is not a finite number)");
  return v;
}

int compare(const Value& a, const Value& b) {
  if ((a.kind == Kind::Integer || a.kind == Kind::Float) && (b.kind == Kind::Integer || b.kind == Kind::Float)) {
    if (a.kind == Kind::Integer && b.kind == Kind::Integer) return a.i < b.i ? -1 : a.i > b.i;
    const double x = num(a), y = num(b);
    return x < y ? -1 : x > y;
  }
  if (a.kind == Kind::String && b.kind == Kind::String) return a.s.compare(b.s) < 0 ? -1 : a.s != b.s;
  if (a.kind == Kind::Boolean && b.kind == Kind::Boolean) return int(a.b) - int(b.b);
  throw OpError(fmt::format("cannot compare {} with {}", kind_name(a.kind), kind_name(b.kind)));
}

}  // namespace

std::int64_t round_even(double v) {
  if (!std::isfinite(v) || v < double(kMin) - 0.5 || v > double(kMax) + 0.5)
    throw OpError(fmt::format("{} does not fit an Integer", float_to_str(v)));
  return fit(std::int64_t(std::nearbyint(v)));  // the default rounding mode is half to even
}

std::int64_t checked_int(double v) {
  if (!std::isfinite(v) || v <= double(kMin) - 1 || v >= double(kMax) + 1)
    throw OpError(fmt::format("{} does not fit an Integer", float_to_str(v)));
  return std::int64_t(std::trunc(v));
}

bool truthy(const Value& v) {
  if (v.kind == Kind::Boolean) return v.b;
  throw OpError(fmt::format("a Boolean was expected, got {}", kind_name(v.kind)));
}

Value apply_binary(Bin op, const Value& a, const Value& b) {
  const bool ints = a.kind == Kind::Integer && b.kind == Kind::Integer;
  switch (op) {
    case Bin::Add:
      if (a.kind == Kind::String || b.kind == Kind::String) {
        std::string s = a.kind == Kind::String ? a.s : value_text(a);
        const std::string& t = b.kind == Kind::String ? b.s : value_text(b);
        if (s.size() + t.size() > kMaxString) throw OpError("string too long (more than 16 MB)");
        return Value::text(s + t);
      }
      return ints ? Value::integer(fit(a.i + b.i)) : Value::real(finite(num(a) + num(b)));
    case Bin::Sub: return ints ? Value::integer(fit(a.i - b.i)) : Value::real(finite(num(a) - num(b)));
    case Bin::Mul: return ints ? Value::integer(fit(a.i * b.i)) : Value::real(finite(num(a) * num(b)));
    case Bin::Div: {
      const double d = num(b);
      if (d == 0) throw OpError("division by zero");
      return Value::real(finite(num(a) / d));
    }
    case Bin::IntDiv:
    case Bin::Mod:
    case Bin::Shl:
    case Bin::Shr: {
      if (!ints) throw OpError("div, mod, shl and shr need Integer operands");
      if (op == Bin::Shl || op == Bin::Shr) {
        if (b.i < 0 || b.i > 31) throw OpError("shift count must be 0..31");
        const auto u = std::uint32_t(std::int32_t(a.i));
        return Value::integer(std::int32_t(op == Bin::Shl ? u << b.i : u >> b.i));
      }
      if (b.i == 0) throw OpError("division by zero");
      return Value::integer(fit(op == Bin::IntDiv ? a.i / b.i : a.i % b.i));
    }
    case Bin::And:
    case Bin::Or:
    case Bin::Xor:
      if (a.kind == Kind::Boolean && b.kind == Kind::Boolean)
        return Value::boolean(op == Bin::And ? (a.b && b.b) : op == Bin::Or ? (a.b || b.b) : (a.b != b.b));
      if (ints) return Value::integer(op == Bin::And ? (a.i & b.i) : op == Bin::Or ? (a.i | b.i) : (a.i ^ b.i));
      throw OpError(fmt::format("and/or/xor need two Booleans or two Integers, got {} and {}", kind_name(a.kind), kind_name(b.kind)));
    case Bin::Eq: return Value::boolean(compare(a, b) == 0);
    case Bin::Ne: return Value::boolean(compare(a, b) != 0);
    case Bin::Lt: return Value::boolean(compare(a, b) < 0);
    case Bin::Le: return Value::boolean(compare(a, b) <= 0);
    case Bin::Gt: return Value::boolean(compare(a, b) > 0);
    case Bin::Ge: return Value::boolean(compare(a, b) >= 0);
  }
  return a;
}

Value apply_unary(Un op, const Value& a) {
  if (op == Un::Not) {
    if (a.kind == Kind::Boolean) return Value::boolean(!a.b);
    if (a.kind == Kind::Integer) return Value::integer(~a.i);
    throw OpError(fmt::format("not needs a Boolean or an Integer, got {}", kind_name(a.kind)));
  }
  if (a.kind == Kind::Integer) return Value::integer(op == Un::Neg ? fit(-a.i) : a.i);
  const double x = num(a);
  return Value::real(op == Un::Neg ? -x : x);
}

Value convert_to(const Value& v, const Type& to) {
  switch (to.kind) {
    case Kind::Integer: {
      std::int64_t x = 0;
      if (v.kind == Kind::Integer) x = v.i;
      else if (v.kind == Kind::Float) x = round_even(v.f);  // Delphi's Variant rounds
      else if (v.kind == Kind::String) {
        char* end = nullptr;
        const long long parsed = std::strtoll(v.s.c_str(), &end, 10);
        if (v.s.empty() || *end != '\0') throw OpError(fmt::format("'{}' is not an integer", v.s));
        x = fit(parsed);
      } else throw OpError(fmt::format("cannot convert {} to Integer", kind_name(v.kind)));
      if (to.width == 1 && (x < 0 || x > 255)) throw OpError(fmt::format("{} is out of the Byte range 0..255", x));
      if (to.width == 2 && x < 0) throw OpError(fmt::format("{} is negative; a Cardinal cannot be", x));
      return Value::integer(x);
    }
    case Kind::Float:
      if (v.kind == Kind::Integer) return Value::real(double(v.i));
      if (v.kind == Kind::Float) return v;
      if (v.kind == Kind::String) {
        char* end = nullptr;
        const double d = std::strtod(v.s.c_str(), &end);
        if (v.s.empty() || *end != '\0' || !std::isfinite(d)) throw OpError(fmt::format("'{}' is not a number", v.s));
        return Value::real(d);
      }
      throw OpError(fmt::format("cannot convert {} to Extended", kind_name(v.kind)));
    case Kind::Boolean:
      if (v.kind == Kind::Boolean) return v;
      if (v.kind == Kind::Integer) return Value::boolean(v.i != 0);
      throw OpError(fmt::format("cannot convert {} to Boolean", kind_name(v.kind)));
    case Kind::String:
      if (v.kind == Kind::String) return v;
      return Value::text(value_text(v));
    default: return v;
  }
}

std::string float_to_str(double v) {
  if (std::isnan(v)) return "NAN";
  if (std::isinf(v)) return v > 0 ? "INF" : "-INF";
  if (v == 0) return "0";
  std::string s = fmt::format("{:.15g}", v);
  const auto e = s.find('e');
  if (e == std::string::npos) return s;
  // 1e-05 -> 1E-5, 1.5e+20 -> 1.5E20
  std::string mant = s.substr(0, e);
  std::string exp = s.substr(e + 1);
  const bool neg = exp[0] == '-';
  std::size_t k = (exp[0] == '-' || exp[0] == '+') ? 1 : 0;
  while (k + 1 < exp.size() && exp[k] == '0') ++k;
  return mant + "E" + (neg ? "-" : "") + exp.substr(k);
}

std::string value_text(const Value& v) {
  switch (v.kind) {
    case Kind::Integer: return std::to_string(v.i);
    case Kind::Float: return float_to_str(v.f);
    case Kind::Boolean: return v.b ? "True" : "False";
    case Kind::String: return v.s;
    default: return "(record)";
  }
}

}  // namespace pikocnc::script
