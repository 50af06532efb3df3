// The block models' number reader: the fast path (up to 15 digits) gives exactly what strtod gives,
// and malformed or huge numbers are errors with their column.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
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
