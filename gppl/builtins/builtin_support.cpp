// Argument access, result checks and errors shared by the built-in functions.
#include "gppl/builtins/builtin_support.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "gppl/builtins/display_format.hpp"

namespace gppl::builtin {

// ---------------------------------------------------------------------------------------------
// Errors and argument access

[[noreturn]] void out_of_range(const FunctionSignature& f, std::string_view detail) {
  throw Error(387, Position{}, fmt::format("Argument of function out of range: {}: {}", f.name, detail));
}

[[noreturn]] void zero_divide(const FunctionSignature& f) {
  throw Error(407, Position{}, fmt::format("Zero divide in {}", f.name));
}

[[noreturn]] void overflow(const FunctionSignature& f) {
  throw Error(410, Position{}, fmt::format("Val: number out of range: the result of {} is too large", f.name));
}

double number(const Value& v) {
  switch (v.type) {
    case Type::Numeric: return v.numeric;
    case Type::Integer: return static_cast<double>(v.integer);
    case Type::Logical: return v.logical ? 1.0 : 0.0;
    case Type::String: break;
  }
  throw Error(386, Position{}, "Variable is not numeric: a number was expected, not a string");
}

std::int64_t whole(const Value& v) {
  switch (v.type) {
    case Type::Integer: return v.integer;
    case Type::Logical: return v.logical ? 1 : 0;
    case Type::Numeric: return static_cast<std::int64_t>(std::clamp(std::trunc(v.numeric), -9e18, 9e18));
    case Type::String: break;
  }
  throw Error(386, Position{}, "Variable is not numeric: an integer was expected, not a string");
}

const std::string& text(const Value& v) {
  if (v.type != Type::String) throw Error(394, Position{}, "Variable is not string variable: a string was expected");
  return v.text;
}

std::optional<double> integral(double x) {
  double r = std::round(x);
  if (std::fabs(x - r) <= integral_tolerance) return r;
  return std::nullopt;
}

Value numeric_result(const FunctionSignature& f, double r) {
  if (!(std::fabs(r) <= max_numeric)) overflow(f);
  return Value::of_numeric(r == 0 ? 0.0 : r);  // no negative zero
}

Value integer_result(const FunctionSignature& f, std::int64_t r) {
  if (r > max_integer || r < -max_integer) overflow(f);
  return Value::of_integer(r);
}

double clean(double r, double reference) {
  double magnitude = std::max(std::fabs(reference), std::fabs(r));
  if (r == 0 || magnitude == 0 || !std::isfinite(magnitude)) return r;
  int decimals = 14 - static_cast<int>(std::floor(std::log10(magnitude)));
  return round_half_away(r, decimals);
}

Builtin fn(std::string_view name, Type result, std::vector<Type> parameters, Impl impl) {
  std::size_t count = parameters.size();
  return {FunctionSignature{name, result, std::move(parameters), count}, impl};
}

}  // namespace gppl::builtin
