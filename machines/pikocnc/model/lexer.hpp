// The words of one NC line (section 1 of the dialect): comments cut off, case, blanks and comma
// decimals normalised, N numbers dropped, malformed text skipped with a diagnostic.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "machines/pikocnc/model/diagnostics.hpp"

namespace pikocnc {

// A G or M word: `G68.2` is number 68, dot 2; `G105.10` is number 105, dot 1 (trailing zeros dropped).
struct CodeWord {
  char letter = 'G';
  int number = 0;
  int dot = 0;
  int dot_digits = 0;  // 0 when the code has no fractional part
  std::uint32_t column = 0;
};

struct Block {
  static constexpr std::size_t kMaxCodes = 24;

  std::size_t line = 0;
  std::uint32_t present = 0;  // bit (letter - 'A') for each value word in the line
  std::array<double, 26> value{};
  std::array<std::uint32_t, 26> column{};
  std::array<CodeWord, kMaxCodes> codes{};
  std::size_t code_count = 0;
  bool has_comment = false;
  std::uint32_t comment_column = 0;
  std::string_view comment;  // trimmed text, valid while the line is
  std::string_view text;     // the whole line as read

  bool has(char letter) const { return (present >> (letter - 'A')) & 1u; }
  double get(char letter) const { return value[static_cast<std::size_t>(letter - 'A')]; }
  std::uint32_t col(char letter) const { return column[static_cast<std::size_t>(letter - 'A')]; }
  bool empty() const { return present == 0 && code_count == 0 && !has_comment; }
};

// Splits `line` into `out`. Problems go to `diagnostics` at their line:column.
void lex_line(std::string_view line, std::size_t line_number, Block& out, Diagnostics& diagnostics);
// The same without lex_line's shortcut for the common line (plain words between blanks): what
// the shortcut is tested against.
void lex_line_general(std::string_view line, std::size_t line_number, Block& out, Diagnostics& diagnostics);

// True when `line` is the program start: its first non-blank character is `%`.
bool is_percent_line(std::string_view line);

}  // namespace pikocnc
