// One pass over the line: blanks may sit anywhere, even inside a number (`Y 30,2` is Y30.2).
#include "machines/pikocnc/model/lexer.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <string>

#include "machines/ncmodel/block_text.hpp"

namespace pikocnc {
namespace {

constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

constexpr std::uint64_t kPow10Int[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000,
                                      1000000000, 10000000000, 100000000000, 1000000000000,
                                      10000000000000, 100000000000000, 1000000000000000};

// Character classes by table: the lexer looks at every byte of every line.
enum : unsigned char { kOther = 0, kBlank = 1, kDigit = 2, kLetter = 3 };
struct ClassTable {
  unsigned char c[256]{};
  constexpr ClassTable() {
    for (const char b : {' ', '\t', '\f', '\v', '\0'}) c[static_cast<unsigned char>(b)] = kBlank;
    for (int i = '0'; i <= '9'; ++i) c[i] = kDigit;
    for (int i = 'A'; i <= 'Z'; ++i) c[i] = c[i + 32] = kLetter;
  }
};
constexpr ClassTable kClass;
inline unsigned char class_of(char c) { return kClass.c[static_cast<unsigned char>(c)]; }
bool is_blank(char c) { return class_of(c) == kBlank; }
bool is_digit(char c) { return class_of(c) == kDigit; }

// Where a comment starts at `i`: `(`, `'`, `;`, `//`, or the typographic quotes U+2018/U+2019.
std::size_t comment_start_length(std::string_view s, std::size_t i) {
  const char c = s[i];
  if (c == '(' || c == ';' || c == '\'') return 1;
  if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') return 2;
  if (static_cast<unsigned char>(c) == 0xE2 && i + 2 < s.size() && static_cast<unsigned char>(s[i + 1]) == 0x80 &&
      (static_cast<unsigned char>(s[i + 2]) == 0x98 || static_cast<unsigned char>(s[i + 2]) == 0x99))
    return 3;
  return 0;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (is_blank(s.front()) || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (is_blank(s.back()) || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

struct Number {
  bool ok = false;
  bool negative = false;
  bool has_sign = false;
  std::uint64_t int_part = 0;
  std::uint64_t mantissa = 0;  // all digits
  int digits = 0;
  int frac_digits = 0;
  std::uint64_t frac = 0;      // fractional digits as an integer (first 18)
  bool has_sep = false;
  std::string_view text;       // from the first digit or separator to the end of the number
  double value() const {
    double v;
    if (digits <= 15) {
      v = static_cast<double>(mantissa) / kPow10[frac_digits];  // exact: both fit a double
    } else {
      std::string slow;  // long numbers: without the blanks, through the correctly rounding parser
      for (char c : text)
        if (is_digit(c)) slow.push_back(c);
        else if (c == '.' || c == ',') slow.push_back('.');
      v = 0;
      if (std::from_chars(slow.data(), slow.data() + slow.size(), v).ec != std::errc())
        v = HUGE_VAL;  // beyond a double: the lexer skips the word (not 0, as it once read)
    }
    return negative ? -v : v;
  }
};

// number = [sign] (digits [sep [digits]] | sep digits), blanks ignored in between. The state is
// kept in locals (registers) and each run of digits is read by its own loop: every byte of the
// program goes through here.
std::size_t read_number(std::string_view s, std::size_t i, Number& n) {
  const char* p = s.data();
  const std::size_t size = s.size();
  bool negative = false, has_sign = false, has_sep = false;
  std::uint64_t mantissa = 0, frac = 0, int_part = 0;
  int digits = 0, frac_digits = 0;
  while (i < size && is_blank(p[i])) ++i;
  if (i < size && (p[i] == '+' || p[i] == '-')) {
    negative = p[i] == '-';
    has_sign = true;
    ++i;
    while (i < size && is_blank(p[i])) ++i;
  }
  const std::size_t begin = i;
  for (;;) {
    while (i < size && is_blank(p[i])) ++i;
    if (i >= size) break;
    char c = p[i];
    if (is_digit(c)) {
      if (!has_sep) {
        do {
          if (digits < 19) mantissa = mantissa * 10 + static_cast<unsigned>(c - '0');
          ++digits;
        } while (++i < size && is_digit(c = p[i]));
        int_part = mantissa;  // the first 19 digits, as the mantissa stops there
      } else {
        do {
          const auto d = static_cast<unsigned>(c - '0');
          if (digits < 19) mantissa = mantissa * 10 + d;
          ++digits;
          if (frac_digits < 18) frac = frac * 10 + d;
          ++frac_digits;
        } while (++i < size && is_digit(c = p[i]));
      }
      continue;
    }
    if ((c == '.' || c == ',') && !has_sep) {
      has_sep = true;
      ++i;
      continue;
    }
    break;
  }
  n.ok = digits > 0;
  n.negative = negative;
  n.has_sign = has_sign;
  n.has_sep = has_sep;
  n.int_part = int_part;
  n.mantissa = mantissa;
  n.frac = frac;
  n.digits = digits;
  n.frac_digits = frac_digits;
  n.text = s.substr(begin, i - begin);
  return i;
}

// The common word value, read by a loop of its own: `-`, up to fifteen digits with a `.` among
// them, then blanks up to the next letter or the end of the line. Fills `n` as read_number would
// and returns where that would stop; returns 0 (nothing read) for anything else (a `+`, a comma,
// blanks inside, more digits, another character after it), which read_number then reads.
std::size_t read_simple_number(std::string_view s, std::size_t i, Number& n) {
  const char* p = s.data();
  const std::size_t size = s.size();
  const bool negative = i < size && p[i] == '-';
  const std::size_t begin = i + negative;
  std::size_t j = begin;
  std::uint64_t mantissa = 0, int_part = 0;
  int digits = 0, frac_digits = 0;
  while (j < size && digits < 15 && is_digit(p[j])) {
    mantissa = mantissa * 10 + static_cast<unsigned>(p[j++] - '0');
    ++digits;
  }
  int_part = mantissa;
  const bool has_sep = j < size && p[j] == '.';
  if (has_sep) {
    ++j;
    while (j < size && digits < 15 && is_digit(p[j])) {
      mantissa = mantissa * 10 + static_cast<unsigned>(p[j++] - '0');
      ++digits;
      ++frac_digits;
    }
  }
  if (digits == 0) return 0;
  std::size_t end = j;
  while (end < size && is_blank(p[end])) ++end;
  if (end < size && class_of(p[end]) != kLetter) return 0;
  n.ok = true;
  n.negative = n.has_sign = negative;
  n.has_sep = has_sep;
  n.int_part = int_part;
  n.mantissa = mantissa;
  n.digits = digits;
  n.frac_digits = frac_digits;
  n.frac = mantissa - int_part * kPow10Int[frac_digits];
  n.text = s.substr(begin, end - begin);
  return end;
}

// The common line in one pass of its own: words `L[-]digits[.digits]` of up to fifteen digits
// between blanks, each value letter once, G and M codes unsigned of at most nine digits, nothing
// else (no comment, no `+`, no comma, no blank inside a number). Fills `out` as lex_line_general
// does and returns true; returns false at anything else, with `out` partly filled and nothing
// reported, and the general reader reads the line again from its start.
bool lex_common_line(std::string_view s, Block& out) {
  const char* const begin = s.data();
  const char* const end = begin + s.size();
  const char* p = begin;
  std::uint32_t present = 0;
  std::size_t codes = 0;
  while (p != end) {
    const char c = *p;
    if (class_of(c) == kBlank) {
      ++p;
      continue;
    }
    if (static_cast<unsigned>((c | 0x20) - 'a') >= 26) return false;
    const auto column = static_cast<std::uint32_t>(p - begin + 1);
    const ncmodel::PlainDecimal number = ncmodel::read_plain_decimal(p + 1, end);
    p = number.end;
    const bool negative = number.negative;
    const std::uint64_t mantissa = number.mantissa, int_part = number.int_part;
    const std::size_t digits = number.digits(), frac_digits = number.decimals;
    if (digits == 0 || digits > 15) return false;  // no number, or one from_chars must round
    // Blanks, then a letter or the end: more digits after blanks belong to this number.
    while (p != end && class_of(*p) == kBlank) ++p;
    if (p != end && class_of(*p) != kLetter) return false;
    const char letter = static_cast<char>(c & ~0x20);
    if (letter == 'N') continue;  // line numbers are ignored
    if (letter == 'G' || letter == 'M') {
      if (negative || digits > 9 || codes == Block::kMaxCodes) return false;
      std::uint64_t frac = mantissa - int_part * kPow10Int[frac_digits];
      int dot_digits = static_cast<int>(frac_digits);
      while (dot_digits > 0 && frac % 10 == 0) {
        frac /= 10;
        --dot_digits;
      }
      CodeWord& w = out.codes[codes++];
      w.letter = letter;
      w.number = static_cast<int>(int_part);
      w.dot = static_cast<int>(frac);
      w.dot_digits = dot_digits;
      w.column = column;
      continue;
    }
    const auto k = static_cast<std::size_t>(letter - 'A');
    if (present & (1u << k)) return false;  // given twice: the general reader warns
    const double v = static_cast<double>(mantissa) / kPow10[frac_digits];  // exact: both fit a double
    present |= 1u << k;
    out.value[k] = negative ? -v : v;
    out.column[k] = column;
  }
  out.present = present;
  out.code_count = codes;
  return true;
}

}  // namespace

bool is_percent_line(std::string_view line) {
  for (char c : line) {
    if (is_blank(c)) continue;
    return c == '%';
  }
  return false;
}

void lex_line(std::string_view s, std::size_t line_number, Block& out, Diagnostics& diag) {
  out.line = line_number;
  out.has_comment = false;
  out.comment = {};
  out.text = s;
  if (!lex_common_line(s, out)) lex_line_general(s, line_number, out, diag);
}

void lex_line_general(std::string_view s, std::size_t line_number, Block& out, Diagnostics& diag) {
  out.line = line_number;
  out.present = 0;
  out.code_count = 0;
  out.has_comment = false;
  out.comment = {};
  out.text = s;
  Number n;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    const unsigned char cls = class_of(c);
    if (cls == kBlank || c == '\r') {
      ++i;
      continue;
    }
    if (cls != kLetter) {
    if (std::size_t len = comment_start_length(s, i)) {
      out.has_comment = true;
      out.comment_column = static_cast<std::uint32_t>(i + 1);
      std::string_view text = s.substr(i + len);
      if (c == '(') {
        const std::size_t close = text.find(')');
        if (close != std::string_view::npos && !trim(text.substr(close + 1)).empty())
          diag.add(line_number, i + len + close + 2,
                   "text after `)` is part of the comment (a `(` comment runs to the end of the line)");
      }
      text = trim(text);
      if (!text.empty() && text.back() == ')') text = trim(text.substr(0, text.size() - 1));
      out.comment = text;
      break;
    }
      const unsigned char u = static_cast<unsigned char>(c);
      diag.add(line_number, i + 1,
               u >= 0x80 || u < 0x20 ? fmt::format("stray byte 0x{:02X} skipped", u)
                                     : fmt::format("stray character `{}` skipped", c));
      ++i;
      continue;
    }
    const char letter = static_cast<char>(c & ~0x20);
    const std::size_t column = i + 1;
    if (const std::size_t end = read_simple_number(s, i + 1, n)) i = end;
    else i = read_number(s, i + 1, n);
    if (!n.ok) {
      diag.add(line_number, column, fmt::format("letter `{}` without a number skipped", letter));
      continue;
    }
    if (i < s.size() && (s[i] == '.' || s[i] == ',')) {  // a second separator: `X1.2.3`
      while (i < s.size() && (is_digit(s[i]) || s[i] == '.' || s[i] == ',' || is_blank(s[i]))) ++i;
      diag.add(line_number, column, fmt::format("malformed number after `{}`: word skipped", letter));
      continue;
    }
    if (letter == 'N') continue;  // line numbers are ignored
    if (letter == 'G' || letter == 'M') {
      if (n.has_sign || !n.ok || n.digits > 9) {
        diag.add(line_number, column, fmt::format("malformed {} code skipped", letter));
        continue;
      }
      if (out.code_count == Block::kMaxCodes) {
        diag.add(line_number, column, "too many G/M codes in one line: code skipped");
        continue;
      }
      CodeWord& w = out.codes[out.code_count++];
      w.letter = letter;
      w.number = static_cast<int>(n.int_part);
      std::uint64_t frac = n.frac;
      int digits = n.frac_digits > 18 ? 18 : n.frac_digits;
      while (digits > 0 && frac % 10 == 0) {
        frac /= 10;
        --digits;
      }
      w.dot = static_cast<int>(frac);
      w.dot_digits = digits;
      w.column = static_cast<std::uint32_t>(column);
      continue;
    }
    const auto k = static_cast<std::size_t>(letter - 'A');
    if (out.present & (1u << k))
      diag.add(line_number, column, fmt::format("`{}` given twice in one line: the last one counts", letter));
    const double value = n.value();
    if (!std::isfinite(value)) {
      diag.add(line_number, column, fmt::format("number after `{}` out of range: word skipped", letter));
      continue;
    }
    out.present |= 1u << k;
    out.value[k] = value;
    out.column[k] = static_cast<std::uint32_t>(column);
  }
}

}  // namespace pikocnc
