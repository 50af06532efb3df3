// GPPL built-in numeric functions (angles in degrees) and the logical even/odd.
#include "gppl/builtins/builtin_support.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "gppl/builtins/display_format.hpp"

namespace gppl::builtin {

namespace {

// ---------------------------------------------------------------------------------------------
// Angles in degrees. Exact multiples of 30 degrees give exact results where they are rational,
// so cos(90) is exactly 0 (spec 9.1, "Exactness").

double to_radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
double to_degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

double sin_degrees(double a) {
  a = std::fmod(a, 360.0);
  if (a < 0) a += 360.0;
  if (std::fmod(a, 30.0) == 0) {
    const double s60 = std::sqrt(3.0) / 2;
    static const double table[12] = {0, 0.5, s60, 1, s60, 0.5, 0, -0.5, -s60, -1, -s60, -0.5};
    return table[static_cast<int>(a / 30.0) % 12];
  }
  return std::sin(to_radians(a > 180.0 ? a - 360.0 : a));
}

double cos_degrees(double a) { return sin_degrees(std::fmod(a, 360.0) + 90.0); }

// tan(90) stays the huge finite value of tan(pi/2) (the manual prints 1.632455E16).
double tan_degrees(double a) {
  a = std::fmod(a, 180.0);
  if (a < 0) a += 180.0;
  if (a == 0) return 0;
  if (a == 45) return 1;
  if (a == 135) return -1;
  return std::tan(to_radians(a > 90.0 ? a - 180.0 : a));
}

// Inverse trigonometry, rounded to 1e-12 degree so that atan(1) is exactly 45.
double angle_result(double radians) { return round_half_away(to_degrees(radians), 12); }

double angle_of(const FunctionSignature& f, double x, double y) {
  if (x == 0 && y == 0) out_of_range(f, "x and y are both zero");
  double a = angle_result(std::atan2(y, x));
  return a == -180.0 ? 180.0 : a;  // the range is (-180, 180]
}

double inverse_trig_argument(const FunctionSignature& f, double x) {
  if (std::fabs(x) > 1.0 + 1e-12) out_of_range(f, fmt::format("{} is outside [-1, 1]", x));
  return std::clamp(x, -1.0, 1.0);
}

// ---------------------------------------------------------------------------------------------
// Numeric functions

Value f_abs(const FunctionSignature& f, Args a) {
  if (integer_like(a[0])) return integer_result(f, std::abs(std::clamp(whole(a[0]), -INT64_MAX, INT64_MAX)));
  return numeric_result(f, std::fabs(number(a[0])));
}

Value f_square(const FunctionSignature& f, Args a) {
  if (integer_like(a[0])) {
    std::int64_t x = whole(a[0]), r = 0;
    if (__builtin_mul_overflow(x, x, &r)) overflow(f);
    return integer_result(f, r);
  }
  double x = number(a[0]);
  return numeric_result(f, x * x);
}

Value f_mod(const FunctionSignature& f, Args a) {
  if (integer_like(a[0]) && integer_like(a[1])) {
    std::int64_t x = whole(a[0]), y = whole(a[1]);
    if (y == 0) zero_divide(f);
    return integer_result(f, y == -1 ? 0 : x % y);  // C remainder: the sign of a
  }
  double x = number(a[0]), y = number(a[1]);
  if (y == 0) zero_divide(f);
  return numeric_result(f, clean(std::fmod(x, y), x));
}

Value f_int(const FunctionSignature& f, Args a) {
  double x = number(a[0]);
  double r = integral(x).value_or(std::trunc(x));
  if (!(std::fabs(r) <= static_cast<double>(max_integer))) out_of_range(f, fmt::format("{} is beyond the integer range", x));
  return Value::of_integer(static_cast<std::int64_t>(r));
}

Value f_frac(const FunctionSignature& f, Args a) {
  double x = std::fabs(number(a[0]));  // non-negative, as the manual's frac(-12.345) = 0.345
  return numeric_result(f, clean(x - std::floor(x), x));
}

Value f_sign(const FunctionSignature&, Args a) {
  double x = number(a[0]);
  return Value::of_integer(x > 0 ? 1 : x < 0 ? -1 : 0);
}

Value f_pow(const FunctionSignature& f, Args a) {
  double b = number(a[0]), p = number(a[1]);
  if (b == 0 && !(p > 0)) out_of_range(f, "a zero base needs a positive exponent");
  if (b < 0) {
    auto whole_p = integral(p);
    if (!whole_p) out_of_range(f, "a negative base needs a whole exponent");
    p = *whole_p;
  }
  return numeric_result(f, std::pow(b, p));
}

Value f_round(const FunctionSignature& f, Args a) {
  auto digits = integral(number(a[1]));
  if (!digits) out_of_range(f, "the number of digits must be a whole number");
  return numeric_result(f, round_half_away(number(a[0]), static_cast<int>(std::clamp(*digits, -400.0, 400.0))));
}

Value f_round2val(const FunctionSignature& f, Args a) {
  double c = number(a[0]), d = number(a[1]);
  if (d == 0) zero_divide(f);
  return numeric_result(f, clean(round_half_away(c / d, 0) * d, c));
}

Value f_log(const FunctionSignature& f, Args a) {
  double x = number(a[0]);
  if (!(x > 0)) out_of_range(f, "the argument must be positive");
  return numeric_result(f, f.name == "log" ? std::log(x) : std::log10(x));
}

Value f_sqrt(const FunctionSignature& f, Args a) {
  double x = number(a[0]);
  if (x < 0) out_of_range(f, "the argument must not be negative");
  return numeric_result(f, std::sqrt(x));
}

Value f_acos(const FunctionSignature& f, Args a) { return numeric_result(f, angle_result(std::acos(inverse_trig_argument(f, number(a[0]))))); }
Value f_asin(const FunctionSignature& f, Args a) { return numeric_result(f, angle_result(std::asin(inverse_trig_argument(f, number(a[0]))))); }
Value f_atan(const FunctionSignature& f, Args a) { return numeric_result(f, angle_result(std::atan(number(a[0])))); }
Value f_ang(const FunctionSignature& f, Args a) { return numeric_result(f, angle_of(f, number(a[0]), number(a[1]))); }
Value f_atan2(const FunctionSignature& f, Args a) { return numeric_result(f, angle_of(f, number(a[1]), number(a[0]))); }
Value f_sin(const FunctionSignature& f, Args a) { return numeric_result(f, sin_degrees(number(a[0]))); }
Value f_cos(const FunctionSignature& f, Args a) { return numeric_result(f, cos_degrees(number(a[0]))); }
Value f_tan(const FunctionSignature& f, Args a) { return numeric_result(f, tan_degrees(number(a[0]))); }
Value f_dist(const FunctionSignature& f, Args a) { return numeric_result(f, std::hypot(number(a[0]), number(a[1]))); }
Value f_exp(const FunctionSignature& f, Args a) { return numeric_result(f, std::exp(number(a[0]))); }

// The angle in [0, 360): norm360(-90) is 270, norm360(720) is 0.
Value f_norm360(const FunctionSignature& f, Args a) {
  const double x = number(a[0]);
  double r = std::fmod(x, 360.0);
  if (r < 0) r += 360.0;
  r = clean(r, x);
  return numeric_result(f, r >= 360.0 ? 0.0 : r);
}
Value f_todeg(const FunctionSignature& f, Args a) { return numeric_result(f, to_degrees(number(a[0]))); }
Value f_torad(const FunctionSignature& f, Args a) { return numeric_result(f, to_radians(number(a[0]))); }


Value parity(Args a, bool want_even) {
  auto x = integral(number(a[0]));
  if (!x) return Value::of_logical(false);
  bool even = std::fmod(*x, 2.0) == 0;
  return Value::of_logical(even == want_even);
}

Value f_even(const FunctionSignature&, Args a) { return parity(a, true); }
Value f_odd(const FunctionSignature&, Args a) { return parity(a, false); }

}  // namespace

std::vector<Builtin> numeric_functions() {
  constexpr Type I = Type::Integer, N = Type::Numeric;
  return {
      fn("abs", N, {N}, f_abs),         fn("acos", N, {N}, f_acos),       fn("ang", N, {N, N}, f_ang),
      fn("asin", N, {N}, f_asin),       fn("atan", N, {N}, f_atan),       fn("atan2", N, {N, N}, f_atan2),
      fn("cos", N, {N}, f_cos),         fn("dist", N, {N, N}, f_dist),    fn("exp", N, {N}, f_exp),
      fn("frac", N, {N}, f_frac),       fn("int", I, {N}, f_int),         fn("log", N, {N}, f_log),
      fn("log10", N, {N}, f_log),       fn("mod", N, {N, N}, f_mod),      fn("norm360", N, {N}, f_norm360),
      fn("pow", N, {N, N}, f_pow),
      fn("round", N, {N, N}, f_round),  fn("round2val", N, {N, N}, f_round2val),
      fn("sign", I, {N}, f_sign),       fn("sin", N, {N}, f_sin),         fn("sqrt", N, {N}, f_sqrt),
      fn("square", N, {N}, f_square),   fn("tan", N, {N}, f_tan),         fn("todeg", N, {N}, f_todeg),
      fn("torad", N, {N}, f_torad),
  };
}

std::vector<Builtin> logical_functions() {
  constexpr Type L = Type::Logical, N = Type::Numeric;
  return {fn("even", L, {N}, f_even), fn("odd", L, {N}, f_odd)};
}

}  // namespace gppl::builtin
