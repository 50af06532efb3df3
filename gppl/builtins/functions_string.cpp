// GPPL built-in string functions, tonum/tostr, and the clock (date, time).
#include "gppl/builtins/builtin_support.hpp"

#include <charconv>
#include <cstdlib>
#include <ctime>

#include <fmt/format.h>

#include "gppl/builtins/display_format.hpp"

namespace gppl::builtin {

namespace {

constexpr std::size_t max_string_length = std::size_t{1} << 24;  // dup/space: a runaway guard


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

// instr(s, sub [, start]): the search begins at position `start` (1-based, at least 1); a start
// past the end finds nothing. The result counts from the beginning of `s`.
Value f_instr(const FunctionSignature& f, Args a) {
  const std::string& s = text(a[0]);
  const std::string& sub = text(a[1]);
  const std::int64_t start = a.size() > 2 ? whole(a[2]) : 1;
  if (start < 1) out_of_range(f, fmt::format("the start position {} is below 1", start));
  if (sub.empty() || start > static_cast<std::int64_t>(s.size())) return Value::of_integer(0);
  std::size_t at = s.find(sub, static_cast<std::size_t>(start - 1));
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

// The month in capitals: a SolidCAM 2024 trace shows JUL where the manual prints 12-Apr-1994
// (posts cut the month out with substr and print it as it is); real output wins. The day is
// padded with a blank, not a zero: SolidCAM's Siemens posts print ` 9-JUL-2026` rearranged by
// substr as `JUL- 9-2026` (docs/gppl-formats.md).
Value f_date(const FunctionSignature&, Args) {
  static constexpr const char* months[] = {"JAN", "FEB", "MAR", "APR", "MAY", "JUN",
                                           "JUL", "AUG", "SEP", "OCT", "NOV", "DEC"};
  std::tm tm = now();
  return Value::of_string(fmt::format("{:2}-{}-{:04}", tm.tm_mday, months[tm.tm_mon % 12], tm.tm_year + 1900));
}

Value f_time(const FunctionSignature&, Args) {
  std::tm tm = now();
  return Value::of_string(fmt::format("{:02}:{:02}:{:02}", tm.tm_hour, tm.tm_min, tm.tm_sec));
}

}  // namespace

std::vector<Builtin> string_functions() {
  constexpr Type I = Type::Integer, N = Type::Numeric, S = Type::String;
  return {
      fn("date", S, {}, f_date),        fn("dup", S, {S, I}, f_dup),      fn("instr", I, {S, S, I}, f_instr),
      fn("left", S, {S, I}, f_left),    fn("lower", S, {S}, f_lower),     fn("replace", S, {S, S, S, I}, f_replace),
      fn("rev", S, {S}, f_rev),         fn("right", S, {S, I}, f_right),  fn("space", S, {I}, f_space),
      fn("strlen", I, {S}, f_strlen),   fn("substr", S, {S, I, I}, f_substr), fn("time", S, {}, f_time),
      fn("tonum", N, {S}, f_tonum),     fn("tostr", S, {N, S}, f_tostr),  fn("trim", S, {S}, f_trim),
      fn("upper", S, {S}, f_upper),
  };
}

}  // namespace gppl::builtin
