// String functions: every example of the language spec (section 9.4), the clock functions and
// their SOURCE_DATE_EPOCH override.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>

#include "tests/gppl/function_call.hpp"

namespace {

using gppl::Value;
using namespace function_test;

struct StringCase {
  const char* call;
  Value result;
  Value expected;
};

std::ostream& operator<<(std::ostream& os, const StringCase& c) { return os << c.call; }

class StringFunctions : public testing::TestWithParam<StringCase> {};

TEST_P(StringFunctions, MatchTheManual) { EXPECT_EQ(GetParam().result, GetParam().expected); }

Value replace(const char* s, const char* from, const char* to, std::int64_t k) {
  return call("replace", {str(s), str(from), str(to), integer(k)});
}

std::vector<StringCase> string_cases() {
  return {
      {"dup('abc', 3)", call("dup", {str("abc"), integer(3)}), str("abcabcabc")},
      {"instr('abcd', 'cd')", call("instr", {str("abcd"), str("cd")}), integer(3)},
      {"instr('abcd', 'x')", call("instr", {str("abcd"), str("x")}), integer(0)},
      {"instr('abcd', 'Cd')", call("instr", {str("abcd"), str("Cd")}), integer(0)},
      {"instr('abcdabcd', 'cd')", call("instr", {str("abcdabcd"), str("cd")}), integer(3)},
      {"left('abcdef', 4)", call("left", {str("abcdef"), integer(4)}), str("abcd")},
      {"left('xyz', 6)", call("left", {str("xyz"), integer(6)}), str("xyz")},
      {"lower('TITLE')", call("lower", {str("TITLE")}), str("title")},
      {"lower('Title no. 1')", call("lower", {str("Title no. 1")}), str("title no. 1")},
      {"replace a x 0", replace("abacad", "a", "x", 0), str("xbxcxd")},
      {"replace a xy 0", replace("abacad", "a", "xy", 0), str("xybxycxyd")},
      {"replace a '' 0", replace("abacad", "a", "", 0), str("bcd")},
      {"replace ac X 0", replace("abacad", "ac", "X", 0), str("abXad")},
      {"replace x y 0", replace("abacad", "x", "y", 0), str("abacad")},
      {"replace a xa 0", replace("abacad", "a", "xa", 0), str("xabxacxad")},
      {"replace '' 0", replace("", "a", "x", 0), str("")},
      {"replace old '' 0", replace("abacad", "", "x", 0), str("abacad")},
      {"replace A x 0", replace("abacad", "A", "x", 0), str("abacad")},
      {"replace 'ab'+'acad'", replace((std::string("ab") + "acad").c_str(), "a", "x", 0), str("xbxcxd")},
      {"replace k=2", replace("abacad", "a", "x", 2), str("xbxcad")},
      {"replace k=-2", replace("abacad", "a", "x", -2), str("abxcxd")},
      {"replace k=8", replace("abacad", "a", "x", 8), str("xbxcxd")},
      {"replace k omitted", call("replace", {str("abacad"), str("a"), str("x")}), str("xbxcxd")},
      {"replace k=-8", replace("abacad", "a", "x", -8), str("xbxcxd")},
      {"replace overlapping", replace("aaaa", "aa", "b", -1), str("aab")},
      {"rev('abcd')", call("rev", {str("abcd")}), str("dcba")},
      {"rev('123')", call("rev", {str("123")}), str("321")},
      {"right('abcdef', 4)", call("right", {str("abcdef"), integer(4)}), str("cdef")},
      {"right('xyz', 6)", call("right", {str("xyz"), integer(6)}), str("xyz")},
      {"space(5)", call("space", {integer(5)}), str("     ")},
      {"space(0)", call("space", {integer(0)}), str("")},
      {"strlen('abcd')", call("strlen", {str("abcd")}), integer(4)},
      {"strlen('abcd ')", call("strlen", {str("abcd ")}), integer(5)},
      {"strlen('')", call("strlen", {str("")}), integer(0)},
      {"substr('abcdefg',5,2)", call("substr", {str("abcdefg"), integer(5), integer(2)}), str("ef")},
      {"substr('abcdefg',5,4)", call("substr", {str("abcdefg"), integer(5), integer(4)}), str("efg")},
      {"tonum(' 12')", call("tonum", {str(" 12")}), num(12)},
      {"tonum('-12.34')", call("tonum", {str("-12.34")}), num(-12.34)},
      {"tonum('12.3e2')", call("tonum", {str("12.3e2")}), num(1230)},
      {"tonum('-12E-1')", call("tonum", {str("-12E-1")}), num(-1.2)},
      {"tostr(12.345)", call("tostr", {num(12.345)}), str("12.345")},
      {"tostr(12.3456)", call("tostr", {num(12.3456)}), str("12.346")},
      {"tostr(12.3456:'4.0')", call("tostr", {num(12.3456), str("4.0")}), str("12.")},
      {"trim('abcd')", call("trim", {str("abcd")}), str("abcd")},
      {"trim('abcd ')", call("trim", {str("abcd ")}), str("abcd")},
      {"upper('TITLE')", call("upper", {str("TITLE")}), str("TITLE")},
      {"upper('Title no. 1')", call("upper", {str("Title no. 1")}), str("TITLE NO. 1")},
      // the spec's extra vectors and corners it decides
      {"tostr(5000) with numeric_def_f", call("tostr", {integer(5000), str("5.3")}), str("5000.")},
      {"tostr(5000) without format", call("tostr", {integer(5000)}), str("5000.")},
      {"tostr(2.5) with an unset numeric_def_f", call("tostr", {num(2.5), str("")}), str("2.5")},
      {"tostr(num:'8.0(p)') num=7", call("tostr", {integer(7), str("8.0(p)")}), str("7")},
      {"tostr(12345678:'8.0(p)')", call("tostr", {integer(12345678), str("8.0(p)")}), str("12345678")},
      {"dup fractional count", call("dup", {str("ab"), integer(2)}), str("abab")},
      {"dup('abc', 0)", call("dup", {str("abc"), integer(0)}), str("")},
      {"dup('', 5)", call("dup", {str(""), integer(5)}), str("")},
      {"instr('abcd', '')", call("instr", {str("abcd"), str("")}), integer(0)},
      {"left('abc', 0)", call("left", {str("abc"), integer(0)}), str("")},
      {"right('abc', 0)", call("right", {str("abc"), integer(0)}), str("")},
      {"substr('abc',3,0)", call("substr", {str("abc"), integer(3), integer(0)}), str("")},
      {"substr('abc',1,99)", call("substr", {str("abc"), integer(1), integer(99)}), str("abc")},
      {"trim('  ab  ')", call("trim", {str("  ab  ")}), str("  ab")},
      {"trim('   ')", call("trim", {str("   ")}), str("")},
      {"lower keeps non-letters", call("lower", {str("[Z@a`{]")}), str("[z@a`{]")},
      {"upper keeps non-letters", call("upper", {str("[z@A`{]")}), str("[Z@A`{]")},
      {"tonum('+.5 ')", call("tonum", {str("+.5 ")}), num(0.5)},
      {"tonum('7.')", call("tonum", {str("7.")}), num(7)},
      {"tonum('1e2')", call("tonum", {str("1e2")}), num(100)},
      {"tonum('-0')", call("tonum", {str("-0")}), num(0)},
  };
}

INSTANTIATE_TEST_SUITE_P(Spec, StringFunctions, testing::ValuesIn(string_cases()));

TEST(StringFunctions, DateAndTimeUseTheClock) {
  std::regex date(R"([ 1-3]\d-(JAN|FEB|MAR|APR|MAY|JUN|JUL|AUG|SEP|OCT|NOV|DEC)-\d{4})");
  std::regex time(R"(([01]\d|2[0-3]):[0-5]\d:[0-5]\d)");
  Value d = call("date", {});
  EXPECT_TRUE(std::regex_match(d.text, date)) << d.text;
  EXPECT_TRUE(std::regex_match(call("time", {}).text, time));
  Value twice = call("dup", {d, integer(2)});
  EXPECT_EQ(twice.text, d.text + d.text);
}

TEST(StringFunctions, SourceDateEpochFixesTheClock) {
  ::setenv("SOURCE_DATE_EPOCH", "628121850", 1);  // 26 Nov 1989 22:17:30 UTC
  Value d = call("date", {});
  Value t = call("time", {});
  ::unsetenv("SOURCE_DATE_EPOCH");
  EXPECT_EQ(d, str("26-NOV-1989"));
  EXPECT_EQ(t, str("22:17:30"));
}

// SolidCAM pads the day with a blank (` 9-JUL-2026`), as its Siemens posts' output shows.
TEST(StringFunctions, DateBlankPadsTheDay) {
  ::setenv("SOURCE_DATE_EPOCH", "1783555200", 1);  // 9 Jul 2026 00:00:00 UTC
  Value d = call("date", {});
  ::unsetenv("SOURCE_DATE_EPOCH");
  EXPECT_EQ(d, str(" 9-JUL-2026"));
}

TEST(StringFunctions, ArgumentsAreNotModified) {
  std::vector<Value> args = {str("Line")};
  call("upper", args);
  EXPECT_EQ(args[0], str("Line"));
}

}  // namespace
