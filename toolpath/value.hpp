// A parameter value of a toolpath command: one of the five GPPL-visible kinds, with an optional
// change flag that overrides the engine's own "did it change?" comparison.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace toolpath {

enum class ValueKind : std::uint8_t { Integer, Numeric, Logical, String, Enum };

// `xpos : 10T` forces "changed", `10F` forces "unchanged"; None lets the engine compare.
enum class ChangeFlag : std::uint8_t { None, Changed, Unchanged };

std::string_view kind_name(ValueKind kind);

struct Value {
  ValueKind kind = ValueKind::Integer;
  ChangeFlag flag = ChangeFlag::None;
  std::int64_t integer = 0;  // Integer
  double numeric = 0.0;      // Numeric
  bool logical = false;      // Logical
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

// ASCII case-insensitive equality (keywords, enumeration words, command names).
bool iequals(std::string_view a, std::string_view b);

}  // namespace toolpath
