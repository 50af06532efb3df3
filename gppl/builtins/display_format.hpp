// GPPL display formats: how a number is printed in a generate statement or by tostr().
//
//   <prefix> sign lead M[/m] . N[/n] trail (options) <postfix>      e.g. '<X> 5.3(p)', '+5.0(/2.54i)'
//
// A format is parsed once into a small flat struct and then applied many times; applying it
// allocates nothing besides growing the caller's string. docs/gppl-formats.md is the user guide.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "gppl/gppl.hpp"

namespace gppl {

struct DisplayFormat {
  static constexpr int max_affix = 31;   // longer affix text is cut silently (the manual's rule)
  static constexpr int max_digits = 99;  // largest M, m, N or n accepted
  static constexpr int max_scales = 4;   // scale options kept one by one; more are folded into the last

  enum class Sign : std::uint8_t { NegativeOnly, Always };
  enum class Pad : std::uint8_t { None, Blank, Zero };

  struct Scale {
    double factor = 1.0;
    bool divide = false;
  };

  std::array<char, max_affix> prefix{};
  std::array<char, max_affix> postfix{};
  std::array<Scale, max_scales> scales{};
  std::uint8_t prefix_length = 0;
  std::uint8_t postfix_length = 0;
  std::uint8_t scale_count = 0;
  std::uint8_t int_digits = 0;       // M: pad width of the integer part (never truncates)
  std::uint8_t min_int_digits = 1;   // m: integer digits always written, zero-filled
  std::uint8_t frac_digits = 0;      // N: the value is rounded to N decimals
  std::uint8_t min_frac_digits = 0;  // n: fraction digits kept when trailing zeros are stripped
  Sign sign = Sign::NegativeOnly;
  Pad lead = Pad::None;   // blank: blanks before the sign; zero: zeros after the sign (up to M)
  Pad trail = Pad::None;  // zero: keep N fraction digits; blank: stripped zeros become blanks
  bool delete_if_zero = false;     // option d: a value that rounds to zero prints nothing at all
  bool no_point = false;           // option n: no decimal point, fraction digits still printed
  bool conditional_point = false;  // option p: no point (and no fraction) when the fraction is zero
  bool invert = false;             // option i: the sign is inverted before printing
  // Derived by the parser: no padding, a sign only when negative, one integer digit at least,
  // trailing zeros stripped to nothing, a point unless option p drops it ('5.3', '<X>5.3(p)').
  // The printer lays these out on a short path.
  bool plain = false;
  // Also derived: plain, no scales, no inversion and N <= 3 ('5.3', '5.0(p)', '<X>2.0(p)'), the
  // shapes that print numbers with a few table lookups and no general layout.
  bool quick = false;

  std::string_view prefix_text() const { return {prefix.data(), prefix_length}; }
  std::string_view postfix_text() const { return {postfix.data(), postfix_length}; }
  friend bool operator==(const DisplayFormat&, const DisplayFormat&) = default;
};

// Parses a format string. Throws gppl::Error with an empty position (the caller fills it):
// 408 no integer digits, 421 no decimal point, 422 no fraction digits, 423 unknown option or
// text left over (also a digit count above max_digits or an unterminated affix), 409 bad scale.
DisplayFormat parse_display_format(std::string_view spec);

// Appends the value formatted by `f`. Integer and Logical (0/1) values are exact; Numeric values
// are rounded half away from zero on their 15-significant-digit decimal form. String values are
// appended verbatim (the format does not apply to text). Throws Error 410 when the scaled value
// is beyond 1e100 in magnitude or not a number.
void append_formatted(std::string& out, const DisplayFormat& f, const Value& v);

// The bytes write_formatted() may touch past `out`: both affixes, the longest number part and the
// fixed-size copies the printer makes past the end of what it keeps.
inline constexpr std::size_t formatted_room = 2 * DisplayFormat::max_affix + 2 * DisplayFormat::max_digits + 110;

// append_formatted() for a number, integer or logical (not a string) written straight to `out`,
// which has formatted_room bytes of room; returns the end of the text (`out` itself when option d
// suppresses the item). The interpreter writes into its output line this way without a copy.
char* write_formatted(char* out, const DisplayFormat& f, const Value& v);
// The same for an integer value without building a Value (block numbers).
char* write_formatted(char* out, const DisplayFormat& f, std::int64_t value);

// Convenience for tests and tostr(): the formatted text as a new string.
std::string format_value(const DisplayFormat& f, const Value& v);

// Rounds half away from zero to `fraction_digits` decimals (negative: to the left of the point),
// on the same 15-significant-digit decimal form the formatter uses, so round(2.675, 2) is 2.68.
double round_half_away(double x, int fraction_digits);

}  // namespace gppl
