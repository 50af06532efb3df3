// The exact display-format printer: the value is taken to 15 significant digits as decimal text,
// rounded half away from zero on those digits, then laid out. The fast printer
// (display_format.cpp) falls back to it whenever one multiplication cannot decide the digits.
#include "gppl/builtins/display_format_internal.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

namespace gppl {

namespace {

// ---------------------------------------------------------------------------------------------
// Decimal rounding

constexpr int significant_digits = 15;

// A non-negative decimal value: digits[0] has the weight 10^exponent, later digits the next lower
// powers; digits past `count` are zeros. count == 0 is zero.
struct Decimal {
  char digits[significant_digits + 1];
  int count = 0;
  int exponent = 0;
};

// The correctly rounded 15 significant digits of `magnitude` (> 0), through the library.
void fifteen_digits_exact(double magnitude, Decimal& d) {
  char buf[40];
  auto res = std::to_chars(buf, buf + sizeof buf, magnitude, std::chars_format::scientific, significant_digits - 1);
  // "d.dddddddddddddde+XX"
  char* e = std::find(buf, res.ptr, 'e');
  std::from_chars(e + (e[1] == '+' ? 2 : 1), res.ptr, d.exponent);
  d.digits[0] = buf[0];
  std::memcpy(d.digits + 1, buf + 2, significant_digits - 1);
}

// The same digits for the common magnitudes (1e-8 to 1e15) in a few multiplications: one exact
// power of ten, one rounding to an integer. When the product lies so close to a half that the
// multiplication's rounding could change the result, the exact path decides.
bool fifteen_digits_fast(double magnitude, Decimal& d) {
  static constexpr double powers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  static constexpr double negative_powers[] = {1e0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9};
  if (!(magnitude >= 1e-8 && magnitude < 1e15)) return false;
  auto power = [](int e) { return e >= 0 ? powers[e] : negative_powers[-e]; };
  int binary_exponent = 0;
  std::frexp(magnitude, &binary_exponent);  // magnitude in [2^(b-1), 2^b)
  int exponent = static_cast<int>(std::floor((binary_exponent - 1) * 0.30102999566398120));
  if (exponent < 14 && magnitude >= power(exponent + 1)) ++exponent;  // now 10^exponent <= magnitude
  if (exponent > -8 && magnitude < power(exponent)) --exponent;
  double q = magnitude * powers[14 - exponent];  // in [1e14, 1e15) with an error below 0.07
  double whole = std::floor(q);
  double fraction = q - whole;
  if (q < 1e14 || q >= 1e15 || std::fabs(fraction - 0.5) < 0.1) return false;
  auto digits = static_cast<std::uint64_t>(whole) + (fraction > 0.5 ? 1 : 0);
  if (digits >= 1'000'000'000'000'000) {  // rounded up to the next power of ten
    digits /= 10;
    ++exponent;
  }
  std::to_chars(d.digits, d.digits + significant_digits, digits);
  d.exponent = exponent;
  return true;
}

// |x| to 15 significant digits, then rounded half away from zero at 10^-fraction_digits.
Decimal round_decimal(double magnitude, int fraction_digits, exact::Digits how) {
  Decimal d;
  if (magnitude == 0) return d;
  if (how == exact::Digits::Library || !fifteen_digits_fast(magnitude, d)) fifteen_digits_exact(magnitude, d);
  d.count = significant_digits;

  int keep = d.exponent + fraction_digits + 1;  // digits with a weight of at least 10^-N
  if (keep >= significant_digits) return d;
  if (keep < 0) {
    d.count = 0;
    return d;
  }
  bool up = d.digits[keep] >= '5';
  d.count = keep;
  if (up) {
    int i = keep - 1;
    while (i >= 0 && d.digits[i] == '9') --i;
    if (i >= 0) {
      ++d.digits[i];
      d.count = i + 1;
    } else {  // 9.99 -> 10, or nothing kept -> one unit in the last place
      d.digits[0] = '1';
      d.count = 1;
      d.exponent = keep == 0 ? -fraction_digits : d.exponent + 1;
    }
  }
  while (d.count > 0 && d.digits[d.count - 1] == '0') --d.count;
  return d;
}

char digit_at(const Decimal& d, int weight) {
  int index = d.exponent - weight;
  return (index >= 0 && index < d.count) ? d.digits[index] : '0';
}

// Writes the number part (without affixes) into `p`, given its integer and fraction digits.
// Returns the end.
char* assemble(char* p, const DisplayFormat& f, bool negative, const char* int_digits, int int_len,
               char* frac, int frac_len_total) {
  int zeros = std::max(0, f.min_int_digits - int_len);  // /m: zero-fill
  int shown_int = int_len + zeros;

  bool frac_zero = true;
  for (int i = 0; i < frac_len_total; ++i) frac_zero = frac_zero && frac[i] == '0';
  int frac_len = frac_len_total;
  while (frac_len > f.min_frac_digits && frac[frac_len - 1] == '0') --frac_len;
  if (f.trail == DisplayFormat::Pad::Zero) frac_len = frac_len_total;
  if (f.trail == DisplayFormat::Pad::Blank) {
    std::fill(frac + frac_len, frac + frac_len_total, ' ');
    frac_len = frac_len_total;
  }
  bool point = !f.no_point && !(f.conditional_point && frac_zero);
  if (f.conditional_point && frac_zero) frac_len = 0;
  // Never print a number without any digit (m = 0 and a zero value): write "0".
  bool any_digit = shown_int > 0 || std::any_of(frac, frac + frac_len, [](char c) { return c != ' '; });
  if (!any_digit) zeros = shown_int = 1;

  int pad = std::max(0, f.int_digits - shown_int);
  if (f.lead == DisplayFormat::Pad::Blank) p = std::fill_n(p, pad, ' ');
  if (negative)
    *p++ = '-';
  else if (f.sign == DisplayFormat::Sign::Always)
    *p++ = '+';
  if (f.lead == DisplayFormat::Pad::Zero) p = std::fill_n(p, pad, '0');
  p = std::fill_n(p, zeros, '0');
  p = std::copy_n(int_digits, int_len, p);
  if (point) *p++ = '.';
  return std::copy_n(frac, frac_len, p);
}

}  // namespace

char* exact::format_number(char* p, const DisplayFormat& f, const Value& v, Digits how) {
  char int_digits[128];
  char frac[DisplayFormat::max_digits];
  int int_len = 0;
  bool negative = false;
  bool zero = false;
  const int n = f.frac_digits;

  if (formats_as_integer(f, v)) {  // exact integer path
    std::int64_t i = integer_of(v);
    std::uint64_t magnitude = i < 0 ? 0 - static_cast<std::uint64_t>(i) : static_cast<std::uint64_t>(i);
    negative = (i < 0) != f.invert && i != 0;
    zero = i == 0;
    if (!zero) int_len = static_cast<int>(std::to_chars(int_digits, int_digits + sizeof int_digits, magnitude).ptr - int_digits);
    std::fill_n(frac, n, '0');
  } else {
    const double x = scaled_number(f, v);
    if (!(std::fabs(x) <= 1e100))
      throw Error(410, Position{}, fmt::format("Val: number out of range ({} is beyond 1.E100)", x));
    Decimal d = round_decimal(std::fabs(x), n, how);
    zero = d.count == 0;
    negative = x < 0 && !zero;  // a value that rounds to zero is never negative
    for (int w = d.exponent; w >= 0 && !zero; --w) int_digits[int_len++] = digit_at(d, w);
    for (int i = 0; i < n; ++i) frac[i] = digit_at(d, -1 - i);
  }
  if (zero && f.delete_if_zero) return nullptr;
  return assemble(p, f, negative, int_digits, int_len, frac, n);
}

void exact::format_reference(std::string& out, const DisplayFormat& f, const Value& v) {
  if (v.type == Type::String) {
    out += v.text;
    return;
  }
  char buf[2 * DisplayFormat::max_affix + max_number];
  char* p = std::copy_n(f.prefix.data(), f.prefix_length, buf);
  p = format_number(p, f, v, Digits::Library);
  if (p == nullptr) return;
  p = std::copy_n(f.postfix.data(), f.postfix_length, p);
  out.append(buf, static_cast<std::size_t>(p - buf));
}

double round_half_away(double x, int fraction_digits) {
  if (!std::isfinite(x)) return x;
  fraction_digits = std::clamp(fraction_digits, -400, 400);
  Decimal d = round_decimal(std::fabs(x), fraction_digits, exact::Digits::Quick);
  if (d.count == 0) return 0.0;
  char buf[48];
  char* p = std::copy_n(d.digits, d.count, buf);
  *p++ = 'e';
  p = std::to_chars(p, buf + sizeof buf, d.exponent - d.count + 1).ptr;
  double r = 0;
  std::from_chars(buf, p, r);
  return x < 0 ? -r : r;
}

}  // namespace gppl
