// The block models' number reader: the fast path (up to 15 digits) gives exactly what strtod gives,
// and malformed or huge numbers are errors with their column.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "machines/ncmodel/block_text.hpp"

namespace {

double read(const std::string& text) {
  ncmodel::Cursor c{text, 0};
  return c.number();
}

TEST(BlockText, NumbersAreReadExactly) {
  for (const char* text : {"0", "-0", "5.", ".5", "+2.25", "-12.345", "0.05", "007.100", "123456789012345",
                           "0.000000000000001", "99999.999999999", "1234567890123456789", "3.14159265358979323846",
                           "0.1", "-0.3", "1200", "-30.", "2.675"}) {
    SCOPED_TRACE(text);
    const double expected = std::strtod(text, nullptr);
    const double got = read(text);
    EXPECT_EQ(got, expected);
    EXPECT_EQ(std::signbit(got), std::signbit(expected));
  }
}

TEST(BlockText, BadNumbersAreErrorsAtTheirColumn) {
  struct Case {
    std::string text;
    std::size_t column;
    std::string message;
  } cases[] = {
      {"X", 1, "expected a number"},
      {"  1.2.3", 3, "malformed number `1.2.3`"},
      {"-", 1, "expected a number"},
      {std::string(400, '9'), 1, "number out of range"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text.substr(0, 20));
    try {
      read(c.text);
      ADD_FAILURE() << "no error";
    } catch (const ncmodel::BlockError& e) {
      EXPECT_EQ(e.column, c.column);
      EXPECT_EQ(e.message, c.message);
    }
  }
}

}  // namespace

namespace {

// Random numbers as the readers meet them (signs, points, leading and trailing zeros, long runs of
// digits, a letter after): the shortcut for plain numbers and the general loop behind it stop where
// the number ends and give strtod's value.
TEST(BlockText, RandomNumbersAsStrtod) {
  std::mt19937_64 rng(25);
  const std::string alphabet = "00123456789.";
  for (int n = 0; n < 200000; ++n) {
    std::string text;
    if (rng() % 3 == 0) text += "+-"[rng() % 2];
    const std::size_t length = 1 + rng() % (rng() % 8 == 0 ? 25 : 9);
    for (std::size_t k = 0; k < length; ++k) text += alphabet[rng() % alphabet.size()];
    const std::size_t end = text.size();
    if (rng() % 2) text += "X1";
    SCOPED_TRACE(text);
    const std::string span = text.substr(0, end);
    const auto points = std::count(span.begin(), span.end(), '.');
    const bool any_digit = span.find_first_of("0123456789") != std::string::npos;
    ncmodel::Cursor c{text, 0};
    if (!any_digit || points > 1) {
      EXPECT_THROW(c.number(), ncmodel::BlockError);
      continue;
    }
    const double got = c.number();
    const double expected = std::strtod(span.c_str(), nullptr);
    EXPECT_EQ(c.i, end);
    EXPECT_EQ(got, expected);
    EXPECT_EQ(std::signbit(got), std::signbit(expected));
  }
}

}  // namespace

namespace {

// The word loops' shortcut (Cursor::plain_number) against number() on the same random texts: where
// it takes a number it gives number()'s value and end; where it declines, the cursor has not moved.
TEST(BlockText, PlainNumberAsNumber) {
  std::mt19937_64 rng(2525);
  const std::string alphabet = "00123456789.-+ e";
  for (int n = 0; n < 200000; ++n) {
    std::string text;
    const std::size_t length = 1 + rng() % (rng() % 8 == 0 ? 22 : 9);
    for (std::size_t k = 0; k < length; ++k) text += alphabet[rng() % alphabet.size()];
    if (rng() % 2) text += "X1";
    SCOPED_TRACE(text);
    ncmodel::Cursor fast{text, 0};
    double got = 0;
    if (!fast.plain_number(got)) {
      EXPECT_EQ(fast.i, 0u);
      continue;
    }
    ncmodel::Cursor general{text, 0};
    const double expected = general.number();  // never throws where the shortcut took a number
    EXPECT_EQ(fast.i, general.i);
    EXPECT_EQ(got, expected);
    EXPECT_EQ(std::signbit(got), std::signbit(expected));
  }
}

// round_half_away is std::round but for the sign of a zero: halves, values near them, large values
// (where doubles are integers), infinities and NaN.
TEST(BlockText, RoundHalfAwayAsStdRound) {
  auto same = [](double v) {
    SCOPED_TRACE(v);
    const double got = ncmodel::round_half_away(v), expected = std::round(v);
    if (std::isnan(expected)) EXPECT_TRUE(std::isnan(got));
    else EXPECT_EQ(got, expected);
  };
  for (double v : {0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994, 10.0,
                   4503599627370495.5, 0x1p51, -0x1p51, 0x1p51 - 0.5, 0x1p52 + 1, 1e300, -1e300,
                   std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN(), 5e-324})
    same(v);
  std::mt19937_64 rng(25);
  for (int n = 0; n < 200000; ++n) {
    const int scale = static_cast<int>(rng() % 60) - 8;
    const double v = std::ldexp(static_cast<double>(rng() % (1u << 20)) / (1u << 20), scale) * (rng() % 2 ? 1 : -1);
    same(v);
    same(std::round(v * 2) / 2);  // a half (or whole) number
  }
}

}  // namespace

namespace {

// find_either against a byte loop: runs of every length up to 80 at every alignment, with neither
// byte, one, or both at random places (in the 16-byte blocks, in the overlapping last one, at the
// ends). Each run is copied to a buffer of its own size, so that a read past it is an ASan error.
TEST(BlockText, FindEitherAsALoop) {
  std::mt19937_64 rng(25);
  for (int n = 0; n < 200000; ++n) {
    const std::size_t size = rng() % 81;
    std::string text(size, ' ');
    for (char& c : text) c = "ab\n\r(;\"xyz 0123"[rng() % 15];
    const char a = "\n(\"x"[rng() % 4], b = "\r;;y"[rng() % 4];
    if (rng() % 2)  // mostly neither
      for (char& c : text)
        if (c == a || c == b) c = '.';
    if (size > 0 && rng() % 4 == 0) text[rng() % size] = rng() % 2 ? a : b;
    const auto copy = std::make_unique<char[]>(size);
    std::copy(text.begin(), text.end(), copy.get());
    std::size_t expected = 0;
    while (expected < size && text[expected] != a && text[expected] != b) ++expected;
    ASSERT_EQ(ncmodel::find_either(copy.get(), size, a, b), expected) << text;
  }
}

}  // namespace

namespace {

// The name character tests (a table) as their definitions, for every byte.
TEST(BlockText, NameCharactersAsDefined) {
  for (int c = 0; c < 256; ++c) {
    const char ch = static_cast<char>(c);
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    EXPECT_EQ(ncmodel::is_letter(ch), letter) << c;
    EXPECT_EQ(ncmodel::ident_start(ch), letter || c == '_') << c;
    EXPECT_EQ(ncmodel::ident_char(ch), letter || c == '_' || (c >= '0' && c <= '9')) << c;
  }
}

}  // namespace
