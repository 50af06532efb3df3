// GPPL internal functions: the signature table, argument access, and every implementation.
#include "gppl/functions.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <numbers>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "gppl/display_format.hpp"

namespace gppl {

namespace {

using Args = std::span<const Value>;
using Impl = Value (*)(const FunctionSignature& f, Args a);

constexpr std::size_t max_string_length = std::size_t{1} << 24;  // dup/space: a runaway guard
constexpr double max_numeric = 1e300;                            // spec 3.1
constexpr double integral_tolerance = 1e-9;                      // spec 4.5: 2.9999999999 is 3

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

bool integer_like(const Value& v) { return v.type == Type::Integer || v.type == Type::Logical; }

// Whole numbers within the tolerance snap to the whole number; nullopt when not integral.
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

// Removes binary representation noise below the 15th significant digit of `reference`:
// frac(12.345) is 0.345, mod(9.2, 4) is 1.2.
double clean(double r, double reference) {
  double magnitude = std::max(std::fabs(reference), std::fabs(r));
  if (r == 0 || magnitude == 0 || !std::isfinite(magnitude)) return r;
  int decimals = 14 - static_cast<int>(std::floor(std::log10(magnitude)));
  return round_half_away(r, decimals);
}

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
Value f_todeg(const FunctionSignature& f, Args a) { return numeric_result(f, to_degrees(number(a[0]))); }
Value f_torad(const FunctionSignature& f, Args a) { return numeric_result(f, to_radians(number(a[0]))); }

// ---------------------------------------------------------------------------------------------
// String functions

std::int64_t count_argument(const FunctionSignature& f, const Value& v, std::string_view what) {
  std::int64_t n = whole(v);
  if (n < 0) out_of_range(f, fmt::format("{} must not be negative", what));
  return n;
}

Value repeated(const FunctionSignature& f, std::string_view s, std::int64_t count) {
  if (!s.empty() && static_cast<std::uint64_t>(count) > max_string_length / s.size())
    out_of_range(f, fmt::format("the result would be longer than {} characters", max_string_length));
  std::string r;
  if (s.empty()) return Value::of_string(r);
  r.reserve(s.size() * static_cast<std::size_t>(count));
  for (std::int64_t i = 0; i < count; ++i) r += s;
  return Value::of_string(std::move(r));
}

Value f_dup(const FunctionSignature& f, Args a) { return repeated(f, text(a[0]), count_argument(f, a[1], "the count")); }
Value f_space(const FunctionSignature& f, Args a) { return repeated(f, " ", count_argument(f, a[0], "the length")); }

Value f_instr(const FunctionSignature&, Args a) {
  const std::string& s = text(a[0]);
  const std::string& sub = text(a[1]);
  if (sub.empty()) return Value::of_integer(0);
  std::size_t at = s.find(sub);
  return Value::of_integer(at == std::string::npos ? 0 : static_cast<std::int64_t>(at) + 1);
}

Value f_left(const FunctionSignature& f, Args a) {
  const std::string& s = text(a[0]);
  auto n = static_cast<std::size_t>(std::min<std::int64_t>(count_argument(f, a[1], "the length"), static_cast<std::int64_t>(s.size())));
  return Value::of_string(s.substr(0, n));
}

Value f_right(const FunctionSignature& f, Args a) {
  const std::string& s = text(a[0]);
  auto n = static_cast<std::size_t>(std::min<std::int64_t>(count_argument(f, a[1], "the length"), static_cast<std::int64_t>(s.size())));
  return Value::of_string(s.substr(s.size() - n));
}

Value f_substr(const FunctionSignature& f, Args a) {
  const std::string& s = text(a[0]);
  std::int64_t from = whole(a[1]);
  if (from < 1 || from > static_cast<std::int64_t>(s.size()))
    out_of_range(f, fmt::format("position {} is outside [1, {}]", from, s.size()));
  std::int64_t len = count_argument(f, a[2], "the length");
  return Value::of_string(s.substr(static_cast<std::size_t>(from - 1), static_cast<std::size_t>(std::min<std::int64_t>(len, static_cast<std::int64_t>(s.size())))));
}

Value map_case(const std::string& s, char from, char to) {
  std::string r = s;
  for (char& c : r)
    if (c >= from && c <= from + 25) c = static_cast<char>(c - from + to);
  return Value::of_string(std::move(r));
}

Value f_lower(const FunctionSignature&, Args a) { return map_case(text(a[0]), 'A', 'a'); }
Value f_upper(const FunctionSignature&, Args a) { return map_case(text(a[0]), 'a', 'A'); }
Value f_rev(const FunctionSignature&, Args a) { return Value::of_string(std::string(text(a[0]).rbegin(), text(a[0]).rend())); }
Value f_strlen(const FunctionSignature&, Args a) { return Value::of_integer(static_cast<std::int64_t>(text(a[0]).size())); }

Value f_trim(const FunctionSignature&, Args a) {
  const std::string& s = text(a[0]);
  std::size_t end = s.find_last_not_of(' ');
  return Value::of_string(end == std::string::npos ? std::string() : s.substr(0, end + 1));
}

// Occurrences are found left to right without overlap; k > 0 replaces the first k, k < 0 the
// last |k|, 0 (or omitted) all. The replacement text is never rescanned.
Value f_replace(const FunctionSignature&, Args a) {
  const std::string& s = text(a[0]);
  const std::string& old = text(a[1]);
  const std::string& with = text(a[2]);
  std::int64_t k = a.size() > 3 ? whole(a[3]) : 0;
  if (old.empty()) return Value::of_string(s);
  std::vector<std::size_t> at;
  for (std::size_t p = s.find(old); p != std::string::npos; p = s.find(old, p + old.size())) at.push_back(p);
  auto total = static_cast<std::int64_t>(at.size());
  std::int64_t first = 0, last = total;  // occurrences [first, last) are replaced
  if (k > 0) last = std::min(k, total);
  if (k < 0) first = std::max<std::int64_t>(0, total + k);
  std::string r;
  std::size_t copied = 0;
  for (std::int64_t i = first; i < last; ++i) {
    std::size_t p = at[static_cast<std::size_t>(i)];
    r.append(s, copied, p - copied);
    r += with;
    copied = p + old.size();
  }
  r.append(s, copied);
  return Value::of_string(std::move(r));
}

// [blanks] [sign] [digits] [.digits] [E [sign] digits] [blanks]
Value f_tonum(const FunctionSignature& f, Args a) {
  const std::string& s = text(a[0]);
  auto blank = [](char c) { return c == ' ' || c == '\t'; };
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  std::size_t i = 0, n = s.size();
  while (i < n && blank(s[i])) ++i;
  bool negative = i < n && s[i] == '-';
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t start = i, mantissa_digits = 0;
  while (i < n && digit(s[i])) ++i, ++mantissa_digits;
  if (i < n && s[i] == '.')
    for (++i; i < n && digit(s[i]); ++i) ++mantissa_digits;
  if (mantissa_digits > 0 && i < n && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < n && (s[j] == '+' || s[j] == '-')) ++j;
    std::size_t exponent_start = j;
    while (j < n && digit(s[j])) ++j;
    if (j > exponent_start) i = j;
  }
  std::size_t end = i;
  while (i < n && blank(s[i])) ++i;
  if (mantissa_digits == 0 || i != n) out_of_range(f, fmt::format("'{}' is not a number", s));
  std::string mantissa = "0";  // so that ".5" parses
  mantissa.append(s, start, end - start);
  double value = 0;
  auto res = std::from_chars(mantissa.data(), mantissa.data() + mantissa.size(), value);
  if (res.ec == std::errc::result_out_of_range) overflow(f);
  return numeric_result(f, negative ? -value : value);
}

Value f_tostr(const FunctionSignature&, Args a) {
  number(a[0]);  // a string is not formatted: error 386
  // No format, or an empty one (an unset numeric_def_f), means the manual's default '5.3'.
  std::string_view spec = a.size() > 1 ? std::string_view(text(a[1])) : std::string_view();
  DisplayFormat format = parse_display_format(spec.empty() ? std::string_view("5.3") : spec);
  return Value::of_string(format_value(format, a[0]));
}

// The clock: SOURCE_DATE_EPOCH (seconds, UTC) when set, for reproducible output; else local time.
std::tm now() {
  std::tm tm{};
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
    long long seconds = 0;
    auto res = std::from_chars(epoch, epoch + std::char_traits<char>::length(epoch), seconds);
    if (res.ec == std::errc{} && *res.ptr == '\0') {
      auto t = static_cast<std::time_t>(seconds);
      gmtime_r(&t, &tm);
      return tm;
    }
  }
  std::time_t t = std::time(nullptr);
  localtime_r(&t, &tm);
  return tm;
}

Value f_date(const FunctionSignature&, Args) {
  static constexpr const char* months[] = {"Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                           "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
  std::tm tm = now();
  return Value::of_string(fmt::format("{:02}-{}-{:04}", tm.tm_mday, months[tm.tm_mon % 12], tm.tm_year + 1900));
}

Value f_time(const FunctionSignature&, Args) {
  std::tm tm = now();
  return Value::of_string(fmt::format("{:02}:{:02}:{:02}", tm.tm_hour, tm.tm_min, tm.tm_sec));
}

// ---------------------------------------------------------------------------------------------
// Logical functions

Value parity(Args a, bool want_even) {
  auto x = integral(number(a[0]));
  if (!x) return Value::of_logical(false);
  bool even = std::fmod(*x, 2.0) == 0;
  return Value::of_logical(even == want_even);
}

Value f_even(const FunctionSignature&, Args a) { return parity(a, true); }
Value f_odd(const FunctionSignature&, Args a) { return parity(a, false); }

// ---------------------------------------------------------------------------------------------
// The table

struct Builtin {
  FunctionSignature signature;
  Impl impl;
};

Builtin fn(std::string_view name, Type result, std::vector<Type> parameters, Impl impl) {
  std::size_t count = parameters.size();
  return {FunctionSignature{name, result, std::move(parameters), count}, impl};
}

struct Table {
  std::vector<FunctionSignature> signatures;
  std::vector<Impl> impls;
};

const Table& table() {
  static const Table t = [] {
    constexpr Type I = Type::Integer, N = Type::Numeric, L = Type::Logical, S = Type::String;
    std::vector<Builtin> all = {
        fn("abs", N, {N}, f_abs),         fn("acos", N, {N}, f_acos),       fn("ang", N, {N, N}, f_ang),
        fn("asin", N, {N}, f_asin),       fn("atan", N, {N}, f_atan),       fn("atan2", N, {N, N}, f_atan2),
        fn("cos", N, {N}, f_cos),         fn("dist", N, {N, N}, f_dist),    fn("exp", N, {N}, f_exp),
        fn("frac", N, {N}, f_frac),       fn("int", I, {N}, f_int),         fn("log", N, {N}, f_log),
        fn("log10", N, {N}, f_log),       fn("mod", N, {N, N}, f_mod),      fn("pow", N, {N, N}, f_pow),
        fn("round", N, {N, N}, f_round),  fn("round2val", N, {N, N}, f_round2val),
        fn("sign", I, {N}, f_sign),       fn("sin", N, {N}, f_sin),         fn("sqrt", N, {N}, f_sqrt),
        fn("square", N, {N}, f_square),   fn("tan", N, {N}, f_tan),         fn("todeg", N, {N}, f_todeg),
        fn("torad", N, {N}, f_torad),
        fn("date", S, {}, f_date),        fn("dup", S, {S, I}, f_dup),      fn("instr", I, {S, S}, f_instr),
        fn("left", S, {S, I}, f_left),    fn("lower", S, {S}, f_lower),     fn("replace", S, {S, S, S, I}, f_replace),
        fn("rev", S, {S}, f_rev),         fn("right", S, {S, I}, f_right),  fn("space", S, {I}, f_space),
        fn("strlen", I, {S}, f_strlen),   fn("substr", S, {S, I, I}, f_substr), fn("time", S, {}, f_time),
        fn("tonum", N, {S}, f_tonum),     fn("tostr", S, {N, S}, f_tostr),  fn("trim", S, {S}, f_trim),
        fn("upper", S, {S}, f_upper),
        fn("even", L, {N}, f_even),       fn("odd", L, {N}, f_odd),
    };
    Table t;
    for (auto& b : all) {
      FunctionSignature& s = b.signature;
      if (s.name == "abs" || s.name == "square" || s.name == "mod") s.integer_if_integer_args = true;
      if (s.name == "replace") s.min_args = 3;
      if (s.name == "tostr") s.min_args = 1, s.format_argument = true;
      if (s.name == "date" || s.name == "time") s.no_parentheses = true;
      t.signatures.push_back(std::move(s));
      t.impls.push_back(b.impl);
    }
    return t;
  }();
  return t;
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char c = a[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != b[i]) return false;
  }
  return true;
}

}  // namespace

const FunctionSignature* find_function(std::string_view name) {
  for (const auto& s : table().signatures)
    if (equal_ignoring_case(name, s.name)) return &s;
  return nullptr;
}

std::span<const FunctionSignature> all_functions() { return table().signatures; }

Type result_type(const FunctionSignature& f, std::span<const Type> argument_types) {
  if (!f.integer_if_integer_args) return f.result;
  bool all_integer = std::all_of(argument_types.begin(), argument_types.end(),
                                 [](Type t) { return t == Type::Integer || t == Type::Logical; });
  return all_integer ? Type::Integer : f.result;
}

Value call_function(const FunctionSignature& f, std::span<const Value> args) {
  const Table& t = table();
  const FunctionSignature* own = &f;
  if (own < t.signatures.data() || own >= t.signatures.data() + t.signatures.size()) own = find_function(f.name);
  if (own == nullptr) throw std::invalid_argument(fmt::format("gppl: '{}' is not a built-in function", f.name));
  if (args.size() < own->min_args || args.size() > own->parameters.size())
    throw std::invalid_argument(fmt::format("gppl: {} takes {} to {} arguments, got {}", own->name, own->min_args,
                                            own->parameters.size(), args.size()));
  return t.impls[static_cast<std::size_t>(own - t.signatures.data())](*own, args);
}

}  // namespace gppl
