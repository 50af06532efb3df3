// Display formats: the printer, run once per printed value (the parser is display_format_parse.cpp).
//
// The fast path turns the value into one integer, `units` = the value rounded to N decimals times
// 10^N, and writes its digits straight into the output. Integers need no rounding. For a numeric
// value the rounding is decided by one multiplication s = |x| * 10^N whenever that is provably the
// same as the documented rule (15 significant digits first, then half away from zero at N
// decimals); otherwise, and for N > 15, the exact printer in display_format_exact.cpp decides.
//
// Why one multiplication suffices: let D be |x| taken to 15 significant digits. With
// 10^e <= |x| < 10^(e+1), |x - D| <= 0.5 * 10^(e-14) <= 5e-15 * |x|, so D * 10^N lies within
// 5e-15 * s of the exact s. The computed s is off by at most 2^-53 * s (10^N is exact up to 1e22,
// the product is rounded once). Rounding half away from zero only jumps at half-integers, so when
// the computed s is farther than 6e-15 * s from the nearest half-integer, D * 10^N rounds to the
// same integer as s does. That condition also excludes every case where D itself has no digit
// left to round (s >= 1e14 makes the bound at least 0.6, more than any distance to a half), and
// s < 2^52 keeps the integer part and the fraction of s exact. The tests compare this path with
// the exact printer on a large table of values for every format shape.
#include "gppl/builtins/display_format.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>

#include "gppl/builtins/display_format_internal.hpp"

namespace gppl {

namespace {

constexpr int max_fast_fraction = fast::max_fraction;
constexpr std::uint64_t powers_of_ten[] = {1,
                                           10,
                                           100,
                                           1'000,
                                           10'000,
                                           100'000,
                                           1'000'000,
                                           10'000'000,
                                           100'000'000,
                                           1'000'000'000,
                                           10'000'000'000,
                                           100'000'000'000,
                                           1'000'000'000'000,
                                           10'000'000'000'000,
                                           100'000'000'000'000,
                                           1'000'000'000'000'000,
                                           10'000'000'000'000'000,
                                           100'000'000'000'000'000,
                                           1'000'000'000'000'000'000,
                                           10'000'000'000'000'000'000u};
constexpr double double_powers_of_ten[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                           1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
static_assert(std::size(double_powers_of_ten) == max_fast_fraction + 1);

constexpr double exact_fraction_limit = 4503599627370496.0;  // 2^52: below it s - floor(s) is exact
constexpr double decision_margin = 6e-15;                    // see the proof at the top

}  // namespace

bool fast::round_to_units(double magnitude, int n, std::uint64_t& units) {
  const double s = magnitude * double_powers_of_ten[n];
  if (!(s < exact_fraction_limit)) return false;
  const auto whole = static_cast<std::int64_t>(s);  // signed: 0 <= s < 2^52, and the conversion is one instruction
  const double from_half = (s - static_cast<double>(whole)) - 0.5;
  if (std::fabs(from_half) <= s * decision_margin) return false;
  units = static_cast<std::uint64_t>(whole) + (from_half > 0 ? 1 : 0);
  return true;
}

namespace {

// "000".."999", four bytes each: three digits, then the count of trailing zeros (bits 0-1, 3 for
// "000") and of significant digits (bits 2-3, 0 for "000"). Four bytes of slack after the last.
constexpr auto digit_triples = [] {
  std::array<char, 4004> t{};
  for (int i = 0; i < 1000; ++i) {
    const int digits[3] = {i / 100, i / 10 % 10, i % 10};
    int trailing = 0;
    while (trailing < 3 && digits[2 - trailing] == 0) ++trailing;
    const int significant = i >= 100 ? 3 : i >= 10 ? 2 : i >= 1 ? 1 : 0;
    for (int d = 0; d < 3; ++d) t[static_cast<std::size_t>(4 * i + d)] = static_cast<char>('0' + digits[d]);
    t[static_cast<std::size_t>(4 * i + 3)] = static_cast<char>(trailing | significant << 2);
  }
  return t;
}();

const char* triple(std::uint64_t v) { return digit_triples.data() + 4 * v; }

// "0".."999" without leading zeros, left-aligned in four bytes whose last holds the digit count:
// a number below 1000 is one four-byte copy and one add (the bytes past its digits are scratch).
constexpr auto short_numbers = [] {
  std::array<char, 4000> t{};
  for (int i = 0; i < 1000; ++i) {
    const int len = i >= 100 ? 3 : i >= 10 ? 2 : 1;
    for (int d = 0, v = i; d < len; ++d, v /= 10) t[static_cast<std::size_t>(4 * i + len - 1 - d)] = static_cast<char>('0' + v % 10);
    t[static_cast<std::size_t>(4 * i + 3)] = static_cast<char>(len);
  }
  return t;
}();

// Writes the integer digits of v so that they end at `end` (none for 0); returns where they
// start. Up to two zeros before the start are scratch.
char* write_integer_digits(char* end, std::uint64_t v) {
  char* first = end;
  while (v >= 1000) {
    const std::uint64_t q = v / 1000;
    first -= 3;
    std::memcpy(first, triple(v - q * 1000), 3);
    v = q;
  }
  const char* top = triple(v);
  std::memcpy(first - 3, top, 3);  // with its leading zeros, which the caller leaves out
  return first - (top[3] >> 2);
}

// Writes the n fraction digits of v (< 10^n, leading zeros included) from `start`, plus scratch
// up to four bytes; returns how many remain once trailing zeros are dropped.
int write_fraction_digits(char* start, std::uint64_t v, int n) {
  if (n <= 3) {  // one table entry: v scaled to three digits, whose extra digits are zeros
    static constexpr std::uint64_t widen[] = {1000, 100, 10, 1};
    const char* t = triple(v * widen[n]);
    std::memcpy(start, t, 4);
    return 3 - (t[3] & 3);
  }
  for (char* p = start + n; p != start; v /= 10) *--p = static_cast<char>('0' + v % 10);
  int kept = n;
  while (kept > 0 && start[kept - 1] == '0') --kept;
  return kept;
}

char* fill(char* p, int count, char c) {
  if (count > 0) {
    std::memset(p, c, static_cast<std::size_t>(count));
    p += count;
  }
  return p;
}

// Lays out the number part for the rounded value units * 10^-N (N <= 15), exactly as the exact
// printer does. Returns the end, or nullptr when option d suppresses the item.
char* write_units(char* p, const DisplayFormat& f, std::uint64_t units, bool negative) {
  if (units == 0 && f.delete_if_zero) return nullptr;
  const int n = f.frac_digits;

  std::uint64_t whole = units, fraction = 0;
  if (n > 0) {
    whole = units / powers_of_ten[n];
    fraction = units - whole * powers_of_ten[n];
  }
  // Digits around a point at digits + 24: up to 20 integer digits before it, up to 15 fraction
  // digits after it. The copies below move fixed sizes (a few register moves, no library call);
  // bytes past the digits are scratch that later writes cover or the length leaves out.
  char digits[48];
  char* const point_at = digits + 24;
  const int int_len = static_cast<int>(point_at - write_integer_digits(point_at, whole));
  const int kept = write_fraction_digits(point_at, fraction, n);

  if (f.plain) {  // the common shapes: [-] digits (a 0 if none) [. kept digits]
    *p = '-';
    p += negative ? 1 : 0;
    *p = '0';
    p += int_len == 0 ? 1 : 0;
    std::memcpy(p, point_at - int_len, 20);
    p += int_len;
    if (kept == 0 && f.conditional_point) return p;
    *p++ = '.';
    std::memcpy(p, point_at, 16);
    return p + kept;
  }

  // Fraction digits kept: trailing zeros go down to n (/n), unless 'z'; blanks replace them
  // with a trailing blank; option p drops a zero fraction together with the point.
  int frac_len = n;
  int frac_blanks = 0;
  bool point = !f.no_point;
  if (f.trail != DisplayFormat::Pad::Zero || f.conditional_point) {
    if (kept == 0 && f.conditional_point) {
      point = false;
      frac_len = 0;
    } else if (f.trail != DisplayFormat::Pad::Zero) {
      frac_len = kept > f.min_frac_digits ? kept : (f.min_frac_digits < n ? f.min_frac_digits : n);
      if (f.trail == DisplayFormat::Pad::Blank) frac_blanks = n - frac_len;
    }
  }

  int zeros = f.min_int_digits > int_len ? f.min_int_digits - int_len : 0;
  if (int_len + zeros == 0 && frac_len == 0) zeros = 1;  // never a number without any digit
  if (f.lead == DisplayFormat::Pad::Blank) p = fill(p, f.int_digits - (int_len + zeros), ' ');
  if (negative)
    *p++ = '-';
  else if (f.sign == DisplayFormat::Sign::Always)
    *p++ = '+';
  if (f.lead == DisplayFormat::Pad::Zero) p = fill(p, f.int_digits - (int_len + zeros), '0');
  p = fill(p, zeros, '0');
  std::memcpy(p, point_at - int_len, 20);  // at most 20 integer digits (2^64)
  p += int_len;
  if (point) *p++ = '.';
  std::memcpy(p, point_at, 16);  // at most 15 fraction digits
  p += frac_len;
  return fill(p, frac_blanks, ' ');
}

// The number part through the fast path; `handled` is false when the exact printer must decide.
char* format_number(char* p, const DisplayFormat& f, const Value& v, bool& handled) {
  const int n = f.frac_digits;
  std::uint64_t units = 0;
  bool negative = false;
  handled = false;
  if (formats_as_integer(f, v)) {  // integers and logicals: exact, no rounding
    const std::int64_t i = integer_of(v);
    const std::uint64_t magnitude = i < 0 ? 0 - static_cast<std::uint64_t>(i) : static_cast<std::uint64_t>(i);
    if (n <= max_fast_fraction && magnitude <= UINT64_MAX / powers_of_ten[n]) {
      handled = true;
      units = magnitude * powers_of_ten[n];
    }
    negative = (i < 0) != f.invert && i != 0;
  } else {
    const double x = scaled_number(f, v);
    handled = n <= max_fast_fraction && fast::round_to_units(std::fabs(x), n, units);
    negative = x < 0 && units != 0;  // a value that rounds to zero has no sign
  }
  return handled ? write_units(p, f, units, negative) : p;
}

// The quick shapes (DisplayFormat::quick): [-]digits[.fraction] for an integer part below 10^6.
// A few table copies and no registers to save, so it pays its way on the commonest numbers
// (coordinates, feeds, G codes, block numbers); anything else falls back to the general path.
constexpr std::uint64_t quick_whole_limit = 1'000'000;

// Affixes: nothing for an empty one, else a fixed-size copy (the length decides what counts).
char* put_affix(char* p, const std::array<char, DisplayFormat::max_affix>& text, int length) {
  if (length != 0) std::memcpy(p, text.data(), DisplayFormat::max_affix);
  return p + length;
}

// A number below 1000 from short_numbers.
char* put_short(char* p, std::uint64_t v) {
  const char* t = short_numbers.data() + 4 * v;
  std::memcpy(p, t, 4);
  return p + t[3];
}

// The digits of `whole` (< quick_whole_limit) without leading zeros, a single 0 for zero.
char* put_whole(char* p, std::uint64_t whole) {
  if (whole < 1000) return put_short(p, whole);
  const std::uint64_t high = whole / 1000;
  p = put_short(p, high);
  std::memcpy(p, triple(whole - high * 1000), 4);  // the low three digits with their zeros
  return p + 3;
}

// An integer under a quick format: its digits, then a point unless option p drops it (the
// fraction is zero). nullptr when the general path must print it. Inlined into both
// write_formatted(): a call would make them save registers.
[[gnu::always_inline]] inline char* quick_integer(char* out, const DisplayFormat& f, std::int64_t i) {
  const std::uint64_t magnitude = i < 0 ? 0 - static_cast<std::uint64_t>(i) : static_cast<std::uint64_t>(i);
  if (!f.quick || magnitude >= quick_whole_limit) return nullptr;
  char* p = put_affix(out, f.prefix, f.prefix_length);
  *p = '-';
  p += i < 0 ? 1 : 0;
  p = put_whole(p, magnitude);
  *p = '.';
  p += f.conditional_point ? 0 : 1;
  return put_affix(p, f.postfix, f.postfix_length);
}

// A numeric value under a quick format, rounded by round_to_units: the fraction's N <= 3 digits
// are one table entry (scaled to three digits, the extra ones zeros), trailing zeros dropped.
[[gnu::always_inline]] inline char* quick_numeric(char* out, const DisplayFormat& f, double x) {
  const int n = f.frac_digits;
  std::uint64_t units = 0;
  if (!f.quick || !fast::round_to_units(std::fabs(x), n, units)) return nullptr;
  const std::uint64_t whole = units / powers_of_ten[n];
  if (whole >= quick_whole_limit) return nullptr;
  static constexpr std::uint64_t widen[] = {1000, 100, 10, 1};
  const char* t = triple((units - whole * powers_of_ten[n]) * widen[n]);
  const int kept = 3 - (t[3] & 3);
  char* p = put_affix(out, f.prefix, f.prefix_length);
  *p = '-';
  p += (units != 0) & std::signbit(x);  // a value that rounds to zero has no sign (nor has -0)
  p = put_whole(p, whole);
  *p = '.';
  p += (kept | !f.conditional_point) != 0;  // a point unless option p drops it with a zero fraction
  std::memcpy(p, t, 4);
  return put_affix(p + kept, f.postfix, f.postfix_length);
}

// The quick path for a Value: nullptr when it is not a quick case.
[[gnu::always_inline]] inline char* quick_value(char* out, const DisplayFormat& f, const Value& v) {
  if (v.type == Type::Numeric) return quick_numeric(out, f, v.numeric);
  if (v.type == Type::Integer) return quick_integer(out, f, v.integer);
  return nullptr;
}

// Everything else. Kept out of line so that the quick path saves no registers.
[[gnu::noinline]] char* write_general(char* out, const DisplayFormat& f, const Value& v) {
  // Affixes are copied whole (a fixed-size copy is a few moves; the length decides what counts).
  std::memcpy(out, f.prefix.data(), DisplayFormat::max_affix);
  char* p = out + f.prefix_length;
  bool handled = false;
  p = format_number(p, f, v, handled);
  if (!handled) p = exact::format_number(p, f, v, exact::Digits::Quick);
  if (p == nullptr) return out;  // option d: not even the affixes
  std::memcpy(p, f.postfix.data(), DisplayFormat::max_affix);
  return p + f.postfix_length;
}

[[gnu::noinline]] char* write_general_integer(char* out, const DisplayFormat& f, std::int64_t value) {
  return write_general(out, f, Value::of_integer(value));
}

}  // namespace

static_assert(formatted_room == DisplayFormat::max_affix + exact::max_number + DisplayFormat::max_affix);

char* fast::write_quick(char* out, const DisplayFormat& f, const Value& v) { return quick_value(out, f, v); }

char* write_formatted(char* out, const DisplayFormat& f, const Value& v) {
  if (char* end = quick_value(out, f, v)) return end;
  return write_general(out, f, v);
}

char* write_formatted(char* out, const DisplayFormat& f, std::int64_t value) {
  if (char* end = quick_integer(out, f, value)) return end;
  return write_general_integer(out, f, value);
}

void append_formatted(std::string& out, const DisplayFormat& f, const Value& v) {
  if (v.type == Type::String) {
    out += v.text;
    return;
  }
  char buf[formatted_room];
  const char* end = write_formatted(buf, f, v);
  out.append(buf, static_cast<std::size_t>(end - buf));
}

std::string format_value(const DisplayFormat& f, const Value& v) {
  std::string s;
  append_formatted(s, f, v);
  return s;
}

}  // namespace gppl
