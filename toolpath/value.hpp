// A parameter value of a toolpath command: one of the five GPPL-visible kinds, with an optional
// change flag that overrides the engine's own "did it change?" comparison.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace toolpath {

enum class ValueKind : std::uint8_t { Integer, Numeric, Logical, String, Enum };

// `xpos : 10T` forces "changed", `10F` forces "unchanged"; None lets the engine compare.
enum class ChangeFlag : std::uint8_t { None, Changed, Unchanged };

std::string_view kind_name(ValueKind kind);

struct Value {
  // The three one-byte fields together: a parameter is 8 bytes smaller (104), and every stage of
  // the pipeline walks every parameter of every command.
  ValueKind kind = ValueKind::Integer;
  ChangeFlag flag = ChangeFlag::None;
  bool logical = false;      // Logical
  std::int64_t integer = 0;  // Integer
  double numeric = 0.0;      // Numeric
  std::string text;          // String contents, or the Enum word as written (compare case-insensitively)

  static Value make_integer(std::int64_t v, ChangeFlag f = ChangeFlag::None);
  static Value make_numeric(double v, ChangeFlag f = ChangeFlag::None);
  static Value make_logical(bool v);
  static Value make_string(std::string v);
  static Value make_enum(std::string word);

  // Integer and Numeric read as a number; anything else gives 0.
  double as_number() const;

  friend bool operator==(const Value& a, const Value& b);
};

// ASCII case-insensitive equality (keywords, enumeration words, command and parameter names).
// Locale-free and inline: the engine and the stream filters compare names on every command.
constexpr char ascii_lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c + ('a' - 'A')) : c; }

namespace detail {

// Lowercases the ASCII capitals among the bytes packed in `x` (bytes of 0x80 and up unchanged):
// a byte's high bit marks 'A' <= byte <= 'Z', shifted down it is the 0x20 that lowercases it.
template <class Word>
constexpr Word lower_ascii(Word x) {
  constexpr Word ones = static_cast<Word>(~Word{0}) / 0xff, high = ones * 0x80;
  const Word low7 = x & ~high;
  const Word above_z = low7 + ones * (0x7f - 'Z');
  const Word from_a = low7 + ones * (0x80 - 'A');
  return x | ((from_a & ~above_z & ~x & high) >> 2);
}

template <class Word>
bool iequal_words(const char* a, const char* b) {
  Word x, y;
  std::memcpy(&x, a, sizeof x);
  std::memcpy(&y, b, sizeof y);
  const Word differ = x ^ y;
  if (differ == 0) return true;
  constexpr Word case_bits = static_cast<Word>(~Word{0}) / 0xff * 0x20;
  if ((differ & ~case_bits) != 0) return false;  // more than letter case differs
  return lower_ascii(x) == lower_ascii(y);
}

}  // namespace detail

// Compares 8 or 4 bytes at a time (the last word overlapping the one before).
inline bool iequals(std::string_view a, std::string_view b) {
  const std::size_t n = a.size();
  if (n != b.size()) return false;
  const char *p = a.data(), *q = b.data();
  if (n >= 8) {
    for (std::size_t i = 0; i + 8 < n; i += 8)
      if (!detail::iequal_words<std::uint64_t>(p + i, q + i)) return false;
    return detail::iequal_words<std::uint64_t>(p + n - 8, q + n - 8);
  }
  if (n >= 4) return detail::iequal_words<std::uint32_t>(p, q) && detail::iequal_words<std::uint32_t>(p + n - 4, q + n - 4);
  for (std::size_t i = 0; i < n; ++i)
    if (p[i] != q[i] && ascii_lower(p[i]) != ascii_lower(q[i])) return false;
  return true;
}

// `part` occurs in `text`, ignoring ASCII case.
inline bool icontains(std::string_view text, std::string_view part) {
  if (part.size() > text.size()) return false;
  for (std::size_t i = 0; i + part.size() <= text.size(); ++i)
    if (iequals(text.substr(i, part.size()), part)) return true;
  return false;
}

}  // namespace toolpath
