// The reader's inline-layout fast path (a number stored as soon as the next `name:` is seen) must
// give exactly what the general rule gives: the value runs to the blanks before the next `name:`
// and is parsed by parse_value. The reference below applies that rule the slow way.
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "toolpath/trace_reader.hpp"

namespace {

using toolpath::Parameter;

// The parameters of a one-command inline trace, or the error text.
struct Outcome {
  std::vector<Parameter> parameters;
  std::string error;
  friend bool operator==(const Outcome&, const Outcome&) = default;
};

std::ostream& operator<<(std::ostream& os, const Outcome& o) {
  if (!o.error.empty()) return os << "error: " << o.error;
  for (const Parameter& p : o.parameters)
    os << p.name << "=[" << toolpath::kind_name(p.value.kind) << ' ' << p.value.integer << ' ' << p.value.numeric << " '"
       << p.value.text << "' " << static_cast<int>(p.value.flag) << "] ";
  return os;
}

// The parameters of the last command read (one vector reused, as a pipeline does), or the error.
Outcome read(const std::string& text) {
  std::istringstream in(text);
  toolpath::TraceReader reader(in, "t.trace");
  toolpath::Command c;
  Outcome o;
  try {
    while (reader.next(c)) o.parameters = c.parameters;
  } catch (const toolpath::InputError& e) {
    o.error = e.what();
  }
  return o;
}

bool blank(char c) { return c == ' ' || c == '\t'; }
bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }

std::size_t pair_name(const std::string& s, std::size_t at) {
  if (at >= s.size() || !ident_start(s[at])) return 0;
  std::size_t n = 1;
  while (at + n < s.size() && ident_char(s[at + n])) ++n;
  return at + n < s.size() && s[at + n] == ':' ? n : 0;
}

// The pairs of `text` (what follows `==>` on line `line`, whose first byte is in column `column`),
// one unquoted value at a time, by the documented rule.
Outcome reference(const std::string& text, std::size_t column, std::size_t line = 1) {
  Outcome o;
  std::size_t i = 0;
  while (i < text.size() && blank(text[i])) ++i;
  try {
    while (i < text.size()) {
      const std::size_t n = pair_name(text, i);
      if (n == 0) throw toolpath::InputError({"t.trace", line, column + i}, "expected `name:value`");
      const std::size_t v = i + n + 1;
      std::size_t end = text.size(), next = text.size();
      for (std::size_t k = v; k < text.size(); ++k) {
        if (!blank(text[k])) continue;
        std::size_t m = k;
        while (m < text.size() && blank(text[m])) ++m;
        if (pair_name(text, m) > 0) {
          end = k;
          next = m;
          break;
        }
      }
      o.parameters.emplace_back(text.substr(i, n), toolpath::parse_value(text.substr(v, end - v), {"t.trace", line, column + v}));
      i = next;
    }
  } catch (const toolpath::InputError& e) {
    o.parameters.clear();
    o.error = e.what();
  }
  return o;
}

void check(const std::string& pairs) {
  const std::string header = "(1)@c ==>";
  Outcome got = read(header + pairs + "\n");
  if (!got.error.empty()) got.parameters.clear();
  const Outcome expected = reference(pairs, header.size() + 1);
  EXPECT_EQ(got, expected) << '`' << pairs << '`';
  // Read again into slots that hold the names already (the reader's common run): after a command
  // of the same name with the same names, or with the first ones, holding other values.
  const Outcome names = reference(pairs + " ", header.size() + 1);  // the names, whatever the last value
  const char* other_values[] = {"0", "CW", "1.5T", "'x y'", "7 z", "TRUE"};
  for (std::size_t keep : {names.parameters.size(), names.parameters.size() / 2}) {
    std::string before = header;
    for (std::size_t k = 0; k < keep; ++k) {
      before += ' ';
      before += names.parameters[k].name;
      before += ':';
      before += other_values[k % std::size(other_values)];
    }
    got = read(before + "\n" + header + pairs + "\n");
    if (!got.error.empty()) got.parameters.clear();
    EXPECT_EQ(got, reference(pairs, header.size() + 1, 2)) << '`' << before << "` then `" << pairs << '`';
  }
}

TEST(TraceReaderInline, NumbersAsTheGeneralRuleReadsThem) {
  const char* values[] = {"0", "-0", "+7", "12", "-12", "007", "123456789012345678", "1234567890123456789",
                          "-9223372036854775808", "9223372036854775807", "99999999999999999999", "1.5", "-0.5",
                          ".5", "5.", "-.5", "1e5", "1E-3", "1.5e+2", "2e", "2e+", "0.1", "0.30000000000000004",
                          "123456789012345.6", "1234567890123456789.5", "9007199254740993", "9007199254740993.0",
                          "9007199254740993.5", "1.7976931348623157e308", "1e400", "4.9e-324", "1e-400",
                          "0.000000000000000000000001", "10T", "10F", "1.5t", "1.5f", "10TT", "10x", "1.2.3", "-",
                          "+", ".", "12 34", "1.5 T", "12abc", "CW", "TRUE", "1:2", "1x:2", "3.0e1T",
                          "ccw", "true", "False", "FALSE", "truex", "tru", "_x", "a_b9", "e5", "E", "T", "x.y", "x-y",
                          "CW:1", "CW'", "x\ty"};
  for (const char* v : values) {
    // Names in the catalogue (the common run takes those) and outside it.
    for (const char* after : {"", "   ", " b:1", "    b:1.0", "\tb:2 ", " 7", " b c:1", " feed:1", "   feed:-1.5 ",
                              "\tfeed:2 zpos:CW", " feed c:1", " feed:'q'", " feed:1 b:2"}) {
      check(std::string(" a:") + v + after);
      check(std::string(" a:1 x:") + v + after);
      check(std::string(" xpos:") + v + after);
      check(std::string(" xpos:1 ypos:") + v + after);
    }
  }
}

// Catalogue names (the common run) with values from the same bytes, blanks between the pairs.
TEST(TraceReaderInline, RandomPairsOfCatalogueNames) {
  std::mt19937 rng(20261128);
  const char* names[] = {"xpos", "ypos", "feed", "arc_direction", "xcenter_rel", "b"};
  const std::string alphabet = "0123456789+-.eETFtf x:ab\t_rue";
  for (int round = 0; round < 20000; ++round) {
    std::string pairs;
    for (std::size_t pair = rng() % 5; pair > 0; --pair) {
      pairs += rng() % 4 == 0 ? "  " : " ";
      pairs += names[rng() % std::size(names)];
      pairs += ':';
      for (std::size_t k = rng() % 8; k > 0; --k) pairs += alphabet[rng() % alphabet.size()];
    }
    check(pairs);
  }
}

TEST(TraceReaderInline, RandomPairs) {
  std::mt19937 rng(20261122);
  const std::string alphabet = "0123456789+-.eETFtf x:ab\t_rue";
  for (int round = 0; round < 30000; ++round) {
    std::string pairs = " a:";
    const std::size_t length = rng() % 14;
    for (std::size_t k = 0; k < length; ++k) pairs += alphabet[rng() % alphabet.size()];
    check(pairs);
  }
}

}  // namespace
