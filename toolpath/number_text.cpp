#include "toolpath/number_text.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace toolpath {
namespace {

constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The nine digits of `v` (below 10^9), leading zeros included.
void write_nine(char* out, std::uint32_t v) {
  for (int i = 7; i >= 1; i -= 2) {
    std::memcpy(out + i, kPairs + 2 * (v % 100), 2);
    v /= 100;
  }
  out[0] = static_cast<char>('0' + v);
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
    const auto n = static_cast<std::uint64_t>((scaled + kShift) - kShift);
    if (static_cast<double>(n) / 1e9 == a) {  // both exact doubles: the quotient is correctly rounded
      if (v < 0) *out++ = '-';
      const auto whole = static_cast<std::uint32_t>(n / 1000000000u);
      const auto frac = static_cast<std::uint32_t>(n % 1000000000u);
      out = std::to_chars(out, out + 8, whole).ptr;
      *out++ = '.';
      if (frac == 0) {
        *out++ = '0';
        return out;
      }
      write_nine(out, frac);
      out += 9;
      while (out[-1] == '0') --out;
      return out;
    }
  } else if (v == 0) {
    const char* text = std::signbit(v) ? "-0.0" : "0.0";
    const std::size_t n = std::signbit(v) ? 4 : 3;
    std::memcpy(out, text, n);
    return out + n;
  }
  return write_exact(out, v);
}

std::string number_text_exact(double v) {
  std::string out = fmt::format("{}", v);
  if (out.find_first_of(".eE") == std::string::npos) out += ".0";
  return out;
}

}  // namespace toolpath
