#include "machines/2xaxiscnc/numbers.hpp"

#include <charconv>
#include <cmath>

namespace twoaxis {

namespace {
bool digit(char c) { return c >= '0' && c <= '9'; }
}  // namespace

Number parse_number(std::string_view text) {
  // Longer numbers than this carry no more information for a 32-bit float; refusing them keeps the
  // scratch buffer on the stack.
  constexpr std::size_t kMaxLength = 64;
  Number n;
  if (text.empty() || text.size() > kMaxLength) return n;
  char buffer[kMaxLength];
  std::size_t i = 0, used = 0;
  bool portable = true;
  if (text[0] == '-' || text[0] == '+') {
    if (text[0] == '-') buffer[used++] = '-';
    ++i;
  }
  const std::size_t int_start = i;
  while (i < text.size() && digit(text[i])) buffer[used++] = text[i++];
  if (i == int_start) return n;  // digits must come first: `,5` and `-` are not numbers
  if (i < text.size() && (text[i] == ',' || text[i] == '.')) {
    portable = portable && text[i] == ',';
    buffer[used++] = '.';
    const std::size_t frac_start = ++i;
    while (i < text.size() && digit(text[i])) buffer[used++] = text[i++];
    if (i == frac_start) return n;  // `5,` has no decimals
  }
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    portable = false;
    buffer[used++] = 'e';
    ++i;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) buffer[used++] = text[i++];
    const std::size_t exp_start = i;
    while (i < text.size() && digit(text[i])) buffer[used++] = text[i++];
    if (i == exp_start) return n;
  }
  if (i != text.size()) return n;
  double v = 0.0;
  const auto [end, ec] = std::from_chars(buffer, buffer + used, v);
  // FLT_MAX plus half its ulp: from there on a value rounds to an infinite float
  constexpr double kFloatLimit = 0x1.ffffffp+127;
  if (ec == std::errc::result_out_of_range || !std::isfinite(v) || std::abs(v) >= kFloatLimit) {
    n.status = Number::Status::OutOfRange;
    return n;
  }
  if (ec != std::errc() || end != buffer + used) return n;
  n.value = v == 0.0 ? 0.0 : v;  // no -0
  n.status = portable ? Number::Status::Ok : Number::Status::NonPortable;
  return n;
}

double tidy(double v) {
  if (!(std::abs(v) < 1e12)) return v;  // beyond that 1e-6 steps are near a double's resolution
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0.0 ? 0.0 : r;
}

}  // namespace twoaxis
