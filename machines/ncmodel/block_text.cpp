#include "machines/ncmodel/block_text.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <system_error>

namespace ncmodel {

bool Cursor::eat(char c) {
  if (peek() != c) return false;
  ++i;
  return true;
}

bool Cursor::eat(std::string_view s) {
  skip();
  if (text.substr(i, s.size()) != s) return false;
  i += s.size();
  return true;
}

std::string Cursor::ident() {
  skip();
  const std::size_t b = i;
  if (i < text.size() && ident_start(text[i]))
    while (i < text.size() && ident_char(text[i])) ++i;
  return std::string(text.substr(b, i - b));
}

std::string Cursor::keyword() {
  skip();
  std::string out;
  while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i])))
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i++])));
  return out;
}

double Cursor::number() {
  skip();
  if (double v; plain_number(v)) return v;
  const std::size_t b = i;
  const char* const p = text.data();
  const std::size_t n = text.size();
  // Any other form: signs, leading zeros, long runs of digits, errors.
  const bool negative = i < n && p[i] == '-';
  if (i < n && (p[i] == '+' || p[i] == '-')) ++i;
  // One pass over the digits and points: the significant digits as an integer (leading zeros of
  // the integer part left out; an overflow wraps, and then more than 15 of them send the text to
  // from_chars below), how many there are and how many follow the point.
  std::uint64_t mantissa = 0;
  int count = 0, decimals = -1, points = 0;
  bool digits = false;
  for (; i < n; ++i) {
    const char c = p[i];
    if (c == '.') {
      ++points;
      decimals = 0;
      continue;
    }
    const auto d = static_cast<unsigned>(static_cast<unsigned char>(c)) - unsigned{'0'};
    if (d > 9) break;
    digits = true;
    if (count == 0 && d == 0 && decimals < 0) continue;  // leading zeros of the integer part
    mantissa = mantissa * 10 + d;
    ++count;
    if (decimals >= 0) ++decimals;
  }
  if (!digits) throw BlockError{b + 1, "expected a number"};
  // The usual case, up to 15 significant digits and one point: the digits as an integer, divided by
  // a power of ten. Both are exact doubles, so the quotient is correctly rounded: from_chars' value.
  if (points <= 1 && count <= 15 && decimals <= 15) {
    const double v = static_cast<double>(mantissa) / kPowersOfTen[decimals < 0 ? 0 : decimals];
    return negative ? -v : v;
  }
  const char* first = p + b;
  const char* last = p + i;
  if (*first == '+') ++first;  // from_chars takes no '+'
  double v = 0;
  const auto [end, error] = std::from_chars(first, last, v);
  if (error == std::errc::result_out_of_range || (error == std::errc{} && !std::isfinite(v)))
    throw BlockError{b + 1, "number out of range"};
  if (error != std::errc{} || end != last)
    throw BlockError{b + 1, fmt::format("malformed number `{}`", text.substr(b, i - b))};
  return v;
}

long long whole(double v, std::size_t column, std::string_view what) {
  if (!(std::abs(v) <= 1e9)) throw BlockError{column, fmt::format("{} out of range", what)};
  return static_cast<long long>(v);
}

}  // namespace ncmodel
