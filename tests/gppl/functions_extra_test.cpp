// The built-ins real posts use beyond the manual's chapter (docs/gppl-formats.md, marked there):
// norm360, instr with a start position, and the array functions adims, alen, asize.
#include <gtest/gtest.h>

#include "gppl/builtins/functions.hpp"
#include "support.hpp"
#include "tests/gppl/function_call.hpp"

namespace {

using function_test::call;
using function_test::num;
using function_test::str;

struct Case {
  const char* what;
  gppl::Value result;
  gppl::Value expected;
};

std::ostream& operator<<(std::ostream& os, const Case& c) { return os << c.what; }

class ExtraFunctions : public testing::TestWithParam<Case> {};

TEST_P(ExtraFunctions, Result) { EXPECT_EQ(GetParam().result, GetParam().expected) << GetParam().what; }

INSTANTIATE_TEST_SUITE_P(
    Values, ExtraFunctions,
    testing::Values(Case{"norm360(45)", call("norm360", {function_test::integer(45)}), num(45.)},
                    Case{"norm360(-90)", call("norm360", {num(-90.)}), num(270.)},
                    Case{"norm360(720)", call("norm360", {num(720.)}), num(0.)},
                    Case{"norm360(360)", call("norm360", {num(360.)}), num(0.)},
                    Case{"norm360(-360.5)", call("norm360", {num(-360.5)}), num(359.5)},
                    Case{"norm360(370.2)", call("norm360", {num(370.2)}), num(10.2)},
                    Case{"norm360(-1e-20)", call("norm360", {num(-1e-20)}), num(0.)},
                    Case{"instr('abcabc', 'bc', 1)", call("instr", {str("abcabc"), str("bc"), function_test::integer(1)}),
                         function_test::integer(2)},
                    Case{"instr('abcabc', 'bc', 3)", call("instr", {str("abcabc"), str("bc"), function_test::integer(3)}),
                         function_test::integer(5)},
                    Case{"instr('abcabc', 'bc', 5)", call("instr", {str("abcabc"), str("bc"), function_test::integer(5)}),
                         function_test::integer(5)},
                    Case{"instr('abcabc', 'bc', 6)", call("instr", {str("abcabc"), str("bc"), function_test::integer(6)}),
                         function_test::integer(0)},
                    Case{"instr('abc', 'c', 99)", call("instr", {str("abc"), str("c"), function_test::integer(99)}),
                         function_test::integer(0)},
                    Case{"instr('abc', '', 1)", call("instr", {str("abc"), str(""), function_test::integer(1)}),
                         function_test::integer(0)}));

TEST(ExtraFunctions, Errors) {
  auto number = [](const char* name, std::vector<gppl::Value> args) {
    try {
      call(name, std::move(args));
    } catch (const gppl::Error& e) {
      return e.number();
    }
    return 0;
  };
  EXPECT_EQ(number("instr", {str("abc"), str("b"), function_test::integer(0)}), 387);
  EXPECT_EQ(number("instr", {str("abc"), str("b"), function_test::integer(-2)}), 387);
  EXPECT_EQ(number("norm360", {str("90")}), 386);
  EXPECT_EQ(number("alen", {str("3,4"), function_test::integer(3)}), 387);
  EXPECT_EQ(number("alen", {str(""), function_test::integer(1)}), 387);
}

// The array functions read the shape of the variable they name (locals, globals, host arrays).
TEST(ArrayFunctions, InAPost) {
  gppl::CompileOptions options;
  options.host_variables.push_back({"wire_table", gppl::Type::Numeric, false, {3, 40}});
  gppl_test::Post post(R"(@t
global integer homes<<54>>
local string grid<<2,3,4>>
local integer n
n = 2
{nb adims(homes) ' ' asize(homes) ' ' alen(homes, 1)}
{nb ADIMS(grid) ' ' Asize(grid) ' ' alen(grid, n) ' ' alen(grid, n + 1)}
{nb adims(wire_table) ' ' asize(wire_table) ' ' alen(wire_table, 2)}
{nb adims(n) ' ' asize(n)}
endp
)",
                       options);
  post.call("@t");
  EXPECT_EQ(post.text(), "1 54 54\n3 24 3 4\n2 120 40\n0 1");
}

TEST(ArrayFunctions, Errors) {
  using gppl_test::compile_error;
  EXPECT_EQ(compile_error("@t\nx = asize(5)\nendp\n"), "2:11: error 385");
  EXPECT_EQ(compile_error("@t\nglobal integer a<<3>>\nx = asize(a<<1>>)\nendp\n"), "3:11: error 385");
  EXPECT_EQ(compile_error("@t\nx = adims(nothing_like_it)\nendp\n"), "2:11: error 383");
  EXPECT_EQ(compile_error("@t\nglobal integer a<<3>>\nx = alen(a)\nendp\n"), "3:5: error 385");
  EXPECT_EQ(compile_error("@t\nglobal integer a<<3>>\nx = instr('a')\nendp\n"), "3:5: error 385");
  EXPECT_EQ(gppl_test::run_error("@t\nglobal integer a<<3>>\nx = alen(a, 2)\nendp\n"), "3:5: error 387");
}

}  // namespace
