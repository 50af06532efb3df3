// What the block-by-block readers (Sinumerik, the ISO family) share to read a block's text: a cursor
// over it, numbers read strictly, and the error that makes a reader skip the block.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ncmodel {

// A block the model cannot execute: reported at `column` (1-based) and skipped.
struct BlockError {
  std::size_t column;
  std::string message;
};

// Sinumerik names and LinuxCNC-style words: a letter or _, then letters, digits and _. ASCII
// letters, as std::isalpha in the "C" locale the program runs in, without a library call per byte.
inline bool is_letter(char c) { return (c | 0x20) >= 'a' && (c | 0x20) <= 'z'; }
inline bool ident_start(char c) { return is_letter(c) || c == '_'; }
inline bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }

struct Cursor {
  std::string_view text;
  std::size_t i = 0;

  // Inline: the readers look at every word through these.
  void skip() {  // blanks and tabs
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  }
  bool at_end() {
    skip();
    return i >= text.size();
  }
  char peek() {  // after blanks; '\0' at the end
    skip();
    return i < text.size() ? text[i] : '\0';
  }
  std::size_t column() const { return i + 1; }
  bool eat(char c);
  bool eat(std::string_view s);
  std::string ident();    // a letter or _, then letters, digits and _, as written
  std::string keyword();  // letters only, lower case
  std::string_view digits();  // a run of digits where the cursor is (no blanks skipped); may be empty
  // [+|-]digits[.digits]: a finite number, or BlockError ("expected a number", "malformed number",
  // "number out of range").
  double number();
};

// A count, number or code as an integer; beyond a billion (or not a number) it is a BlockError at
// `column`, never a conversion the language leaves undefined.
long long whole(double v, std::size_t column, std::string_view what);

}  // namespace ncmodel
