// What the block-by-block readers (Sinumerik, the ISO family) share to read a block's text: a cursor
// over it, numbers read strictly, and the error that makes a reader skip the block.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ncmodel {

// Where the first `a` or `b` is in [p, p + n): its index, or n. The line reader's line ends and the
// readers' comment marks, in one pass instead of a memchr for each (a call costs more than a short
// line's bytes). SSE2 (every x86-64) reads 16 bytes at a time, the last 16 overlapping those before,
// so that no byte outside [p, p + n) is read; shorter runs, and other machines, a byte at a time.
inline std::size_t find_either(const char* p, std::size_t n, char a, char b) {
#if defined(__SSE2__)
  if (n >= 16) {
    const __m128i va = _mm_set1_epi8(a), vb = _mm_set1_epi8(b);
    for (std::size_t i = 0;; i += 16) {
      if (i + 16 > n) i = n - 16;  // the last 16 bytes: those before them hold neither
      const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + i));
      const auto hits = static_cast<unsigned>(_mm_movemask_epi8(_mm_or_si128(_mm_cmpeq_epi8(v, va), _mm_cmpeq_epi8(v, vb))));
      if (hits != 0) return i + static_cast<std::size_t>(std::countr_zero(hits));
      if (i + 16 == n) return n;
    }
  }
#endif
  for (std::size_t i = 0; i < n; ++i)
    if (p[i] == a || p[i] == b) return i;
  return n;
}

// A block the model cannot execute: reported at `column` (1-based) and skipped.
struct BlockError {
  std::size_t column;
  std::string message;
};

// Sinumerik names and LinuxCNC-style words: a letter or _, then letters, digits and _. ASCII
// letters, as std::isalpha in the "C" locale the program runs in, without a library call per byte.
constexpr bool is_letter(char c) { return (c | 0x20) >= 'a' && (c | 0x20) <= 'z'; }
constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }  // std::isdigit is a call
namespace detail {
// By byte: 1 a name's first character (a letter or _), 2 one after it (those and digits). One load
// for the tests that the readers make on every character of a name.
inline constexpr auto kNameChars = [] {
  std::array<unsigned char, 256> table{};
  for (int c = 0; c < 256; ++c) {
    const char ch = static_cast<char>(c);
    const bool start = is_letter(ch) || ch == '_';
    table[static_cast<std::size_t>(c)] = static_cast<unsigned char>((start ? 1 : 0) | (start || is_digit(ch) ? 2 : 0));
  }
  return table;
}();
}  // namespace detail
inline bool ident_start(char c) { return (detail::kNameChars[static_cast<unsigned char>(c)] & 1) != 0; }
inline bool ident_char(char c) { return (detail::kNameChars[static_cast<unsigned char>(c)] & 2) != 0; }

// A plain decimal `[-]digits[.digits]` at [p, end), by loops of its own: the readers' shortcut for
// the usual number (PikoCNC's lexer, Cursor::number). Only the sign, the digits and one point are
// read; what follows (and whether the number is usable) is the caller's to judge.
struct PlainDecimal {
  const char* end;            // after the last digit or the point
  std::uint64_t mantissa;     // every digit, as one integer (callers take at most fifteen digits)
  std::uint64_t int_part;     // the digits before the point
  std::size_t int_digits, decimals;
  bool negative;
  std::size_t digits() const { return int_digits + decimals; }
};

inline PlainDecimal read_plain_decimal(const char* p, const char* end) {
  PlainDecimal d{};
  d.negative = p != end && *p == '-';
  p += d.negative;
  const char* const first = p;
  std::uint64_t mantissa = 0;
  unsigned digit = 0;
  while (p != end && (digit = static_cast<unsigned char>(*p) - unsigned{'0'}) <= 9) {
    mantissa = mantissa * 10 + digit;
    ++p;
  }
  d.int_part = mantissa;
  d.int_digits = static_cast<std::size_t>(p - first);
  if (p != end && *p == '.') {
    const char* const point = ++p;
    while (p != end && (digit = static_cast<unsigned char>(*p) - unsigned{'0'}) <= 9) {
      mantissa = mantissa * 10 + digit;
      ++p;
    }
    d.decimals = static_cast<std::size_t>(p - point);
  }
  d.mantissa = mantissa;
  d.end = p;
  return d;
}

// 10^0 to 10^15, exact doubles: a decimal of up to fifteen digits is its digits over one of them.
inline constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                          1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

struct Cursor {
  std::string_view text;
  std::size_t i = 0;

  // Inline: the readers look at every word through these.
  void skip() {  // blanks and tabs
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  }
  bool at_end() {
    skip();
    return i >= text.size();
  }
  char peek() {  // after blanks; '\0' at the end
    skip();
    return i < text.size() ? text[i] : '\0';
  }
  std::size_t column() const { return i + 1; }
  bool eat(char c);
  bool eat(std::string_view s);
  std::string ident();    // a letter or _, then letters, digits and _, as written
  std::string keyword();  // letters only, lower case
  std::string_view digits() {  // a run of digits where the cursor is (no blanks skipped); may be empty
    const std::size_t b = i;
    while (i < text.size() && is_digit(text[i])) ++i;
    return text.substr(b, i - b);
  }
  // [+|-]digits[.digits]: a finite number, or BlockError ("expected a number", "malformed number",
  // "number out of range").
  double number();
  // number()'s shortcut where the cursor is, no blanks skipped: a plain `[-]digits[.digits]` of one
  // to fifteen digits, not followed by another point. Its value (as number() reads it) and true, the
  // cursor after it; false, the cursor unmoved, for anything else (which number() then reads or
  // rejects). The readers' word loops call it first; inline, so that their cursor stays in registers.
  bool plain_number(double& value) {
    const char* const end = text.data() + text.size();
    const PlainDecimal d = read_plain_decimal(text.data() + i, end);
    if (d.digits() - 1 >= 15) return false;  // none (wraps around) or more than fifteen
    if (d.end != end && *d.end == '.') return false;  // a second point: malformed, said by number()
    // The digits as an integer over a power of ten: both exact doubles, so the quotient is
    // correctly rounded (strtod's value).
    const double v = static_cast<double>(d.mantissa) / kPowersOfTen[d.decimals];
    value = d.negative ? -v : v;
    i = static_cast<std::size_t>(d.end - text.data());
    return true;
  }
};

// std::round's value (halves away from zero), except that a result of zero may be +0 where
// std::round gives -0: for callers that make it an integer or drop the sign of a zero. Without a
// libm call below 2^51.
inline double round_half_away(double v) {
  if (!(std::abs(v) < 0x1p51)) return std::round(v);  // large, infinite or NaN
  constexpr double kShift = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer, halves to even
  double r = (v + kShift) - kShift;
  if (std::abs(v - r) == 0.5) r = v + std::copysign(0.5, v);  // a half: away from zero (exact here)
  return r;
}

// A count, number or code as an integer; beyond a billion (or not a number) it is a BlockError at
// `column`, never a conversion the language leaves undefined.
long long whole(double v, std::size_t column, std::string_view what);

}  // namespace ncmodel
