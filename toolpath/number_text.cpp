#include "toolpath/number_text.hpp"

#include <fmt/format.h>

namespace toolpath {
namespace {

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

char* detail::write_number_text_rest(char* out, double v) {
  if (v == 0) {
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
