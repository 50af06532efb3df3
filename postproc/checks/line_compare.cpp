#include "postproc/checks/line_compare.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace postproc {
namespace {

bool digit(char c) { return c >= '0' && c <= '9'; }
bool alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool blank(char c) { return c == ' ' || c == '\t'; }

// A month word that opens a date (`JUL-12-2026`, `JUL- 9-2026`, as SolidCAM's posts print it).
bool month_opens_date(std::string_view text, std::size_t i) {
  if (i + 4 >= text.size() || !alpha(text[i]) || !alpha(text[i + 1]) || !alpha(text[i + 2]) || alpha(text[i + 3])) return false;
  if (text[i + 3] != '-' && text[i + 3] != '/' && text[i + 3] != '.') return false;
  std::size_t k = i + 4;
  while (k < text.size() && blank(text[k])) ++k;
  return k < text.size() && digit(text[k]);
}

// Replaces dates and times in `text` (a comment) with `#`: `21.11.2025`, `2025-11-21`, `21-NOV-2025`,
// `JUL-12-2026`, `12:05`, `12:05:33`. A plain decimal number (one `.`) is not a date.
std::string mask_datetime(std::string_view text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const bool opens = i == 0 || !(digit(text[i - 1]) || alpha(text[i - 1]));
    const bool month = opens && month_opens_date(text, i);
    if (!opens || !(digit(text[i]) || month)) {
      out += text[i++];
      continue;
    }
    std::size_t j = i, separators = 0, colons = 0;
    while (j < text.size() && (digit(text[j]) || (month && alpha(text[j])))) ++j;
    while (j + 1 < text.size() && (text[j] == '.' || text[j] == '/' || text[j] == '-' || text[j] == ':') &&
           (digit(text[j + 1]) || (text[j] != ':' && alpha(text[j + 1])) ||
            (text[j] == '-' && blank(text[j + 1]) && j + 2 < text.size() && digit(text[j + 2])))) {
      colons += text[j] == ':';
      ++separators;
      ++j;
      if (blank(text[j])) ++j;  // a day padded with a blank: `JUL- 9-2026`
      if (digit(text[j]))
        while (j < text.size() && digit(text[j])) ++j;
      else
        while (j < text.size() && alpha(text[j])) ++j;
    }
    if (separators >= 2 || colons >= 1) {
      // A clock time's AM or PM is part of it: a post run before noon prints AM where SolidCAM's
      // run printed PM (`3:43:33PM`, `12:42:26 AM`).
      std::size_t k = j < text.size() && blank(text[j]) ? j + 1 : j;
      if (colons >= 1 && k + 1 < text.size() && (text[k] == 'A' || text[k] == 'P' || text[k] == 'a' || text[k] == 'p') &&
          (text[k + 1] == 'M' || text[k + 1] == 'm') && (k + 2 == text.size() || !alpha(text[k + 2])))
        j = k + 2;
      out += '#';
      i = j;
    } else {
      out.append(text.substr(i, j - i));
      i = j;
    }
  }
  return out;
}

std::string mask_comment_datetimes(std::string_view line) {
  std::string out;
  std::size_t i = 0;
  while (i < line.size()) {
    char c = line[i];
    if (c == '(') {
      std::size_t close = line.find(')', i);
      std::size_t end = close == std::string_view::npos ? line.size() : close + 1;
      out += mask_datetime(line.substr(i, end - i));
      i = end;
    } else if (c == ';') {
      out += mask_datetime(line.substr(i));
      break;
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

// Splits off the next number (`-12.5`, `.5`, `3.`) at `pos`, or returns false.
bool read_number(std::string_view s, std::size_t& pos, double& value) {
  std::size_t j = pos;
  if (j < s.size() && (s[j] == '-' || s[j] == '+')) ++j;
  std::size_t digits = 0;
  while (j < s.size() && digit(s[j])) ++j, ++digits;
  if (j < s.size() && s[j] == '.') {
    ++j;
    while (j < s.size() && digit(s[j])) ++j, ++digits;
  }
  if (digits == 0) return false;
  value = std::strtod(std::string(s.substr(pos, j - pos)).c_str(), nullptr);
  pos = j;
  return true;
}

bool match_with_tolerance(std::string_view a, std::string_view b, double tolerance) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    double x = 0, y = 0;
    std::size_t i2 = i, j2 = j;
    bool na = read_number(a, i2, x), nb = read_number(b, j2, y);
    if (na && nb) {
      if (std::fabs(x - y) > tolerance) return false;
      i = i2;
      j = j2;
      continue;
    }
    if (a[i] != b[j]) return false;
    ++i;
    ++j;
  }
  return i == a.size() && j == b.size();
}

// The comments of a line without their digits and blanks: two lines that hold a date or a time in
// a comment match when they differ in that value only, even where its width differs
// (`JUL- 9-2026-3:37:23PM` against `JUL-12-2026-11:04:10AM`).
std::string without_comment_digits(std::string_view line) {
  std::string out;
  bool comment = false;
  for (char c : line) {
    if (c == '(' || c == ';') comment = true;
    if (comment && (digit(c) || blank(c))) continue;
    if (c == ')') comment = false;
    out += c;
  }
  return out;
}

}  // namespace

std::string normalize_line(std::string_view line, const CompareOptions& o) {
  std::string_view s = line;
  if (o.ignore_trailing_blanks)
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  if (o.ignore_block_numbers) {
    std::size_t p = 0;
    while (p < s.size() && blank(s[p])) ++p;
    if (p + 1 < s.size() && s[p] == 'N' && digit(s[p + 1])) {
      p += 1;
      while (p < s.size() && digit(s[p])) ++p;
      if (p < s.size() && blank(s[p])) ++p;
      s.remove_prefix(p);
    }
  }
  if (o.ignore_leading_blanks)
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  return o.ignore_datetime ? mask_comment_datetimes(s) : std::string(s);
}

bool lines_match(std::string_view expected, std::string_view actual, const CompareOptions& o) {
  bool plain = !o.ignore_block_numbers && !o.ignore_trailing_blanks && !o.ignore_leading_blanks && !o.ignore_datetime;
  if (plain && o.numeric_tolerance <= 0) return expected == actual;
  std::string a = normalize_line(expected, o), b = normalize_line(actual, o);
  if (o.numeric_tolerance > 0 ? match_with_tolerance(a, b, o.numeric_tolerance) : a == b) return true;
  return o.ignore_datetime && a.find('#') != std::string::npos && b.find('#') != std::string::npos &&
         without_comment_digits(a) == without_comment_digits(b);
}

}  // namespace postproc
