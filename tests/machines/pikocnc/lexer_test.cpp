// Section 1 of the dialect: comments, case, blanks, comma decimals, code numbers, malformed text.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "machines/pikocnc/model/codes.hpp"
#include "machines/pikocnc/model/lexer.hpp"
#include "machines/pikocnc/model/reader.hpp"

#include <sstream>

namespace {

// The block as `G1 X45.5 | comment | warnings`, codes first, then words in letter order.
std::string render(std::string_view line) {
  pikocnc::Block b;
  pikocnc::Diagnostics d;
  pikocnc::lex_line(line, 7, b, d);
  std::string out;
  for (std::size_t i = 0; i < b.code_count; ++i) {
    const auto& c = b.codes[i];
    out += fmt::format("{}{}{}{} ", c.letter, c.number, c.dot_digits ? "." : "", c.dot_digits ? std::to_string(c.dot) : "");
  }
  for (char l = 'A'; l <= 'Z'; ++l)
    if (b.has(l)) out += fmt::format("{}{} ", l, b.get(l));
  if (!out.empty()) out.pop_back();
  if (b.has_comment) out += fmt::format(" |{}|", b.comment);
  for (const auto& x : d.kept()) out += fmt::format(" [{}:{} {}]", x.where.line, x.where.column, x.message);
  return out;
}

TEST(PikoLexer, Table) {
  struct Case {
    std::string line;
    const char* expected;
  } cases[] = {
      {"G1 X45.5 Y30.2", "G1 X45.5 Y30.2"},
      {"G01 x45,5 Y 30,2", "G1 X45.5 Y30.2"},
      {"g1x45.5y30.2", "G1 X45.5 Y30.2"},
      {"G0 Z2.", "G0 Z2"},
      {"X-.5", "X-0.5"},
      {"X+3", "X3"},
      {"X1 2", "X12"},
      {"N10 G0 X1", "G0 X1"},
      {"N160 G0 Z2 ; lift", "G0 Z2 |lift|"},
      {"G1 X20.6 Y36 ( koniec", "G1 X20.6 Y36 |koniec|"},
      {"( Frez 2mm", " |Frez 2mm|"},
      {"' Frez 2mm", " |Frez 2mm|"},
      {"; Frez 2mm", " |Frez 2mm|"},
      {"G125 // koniec pierwszej petli", "G125 |koniec pierwszej petli|"},
      {"G1 X1 \xE2\x80\x99 typographic", "G1 X1 |typographic|"},
      {"G120 (Tekst na ekranie)", "G120 |Tekst na ekranie|"},
      {"G0 X1 (approach) Y2", "G0 X1 |approach) Y2| [7:17 text after `)` is part of the comment (a `(` comment runs to the end of the line)]"},
      {"G68.2 P1 Q123 I90 Z-60", "G68.2 I90 P1 Q123 Z-60"},
      {"G105.10 P1", "G105.1 P1"},
      {"G1.0 X1", "G1 X1"},
      {"G0.1 X10", "G0.1 X10"},
      {"M6T5", "M6 T5"},
      {"M03 S1000", "M3 S1000"},
      {"G1 X1.2.3 Y1", "G1 Y1 [7:4 malformed number after `X`: word skipped]"},
      {"G1 =X5", "G1 X5 [7:4 stray character `=` skipped]"},
      {"G1 X Y2", "G1 Y2 [7:4 letter `X` without a number skipped]"},
      {"G1 X1 X2", "G1 X2 [7:7 `X` given twice in one line: the last one counts]"},
      {"#1=5", " [7:1 stray character `#` skipped] [7:2 stray character `1` skipped] [7:3 stray character `=` skipped] [7:4 stray character `5` skipped]"},
      {"G1 X1\r", "G1 X1"},
      {"G1 X1" + std::string(400, '0') + " Y1", "G1 Y1 [7:4 number after `X` out of range: word skipped]"},
      {"", ""},
  };
  for (const auto& c : cases) EXPECT_EQ(render(c.line), c.expected) << c.line;
}

// A word right after its letter (`X-12.5`, up to fifteen digits) is read by a fast path; a blank
// after the letter (`X -12.5`) sends it through the general reader. Both must read the same
// values and codes, warn the same, whatever the digits: random words of every length and form.
TEST(PikoLexer, FastAndGeneralNumberReadersAgree) {
  std::mt19937_64 rng(25);
  auto digits = [&](std::size_t n) {
    std::string d;
    for (std::size_t i = 0; i < n; ++i) d += static_cast<char>('0' + rng() % 10);
    return d;
  };
  auto word = [&](char letter) {
    std::string w(1, letter);
    if (rng() % 3 == 0) w += '-';
    w += digits(rng() % 10);
    if (rng() % 2) w += '.' + digits(rng() % 11);
    if (rng() % 8 == 0) w += digits(rng() % 9);  // past fifteen digits at times
    return w;
  };
  for (int i = 0; i < 20000; ++i) {
    std::vector<std::string> words;
    for (const char l : {'N', 'G', 'X', 'Y', 'I', 'J', 'M'})
      if (rng() % 2) words.push_back(word(l));
    std::string fast, general;
    for (const std::string& w : words) {
      fast += w + (rng() % 2 ? " " : "");
      general += w.substr(0, 1) + " " + w.substr(1) + " ";
    }
    pikocnc::Block a, b;
    pikocnc::Diagnostics da, db;
    pikocnc::lex_line(fast, 1, a, da);
    pikocnc::lex_line(general, 1, b, db);
    ASSERT_EQ(a.present, b.present) << fast;
    for (int k = 0; k < 26; ++k)
      if ((a.present >> k) & 1) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(a.value[k]), std::bit_cast<std::uint64_t>(b.value[k])) << fast;
      }
    ASSERT_EQ(a.code_count, b.code_count) << fast;
    for (std::size_t k = 0; k < a.code_count; ++k) {
      ASSERT_EQ(a.codes[k].number, b.codes[k].number) << fast;
      ASSERT_EQ(a.codes[k].dot, b.codes[k].dot) << fast;
      ASSERT_EQ(a.codes[k].dot_digits, b.codes[k].dot_digits) << fast;
    }
    ASSERT_EQ(da.kept().size(), db.kept().size()) << fast;
    for (std::size_t k = 0; k < da.kept().size(); ++k) ASSERT_EQ(da.kept()[k].message, db.kept()[k].message) << fast;
  }
}

// lex_line reads the common line (plain words between blanks) by a shortcut of its own and
// leaves every other line to lex_line_general: both must give the same block and the same
// warnings on any line. Random lines of plain words, with now and then a piece that is not
// plain (signs, commas, blanks inside numbers, comments, repeats, long numbers, stray bytes).
TEST(PikoLexer, CommonLineShortcutAgreesWithTheGeneralReader) {
  std::mt19937_64 rng(2025);
  auto pick = [&](std::string_view from) { return from[rng() % from.size()]; };
  auto digits = [&](std::size_t n) {
    std::string d;
    for (std::size_t i = 0; i < n; ++i) d += static_cast<char>('0' + rng() % 10);
    return d;
  };
  auto word = [&] {
    std::string w(1, pick("NGMXYZIJKFSTRPQABgmxyzn"));
    switch (rng() % 24) {
      case 0: w += '+'; break;
      case 1: w += ' '; break;
      case 2: w += "- "; break;
      default: if (rng() % 3 == 0) w += '-';
    }
    w += digits(rng() % 8);
    if (rng() % 2) w += (rng() % 20 == 0 ? ',' : '.') + digits(rng() % 10);
    switch (rng() % 30) {
      case 0: w += digits(rng() % 12); break;  // past fifteen digits at times
      case 1: w += " " + digits(1 + rng() % 2); break;  // a blank inside the number
      case 2: w += ".5"; break;  // a second point
      case 3: w += pick("=#%&\t\r\x80,"); break;
      default: break;
    }
    return w;
  };
  const std::string_view comments[] = {" (note)", "; lift", " ' quote", " // end", "(", " \xE2\x80\x98 q"};
  for (int i = 0; i < 200000; ++i) {
    std::string line;
    if (rng() % 10 == 0) line += "\t ";
    for (std::size_t n = rng() % 8; n > 0; --n) line += word() + std::string(rng() % 4 == 0 ? 0 : 1 + rng() % 2, ' ');
    if (rng() % 20 == 0) line += comments[rng() % std::size(comments)];
    pikocnc::Block a, b;
    pikocnc::Diagnostics da, db;
    pikocnc::lex_line(line, 3, a, da);
    pikocnc::lex_line_general(line, 3, b, db);
    ASSERT_EQ(a.line, b.line) << line;
    ASSERT_EQ(a.text, b.text) << line;
    ASSERT_EQ(a.present, b.present) << line;
    for (int k = 0; k < 26; ++k)
      if ((a.present >> k) & 1) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(a.value[k]), std::bit_cast<std::uint64_t>(b.value[k])) << line;
        ASSERT_EQ(a.column[k], b.column[k]) << line;
      }
    ASSERT_EQ(a.code_count, b.code_count) << line;
    for (std::size_t k = 0; k < a.code_count; ++k) {
      ASSERT_EQ(a.codes[k].letter, b.codes[k].letter) << line;
      ASSERT_EQ(a.codes[k].number, b.codes[k].number) << line;
      ASSERT_EQ(a.codes[k].dot, b.codes[k].dot) << line;
      ASSERT_EQ(a.codes[k].dot_digits, b.codes[k].dot_digits) << line;
      ASSERT_EQ(a.codes[k].column, b.codes[k].column) << line;
    }
    ASSERT_EQ(a.has_comment, b.has_comment) << line;
    ASSERT_EQ(a.comment, b.comment) << line;
    ASSERT_EQ(a.comment_column, b.comment_column) << line;
    ASSERT_EQ(da.kept().size(), db.kept().size()) << line;
    for (std::size_t k = 0; k < da.kept().size(); ++k) {
      ASSERT_EQ(da.kept()[k].where.column, db.kept()[k].where.column) << line;
      ASSERT_EQ(da.kept()[k].message, db.kept()[k].message) << line;
    }
  }
}

TEST(PikoLexer, PercentLine) {
  EXPECT_TRUE(pikocnc::is_percent_line("%"));
  EXPECT_TRUE(pikocnc::is_percent_line("  % ; program start"));
  EXPECT_FALSE(pikocnc::is_percent_line("G0 %"));
  EXPECT_FALSE(pikocnc::is_percent_line(""));
}

TEST(PikoCodes, DialectsKnowTheirCodes) {
  using pikocnc::Dialect;
  auto known = [](char letter, int number, int dot, int digits, Dialect d) {
    pikocnc::CodeWord w{letter, number, dot, digits, 1};
    return pikocnc::find_code(w, d) != nullptr;
  };
  EXPECT_TRUE(known('G', 81, 0, 0, Dialect::V2016));
  EXPECT_FALSE(known('G', 17, 0, 0, Dialect::V2016));  // planes are 2025 only
  EXPECT_FALSE(known('G', 0, 1, 1, Dialect::V2016));
  EXPECT_TRUE(known('G', 0, 1, 1, Dialect::V2025));
  EXPECT_TRUE(known('G', 110, 0, 0, Dialect::V2016));
  EXPECT_FALSE(known('G', 111, 0, 0, Dialect::V2016));
  EXPECT_TRUE(known('G', 114, 7, 1, Dialect::V2025));
  EXPECT_FALSE(known('G', 115, 1, 1, Dialect::V2025));
  EXPECT_TRUE(known('G', 234, 12, 2, Dialect::V2025));
  EXPECT_FALSE(known('M', 1, 0, 0, Dialect::V2016));
  EXPECT_TRUE(known('M', 99, 0, 0, Dialect::V2016));
  EXPECT_FALSE(known('M', 2, 0, 0, Dialect::V2025));  // M2 is not documented
  EXPECT_FALSE(known('G', 82, 0, 0, Dialect::V2025));
}

}  // namespace

namespace {

// A G-code line longer than 16 MiB is an error naming it, not a buffer that grows with the file.
TEST(PikoLineReader, LinesLongerThanTheLimitAreAnError) {
  std::istringstream in("%\nG0 X1\n(" + std::string(17 << 20, 'a'));
  pikocnc::PikoReader reader(in, "long.nc", pikocnc::Options{});
  toolpath::Command c;
  std::string error;
  try {
    while (reader.next(c)) {
    }
  } catch (const toolpath::InputError& e) {
    error = e.what();
  }
  EXPECT_EQ(error, "long.nc:3:1: line longer than 16 MiB: not a G-code program?");
}

}  // namespace
