// Display formats: the parser, run once per format string (the printer is display_format.cpp).
#include "gppl/builtins/display_format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

namespace gppl {

namespace {

// ---------------------------------------------------------------------------------------------
// Parsing

[[noreturn]] void format_error(int number, std::string_view what, std::string_view spec) {
  throw Error(number, Position{}, fmt::format("Format: {} in '{}'", what, spec));
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }
char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

class FormatParser {
public:
  explicit FormatParser(std::string_view spec) : s_(spec) {}

  DisplayFormat parse() {
    // A prefix sits at the very start; blanks before it and right after it only separate.
    std::size_t first = s_.find_first_not_of(' ');
    if (first != std::string_view::npos && s_[first] == '<') {
      pos_ = first;
      affix(f_.prefix, f_.prefix_length, "prefix");
      skip_blanks();
    }
    sign_and_lead();
    integer_part();
    if (!eat('.')) format_error(421, "No decimal point", s_);
    fraction_part();
    trailing_control();
    skip_blanks();
    if (eat('(')) options();
    skip_blanks();
    if (peek() == '<') {
      affix(f_.postfix, f_.postfix_length, "postfix");
      skip_blanks();
    }
    if (pos_ < s_.size()) format_error(423, fmt::format("Invalid format option, unexpected '{}'", s_[pos_]), s_);
    f_.plain = f_.lead == DisplayFormat::Pad::None && f_.sign == DisplayFormat::Sign::NegativeOnly &&
               f_.min_int_digits == 1 && f_.min_frac_digits == 0 && f_.trail == DisplayFormat::Pad::None &&
               !f_.no_point && !f_.delete_if_zero;
    f_.quick = f_.plain && f_.scale_count == 0 && !f_.invert && f_.frac_digits <= 3;
    return f_;
  }

private:
  char peek() const { return pos_ < s_.size() ? s_[pos_] : '\0'; }
  bool eat(char c) {
    if (peek() != c) return false;
    ++pos_;
    return true;
  }
  void skip_blanks() {
    while (peek() == ' ') ++pos_;
  }

  void affix(std::array<char, DisplayFormat::max_affix>& text, std::uint8_t& length, std::string_view which) {
    ++pos_;  // '<'
    std::size_t close = s_.find('>', pos_);
    if (close == std::string_view::npos) format_error(423, fmt::format("Invalid format option, '>' missing after the {}", which), s_);
    std::size_t n = std::min<std::size_t>(close - pos_, DisplayFormat::max_affix);
    std::memcpy(text.data(), s_.data() + pos_, n);
    length = static_cast<std::uint8_t>(n);
    pos_ = close + 1;
  }

  // Sign control and leading control, at most one of each, in either order. A run of blanks is
  // one leading-blank control (the manual writes ' 5.3z').
  void sign_and_lead() {
    bool have_sign = false, have_lead = false;
    for (;;) {
      char c = peek();
      if ((c == '+' || c == '-') && !have_sign) {
        f_.sign = c == '+' ? DisplayFormat::Sign::Always : DisplayFormat::Sign::NegativeOnly;
        have_sign = true;
        ++pos_;
      } else if (c == ' ' && !have_lead) {
        f_.lead = DisplayFormat::Pad::Blank;
        have_lead = true;
        skip_blanks();
      } else if ((c == 'z' || c == 'Z') && !have_lead) {
        f_.lead = DisplayFormat::Pad::Zero;
        have_lead = true;
        ++pos_;
      } else {
        return;
      }
    }
  }

  // Reads a digit count; returns false when there are no digits.
  bool count(std::uint8_t& out) {
    std::size_t start = pos_;
    int value = 0;
    while (is_digit(peek())) {
      value = std::min(value * 10 + (s_[pos_] - '0'), 1000);
      ++pos_;
    }
    if (pos_ == start) return false;
    if (value > DisplayFormat::max_digits)
      format_error(423, fmt::format("Invalid format option, digit count {} is above {}", s_.substr(start, pos_ - start),
                                    DisplayFormat::max_digits),
                   s_);
    out = static_cast<std::uint8_t>(value);
    return true;
  }

  void integer_part() {
    char c = peek();
    if (!is_digit(c)) {
      if (c == '.' || c == '\0') format_error(408, "without any digit", s_);
      format_error(423, fmt::format("Invalid format option, unexpected '{}'", c), s_);
    }
    count(f_.int_digits);
    if (eat('/') && !count(f_.min_int_digits)) format_error(408, "without any digit after '/'", s_);
    // m never exceeds M: SolidCAM prints '1/2.0(p)' as G0 and M3, not G00 and M03, while
    // '8/5.7/4' still gives 00012.3450 (docs/gppl-formats.md, "M/m").
    if (f_.int_digits > 0 && f_.min_int_digits > f_.int_digits) f_.min_int_digits = f_.int_digits;
  }

  void fraction_part() {
    if (!count(f_.frac_digits)) format_error(422, "No fraction digits", s_);
    if (eat('/') && !count(f_.min_frac_digits)) format_error(422, "No fraction digits after '/'", s_);
  }

  // 'z' keeps the zeros; a blank pads with blanks, but only as the last character of the format
  // (elsewhere blanks only separate: '<X> 5.2 (p)').
  void trailing_control() {
    char c = peek();
    if (c == 'z' || c == 'Z') {
      f_.trail = DisplayFormat::Pad::Zero;
      ++pos_;
    } else if (c == ' ' && s_.find_first_not_of(' ', pos_) == std::string_view::npos) {
      f_.trail = DisplayFormat::Pad::Blank;
      pos_ = s_.size();
    }
  }

  void options() {
    for (;;) {
      char c = peek();
      if (c == '\0') format_error(423, "Invalid format option, ')' missing", s_);
      ++pos_;
      switch (lower(c)) {
        case ')': return;
        case ' ': break;
        case 'd': f_.delete_if_zero = true; break;
        case 'n': f_.no_point = true; break;
        case 'p': f_.conditional_point = true; break;
        case 'i': f_.invert = true; break;
        case '*': add_scale(scale_number(), false); break;
        case '/': add_scale(scale_number(), true); break;
        default: format_error(423, fmt::format("Invalid format option '{}'", c), s_);
      }
    }
  }

  // [+|-] ( digits [ "." [digits] ] | "." digits )
  double scale_number() {
    skip_blanks();
    std::size_t start = pos_;
    if (peek() == '+' || peek() == '-') ++pos_;
    std::size_t digits_start = pos_;
    std::size_t digits = 0;
    while (is_digit(peek())) ++pos_, ++digits;
    if (eat('.'))
      while (is_digit(peek())) ++pos_, ++digits;
    if (digits == 0) format_error(409, "scale factor invalid (a number must follow '*' or '/')", s_);
    double value = 0;
    std::from_chars(s_.data() + digits_start, s_.data() + pos_, value);
    if (s_[start] == '-') value = -value;
    if (!std::isfinite(value)) format_error(409, "scale factor invalid", s_);
    return value;
  }

  void add_scale(double factor, bool divide) {
    if (divide && factor == 0) format_error(409, "scale factor invalid (division by zero)", s_);
    if (f_.scale_count < DisplayFormat::max_scales) {
      f_.scales[f_.scale_count++] = {factor, divide};
      return;
    }
    auto& last = f_.scales[DisplayFormat::max_scales - 1];
    if (last.divide == divide)
      last.factor *= factor;
    else
      last.factor /= factor;
  }

  std::string_view s_;
  std::size_t pos_ = 0;
  DisplayFormat f_;
};

}  // namespace

DisplayFormat parse_display_format(std::string_view spec) { return FormatParser(spec).parse(); }

}  // namespace gppl
