// The text of a numeric trace value: the shortest digits that read back to the same double, as
// fmt's "{}" writes them (fixed notation for decimal exponents -4 to 15, exponent notation
// otherwise), with ".0" added when that text has neither a point nor an exponent, so that it reads
// back as numeric, not integer.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace toolpath {

// Enough for any double's text: `-2.2250738585072014e-308` and the ".0".
inline constexpr std::size_t kMaxNumberText = 32;

// The reference: fmt's shortest "{}" and the ".0" rule (write_number_text's path for the rest).
std::string number_text_exact(double v);

namespace detail {

static_assert(std::endian::native == std::endian::little, "the digit words are little-endian");

// Every value write_number_text's fast path does not take (out of line: fmt, zeros).
char* write_number_text_rest(char* out, double v);

// The eight decimal digits of `v` (below 10^8) as the bytes of a little-endian word, the most
// significant first, each 0 to 9 (not yet ASCII): four lanes of two digits divided at once by
// multiplying (Paul Khuong's method), no table and no loop.
inline std::uint64_t eight_digits(std::uint32_t v) {
  const std::uint64_t merged = (v / 10000) | (std::uint64_t{v % 10000} << 32);
  const std::uint64_t top = ((merged * 10486) >> 20) & ((0x7Full << 32) | 0x7F);  // lane / 100
  const std::uint64_t bottom = merged - 100 * top;
  const std::uint64_t hundreds = (bottom << 16) + top;
  std::uint64_t tens = (hundreds * 103) >> 10;  // lane / 10
  tens &= (0xFull << 48) | (0xFull << 32) | (0xFull << 16) | 0xF;
  tens += (hundreds - 10 * tens) << 8;
  return tens;
}

// The same for four digits (`v` below 10^4), in the low half: two lanes instead of four.
inline std::uint32_t four_digits(std::uint32_t v) {
  const std::uint32_t top = (v * 5243) >> 19;  // v / 100, exact below 43 699
  const std::uint32_t hundreds = ((v - 100 * top) << 16) + top;
  std::uint32_t tens = ((hundreds * 103) >> 10) & 0x000F000F;  // lane / 10
  tens += (hundreds - 10 * tens) << 8;
  return tens;
}

// Writes the ASCII digits of a digit word (all its bytes, some possibly past what counts).
template <class Word>
inline void put_digits(char* out, Word digits) {
  digits += static_cast<Word>(0x3030303030303030ull);  // '0' in every byte
  std::memcpy(out, &digits, sizeof digits);
}

}  // namespace detail

// Writes the text at `out` and returns its end; it may write bytes after the end, never more than
// kMaxNumberText in all. Values with at most nine decimals and fifteen significant digits between
// 1e-4 and 1e6 (every value the controller models write: they round to a nanometre) are written
// from an integer without the shortest-digits search; every other value goes through
// number_text_exact. Both give the same bytes (tests/toolpath/number_text_test.cpp). Inline: the
// trace writer calls it for every number it has not written just before.
inline char* write_number_text(char* out, double v) {
  // If n / 10^9 (n below 10^15, so at most fifteen significant digits) reads back to |v|, these
  // digits are the shortest ones: two different decimals of at most fifteen significant digits
  // never read back to the same double (DBL_DIG), so the shortest text, which has no more digits
  // than this one, is this one. Between 1e-4 and 1e6 fmt writes them in fixed notation.
  const double a = std::fabs(v);
  if (!(a >= 1e-4 && a < 1e6)) return detail::write_number_text_rest(out, v);
  constexpr double kShift = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
  // Signed conversions: below 10^15 both ways are exact, and x86-64 has single instructions for
  // them (the unsigned ones take a branch and a few more).
  const auto n = static_cast<std::uint64_t>(static_cast<std::int64_t>((a * 1e9 + kShift) - kShift));
  if (static_cast<double>(static_cast<std::int64_t>(n)) / 1e9 != a)  // both exact doubles: the quotient is correctly rounded
    return detail::write_number_text_rest(out, v);
  *out = '-';  // kept for a negative value: no branch on a sign that changes value to value
  out += v < 0;
  const auto whole = static_cast<std::uint32_t>(n / 1000000000u);  // below 10^6
  const auto frac = static_cast<std::uint32_t>(n % 1000000000u);
  // The whole part without its leading zeros (the first bytes of its digit word), "0" for none;
  // four digits in a smaller word, as most coordinates have.
  if (whole < 10000) {
    const std::uint32_t w = detail::four_digits(whole);
    const int leading = whole == 0 ? 3 : std::countr_zero(w) / 8;
    detail::put_digits(out, w >> (8 * leading));
    out += 4 - leading;
  } else {
    const std::uint64_t w = detail::eight_digits(whole);
    const int leading = std::countr_zero(w) / 8;
    detail::put_digits(out, w >> (8 * leading));
    out += 8 - leading;
  }
  *out++ = '.';
  // The decimals without their trailing zeros (the last bytes of their digit word), "0" for none;
  // at most four (a program's coordinates) in a smaller word.
  if (frac % 100000 == 0) {
    const std::uint32_t f = detail::four_digits(frac / 100000);
    detail::put_digits(out, f);
    return out + (frac == 0 ? 1 : 4 - std::countl_zero(f) / 8);
  }
  const std::uint32_t rest = frac % 100000000u;
  out[0] = static_cast<char>('0' + frac / 100000000u);
  const std::uint64_t f = detail::eight_digits(rest);
  detail::put_digits(out + 1, f);
  return out + 9 - (rest == 0 ? 8 : std::countl_zero(f) / 8);
}

}  // namespace toolpath
