// The reader's terminated number scan (no bound checks: it relies on the byte after the line)
// must agree field by field with the bounded scan, for every terminator a line can have.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "toolpath/trace_syntax.hpp"

namespace {

using toolpath::trace_syntax::NumberScan;

std::string show(const NumberScan& n) {
  return std::to_string(n.length) + (n.numeric ? " numeric" : "") + (n.exponent ? " exponent" : "") +
         (n.negative ? " negative" : "") + " digits=" + std::to_string(n.digits) + " decimals=" +
         std::to_string(n.decimals) + " mantissa=" + std::to_string(n.mantissa);
}

void check(const std::string& text) {
  const std::string expected = show(toolpath::trace_syntax::scan_number(text));
  for (char terminator : {'\n', '\r', '\0'}) {
    const std::string line = text + terminator;  // as in the reader's chunk or carry buffer
    EXPECT_EQ(show(toolpath::trace_syntax::scan_terminated_number(line.data())), expected)
        << '`' << text << "` then " << static_cast<int>(terminator);
  }
}

TEST(TraceSyntax, TerminatedNumberScanAgreesWithTheBoundedOne) {
  const char* values[] = {"", "0", "-0", "+7", "12", "-12", "007", "123456789012345678", "1234567890123456789",
                          "99999999999999999999", "1.5", "-0.5", ".5", "5.", "-.5", "1e5", "1E-3", "1.5e+2", "2e",
                          "2e+", "2E-", "e5", "0.1", "10T", "1.5f", "1.2.3", "-", "+", ".", "+.", "-e", "12 34",
                          "1x", "3.0e1T", "1e5e5", "1ee5", "1.e5", "45.0 ypos:1"};
  for (const char* v : values) check(v);
}

TEST(TraceSyntax, TerminatedNumberScanOnRandomText) {
  std::mt19937 rng(20261123);
  const std::string alphabet = "0123456789+-.eETF x";
  for (int round = 0; round < 50000; ++round) {
    std::string text;
    const std::size_t length = rng() % 12;
    for (std::size_t k = 0; k < length; ++k) text += alphabet[rng() % alphabet.size()];
    check(text);
  }
}

// skip_blanks looks at eight bytes at a time when that many are left: it must stop exactly where
// a byte-by-byte skip stops, for runs of spaces and tabs of every length and position.
TEST(TraceSyntax, SkipBlanksAsByteByByte) {
  std::mt19937 rng(20261124);
  const std::string alphabet = "     \t\tx:";
  for (int round = 0; round < 50000; ++round) {
    std::string text;
    const std::size_t length = rng() % 30;
    for (std::size_t k = 0; k < length; ++k) text += alphabet[rng() % alphabet.size()];
    for (std::size_t from = 0; from <= text.size(); ++from) {
      std::size_t expected = from;
      while (expected < text.size() && (text[expected] == ' ' || text[expected] == '\t')) ++expected;
      ASSERT_EQ(toolpath::trace_syntax::skip_blanks(text, from), expected) << '`' << text << "` from " << from;
    }
  }
}

// skip_terminated_blanks (the reader's fast path: words below `end`, then the terminator stops the
// bytes) stops where the byte-by-byte skip stops, for every start and every terminator.
TEST(TraceSyntax, SkipTerminatedBlanksAsByteByByte) {
  std::mt19937 rng(20261131);
  const std::string alphabet = "     \t\tx:";
  for (int round = 0; round < 20000; ++round) {
    std::string text;
    const std::size_t length = rng() % 30;
    for (std::size_t k = 0; k < length; ++k) text += alphabet[rng() % alphabet.size()];
    for (char terminator : {'\n', '\r', '\0'}) {
      const std::string line = text + terminator;
      const char* const end = line.data() + text.size();
      for (std::size_t from = 0; from <= text.size(); ++from) {
        std::size_t expected = from;
        while (expected < text.size() && (text[expected] == ' ' || text[expected] == '\t')) ++expected;
        ASSERT_EQ(toolpath::trace_syntax::skip_terminated_blanks(line.data() + from, end) - line.data(),
                  static_cast<std::ptrdiff_t>(expected))
            << '`' << text << "` from " << from;
      }
    }
  }
}

TEST(TraceSyntax, FlagLetters) {
  for (int c = 0; c < 256; ++c) {
    const auto expected = c == 'T' || c == 't'   ? toolpath::ChangeFlag::Changed
                          : c == 'F' || c == 'f' ? toolpath::ChangeFlag::Unchanged
                                                 : toolpath::ChangeFlag::None;
    EXPECT_EQ(toolpath::trace_syntax::flag_letter(static_cast<char>(c)), expected) << c;
  }
}

}  // namespace
