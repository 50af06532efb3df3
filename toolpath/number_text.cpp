#include "toolpath/number_text.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

static_assert(std::endian::native == std::endian::little, "eight_digits makes a little-endian word");

namespace toolpath {
namespace {

// The eight decimal digits of `v` (below 10^8) as the bytes of a little-endian word, the most
// significant first, each 0 to 9 (not yet ASCII): four lanes of two digits divided at once by
// multiplying (Paul Khuong's method), no table and no loop.
std::uint64_t eight_digits(std::uint32_t v) {
  const std::uint64_t merged = (v / 10000) | (std::uint64_t{v % 10000} << 32);
  const std::uint64_t top = ((merged * 10486) >> 20) & ((0x7Full << 32) | 0x7F);  // lane / 100
  const std::uint64_t bottom = merged - 100 * top;
  const std::uint64_t hundreds = (bottom << 16) + top;
  std::uint64_t tens = (hundreds * 103) >> 10;  // lane / 10
  tens &= (0xFull << 48) | (0xFull << 32) | (0xFull << 16) | 0xF;
  tens += (hundreds - 10 * tens) << 8;
  return tens;
}

constexpr std::uint64_t kZeros = 0x3030303030303030;  // '0' in every byte

// Writes the ASCII digits of a word from eight_digits (8 bytes, some possibly past what counts).
void put8(char* out, std::uint64_t digits) {
  digits += kZeros;
  std::memcpy(out, &digits, 8);
}

char* write_exact(char* out, double v) {
  char* const start = out;
  out = fmt::format_to(out, "{}", v);
  bool has_point = false;
  for (const char* p = start; p != out; ++p) has_point |= *p == '.' || *p == 'e' || *p == 'E';
  if (!has_point) {
    *out++ = '.';
    *out++ = '0';
  }
  return out;
}

}  // namespace

char* write_number_text(char* out, double v) {
  // If n / 10^9 (n below 10^15, so at most fifteen significant digits) reads back to |v|, these
  // digits are the shortest ones: two different decimals of at most fifteen significant digits
  // never read back to the same double (DBL_DIG), so the shortest text, which has no more digits
  // than this one, is this one. Between 1e-4 and 1e6 fmt writes them in fixed notation.
  const double a = std::fabs(v);
  if (a >= 1e-4 && a < 1e6) {
    const double scaled = a * 1e9;
    constexpr double kShift = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
    // Signed conversions: below 10^15 both ways are exact, and x86-64 has single instructions for
    // them (the unsigned ones take a branch and a few more).
    const auto n = static_cast<std::uint64_t>(static_cast<std::int64_t>((scaled + kShift) - kShift));
    if (static_cast<double>(static_cast<std::int64_t>(n)) / 1e9 == a) {  // both exact doubles: the quotient is correctly rounded
      *out = '-';  // kept for a negative value: no branch on a sign that changes value to value
      out += v < 0;
      const auto whole = static_cast<std::uint32_t>(n / 1000000000u);  // below 10^6
      const auto frac = static_cast<std::uint32_t>(n % 1000000000u);
      // The whole part without its leading zeros (the first bytes of the word), "0" for none.
      const std::uint64_t w = eight_digits(whole);
      const int leading = whole == 0 ? 7 : std::countr_zero(w) / 8;
      put8(out, w >> (8 * leading));
      out += 8 - leading;
      *out++ = '.';
      if (frac == 0) {
        *out++ = '0';
        return out;
      }
      // Nine decimals without their trailing zeros (the last bytes of the word).
      const std::uint32_t rest = frac % 100000000u;
      out[0] = static_cast<char>('0' + frac / 100000000u);
      const std::uint64_t f = eight_digits(rest);
      put8(out + 1, f);
      const int trailing = rest == 0 ? 8 : std::countl_zero(f) / 8;
      return out + 9 - trailing;
    }
  } else if (v == 0) {
    const char* text = std::signbit(v) ? "-0.0" : "0.0";
    const std::size_t length = std::signbit(v) ? 4 : 3;
    std::memcpy(out, text, length);
    return out + length;
  }
  return write_exact(out, v);
}

std::string number_text_exact(double v) {
  char text[kMaxNumberText];
  return std::string(text, write_exact(text, v));
}

}  // namespace toolpath
