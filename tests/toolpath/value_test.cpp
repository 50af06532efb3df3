// Name comparison (iequals) and number reading: the fast paths must give exactly what the plain
// definitions give.
#include <gtest/gtest.h>

#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <random>
#include <string>

#include "toolpath/trace_reader.hpp"
#include "toolpath/value.hpp"

namespace {

bool plain_iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

struct NamePair {
  const char* a;
  const char* b;
  bool equal;
};

TEST(Iequals, Table) {
  const NamePair cases[] = {
      {"", "", true},
      {"x", "X", true},
      {"xpos", "XPOS", true},
      {"xpos", "ypos", false},
      {"@line", "@LINE", true},
      {"@line", "@lin", false},
      {"xcenter_rel", "XCENTER_REL", true},
      {"xcenter_rel", "ycenter_rel", false},
      {"xcenter_rel", "xcenter_reL", true},
      {"drill_clearance_z", "DRILL_CLEARANCE_Z", true},
      {"drill_clearance_z", "drill_clearance_y", false},
      {"@start_of_file", "@START_of_FILE", true},
      {"[", "{", false},  // differ only in bit 0x20, but are not letters
      {"@", "`", false},
      {"a_b@", "A_B`", false},
      {"\xc1", "\xe1", false},  // bytes of 0x80 and up are never folded
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(c.a) + " / " + c.b);
    EXPECT_EQ(toolpath::iequals(c.a, c.b), c.equal);
    EXPECT_EQ(toolpath::iequals(c.b, c.a), c.equal);
  }
}

TEST(Iequals, EveryByteInEveryPosition) {
  // Lengths around the 4- and 8-byte words the comparison works in.
  for (std::size_t length : {1, 3, 4, 5, 7, 8, 9, 12, 15, 16, 17, 24})
    for (std::size_t at : {std::size_t{0}, length / 2, length - 1})  // first, middle and last word
      for (int x = 0; x < 256; ++x)
        for (int y = 0; y < 256; ++y) {
          static std::string a, b;
          a.assign(length, 'k');
          b.assign(length, 'K');
          a[at] = static_cast<char>(x);
          b[at] = static_cast<char>(y);
          if (toolpath::iequals(a, b) != plain_iequals(a, b)) {
            ADD_FAILURE() << "length " << length << " position " << at << " bytes " << x << " " << y;
            return;
          }
        }
}

double reference(const std::string& text) {
  double v = 0;
  const char* first = text.data() + (text[0] == '+' ? 1 : 0);
  std::from_chars(first, text.data() + text.size(), v);
  return v;
}

// The reader's own decimal conversion (exact for short mantissas) against from_chars, bit for bit.
TEST(ParseValue, NumbersAsFromChars) {
  const char* cases[] = {"0.0",
                         "-0.0",
                         "45.0",
                         "-45.4760057628",
                         "0.1",
                         "0.30000000000000004",
                         "123456.789",
                         "9007199254740992.0",     // 2^53
                         "9007199254740993.0",     // above 2^53: from_chars
                         "1.0000000000000000000001",  // more than 19 digits
                         "0.0000000000000000000001",  // 22 decimals
                         "0.00000000000000000000001",  // 23 decimals
                         "1e-7",
                         "12345678901234567890.5",
                         "+3.25",
                         "99999999999999.9",       // 15 digits: the short check of the fast path
                         "999999999999999.9",      // 16 digits: the full check
                         "0.000000000000001",
                         "0.0000000000000001"};
  for (const char* text : cases) {
    SCOPED_TRACE(text);
    toolpath::Value v = toolpath::parse_value(text, {"f", 1, 1});
    ASSERT_EQ(v.kind, toolpath::ValueKind::Numeric);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(v.numeric), std::bit_cast<std::uint64_t>(reference(text)));
  }
  std::mt19937_64 random(20251121);
  for (int i = 0; i < 200000; ++i) {
    std::string text = (random() % 2 ? "-" : "") + std::to_string(random() % 100000000000ULL);
    const std::size_t decimals = random() % 12;
    text.insert(text.size() - std::min(decimals, text.size() - (text[0] == '-')), ".");
    toolpath::Value v = toolpath::parse_value(text, {"f", 1, 1});
    if (std::bit_cast<std::uint64_t>(v.numeric) != std::bit_cast<std::uint64_t>(reference(text))) {
      ADD_FAILURE() << text;
      return;
    }
  }
  for (int i = 0; i < 100000; ++i) {  // 12 to 19 digits, around the 15-digit and 2^53 limits
    std::string text = std::to_string(random() % 10000000000000000000ULL);
    text.insert(text.size() - std::min<std::size_t>(random() % 20, text.size()), ".");
    toolpath::Value v = toolpath::parse_value(text, {"f", 1, 1});
    if (std::bit_cast<std::uint64_t>(v.numeric) != std::bit_cast<std::uint64_t>(reference(text))) {
      ADD_FAILURE() << text;
      return;
    }
  }
}

TEST(ParseValue, Integers) {
  struct Case {
    const char* text;
    std::int64_t value;
  };
  const Case cases[] = {{"0", 0},
                        {"-0", 0},
                        {"999999999999999999", 999999999999999999},
                        {"-999999999999999999", -999999999999999999},
                        {"9223372036854775807", INT64_MAX},
                        {"-9223372036854775808", INT64_MIN},
                        {"000000000000000000000042", 42}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    toolpath::Value v = toolpath::parse_value(c.text, {"f", 1, 1});
    ASSERT_EQ(v.kind, toolpath::ValueKind::Integer);
    EXPECT_EQ(v.integer, c.value);
  }
  EXPECT_THROW(toolpath::parse_value("9223372036854775808", {"f", 1, 1}), toolpath::InputError);
}

}  // namespace
