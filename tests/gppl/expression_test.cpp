// Expressions (spec 4): every vector of 4.6, the conversion table of 4.5, precedence of 4.4.
#include <gtest/gtest.h>

#include "support.hpp"

using namespace gppl_test;

namespace {

// Evaluates `expr` into the implicit host variable `result` (typed by the value) and returns it.
gppl::Value evaluate(const std::string& expr, const std::string& setup = "") {
  Post post("@t\n" + setup + "\nresult = " + expr + "\nendp\n");
  post.call("@t");
  return post.get("result");
}

struct ExpressionCase {
  const char* expr;
  const char* setup;
  gppl::Value expected;
};

class Expressions : public testing::TestWithParam<ExpressionCase> {};

TEST_P(Expressions, Evaluate) {
  const auto& c = GetParam();
  EXPECT_EQ(evaluate(c.expr, c.setup), c.expected) << c.expr;
}

INSTANTIATE_TEST_SUITE_P(
    Spec46, Expressions,
    testing::Values(ExpressionCase{"1+2*3", "", integer(7)}, ExpressionCase{"1+(2*3)", "", integer(7)},
                    ExpressionCase{"4 ^ 3 ^ 2", "", numeric(262144.)}, ExpressionCase{"10+1.2", "", numeric(11.2)},
                    ExpressionCase{"'abc'+'xyz'", "", string("abcxyz")},
                    ExpressionCase{"xpos gt 100", "xpos = 150.", logical(true)},
                    ExpressionCase{"not xpos gt 100 and xpos lt -100", "xpos = 50.", logical(false)},
                    ExpressionCase{"1+(2-3)", "", integer(0)}, ExpressionCase{"1.+(2-3)", "", numeric(0.)},
                    ExpressionCase{"7/2", "", integer(3)}, ExpressionCase{"-7/2", "", integer(-3)},
                    ExpressionCase{"7./2", "", numeric(3.5)}, ExpressionCase{"-2^2", "", numeric(-4.)},
                    ExpressionCase{"2^-1", "", numeric(0.5)}, ExpressionCase{"TRUE + 1", "", integer(2)},
                    ExpressionCase{"TRUE + TRUE", "", integer(2)}, ExpressionCase{"5 eq 5.", "", logical(true)},
                    ExpressionCase{"direction = CCW", "direction = 3\nCCW = 3", logical(true)},
                    ExpressionCase{"!mill_tool", "mill_tool = FALSE", logical(true)},
                    ExpressionCase{"! mill_tool", "mill_tool = TRUE", logical(false)}));

INSTANTIATE_TEST_SUITE_P(
    Operators, Expressions,
    testing::Values(ExpressionCase{"3 == 3", "", logical(true)}, ExpressionCase{"3 != 3", "", logical(false)},
                    ExpressionCase{"3 <> 4", "", logical(true)}, ExpressionCase{"3 ne 4", "", logical(true)},
                    ExpressionCase{"3 < 4", "", logical(true)}, ExpressionCase{"3 lt 3", "", logical(false)},
                    ExpressionCase{"3 <= 3", "", logical(true)}, ExpressionCase{"3 LE 2", "", logical(false)},
                    ExpressionCase{"4 > 3", "", logical(true)}, ExpressionCase{"4 gt 4", "", logical(false)},
                    ExpressionCase{"4 >= 4", "", logical(true)}, ExpressionCase{"4 Ge 5", "", logical(false)},
                    ExpressionCase{"'abc' eq 'abc'", "", logical(true)},
                    ExpressionCase{"'abc' == 'Abc'", "", logical(false)},
                    ExpressionCase{"'abc' < 'abd'", "", logical(true)},
                    ExpressionCase{"\"abc\" = 'abc'", "", logical(true)},
                    ExpressionCase{"1 = 1 and 2 = 2 or FALSE", "", logical(true)},
                    ExpressionCase{"FALSE or TRUE and FALSE", "", logical(false)},
                    ExpressionCase{"not TRUE or TRUE", "", logical(true)},
                    // Under and/or/not a number is TRUE when not zero, as real posts rely on.
                    ExpressionCase{"2 and TRUE", "", logical(true)}, ExpressionCase{"not 0.5", "", logical(false)},
                    ExpressionCase{"0 or -3", "", logical(true)}, ExpressionCase{"not 0", "", logical(true)},
                    ExpressionCase{"not (TRUE or TRUE)", "", logical(false)},
                    ExpressionCase{"- - 3", "", integer(3)}, ExpressionCase{"+3 - -2", "", integer(5)},
                    ExpressionCase{"-TRUE", "", integer(-1)}, ExpressionCase{"2 * 3 ^ 2", "", numeric(18.)},
                    ExpressionCase{"(1 + 2) * 3", "", integer(9)}, ExpressionCase{"10 - 4 - 3", "", integer(3)},
                    ExpressionCase{"100 / 10 / 5", "", integer(2)}, ExpressionCase{"1.2E2", "", numeric(120.)},
                    ExpressionCase{"1.2E-2", "", numeric(0.012)}, ExpressionCase{".123", "", numeric(0.123)},
                    ExpressionCase{"-0.23", "", numeric(-0.23)}, ExpressionCase{"-123", "", integer(-123)},
                    ExpressionCase{"PI", "", numeric(3.14159265358979323846)},
                    ExpressionCase{"change(g)", "global integer g\ng = 0", logical(true)},
                    ExpressionCase{"active(g) and not change(g)", "global integer g\ng = 1\ng = 1", logical(true)},
                    ExpressionCase{"a<<2,3>> + a<<1,1>>", "global integer a<<2,3>>\na<<2,3>> = 7\na<<1,1>> = 1",
                                   integer(8)}));

struct ErrorCase {
  const char* expr;
  const char* setup;
  int number;
};

class ExpressionErrors : public testing::TestWithParam<ErrorCase> {};

TEST_P(ExpressionErrors, Raise) {
  const auto& c = GetParam();
  try {
    evaluate(c.expr, c.setup);
    ADD_FAILURE() << c.expr << ": no error";
  } catch (const gppl::Error& e) {
    EXPECT_EQ(e.number(), c.number) << c.expr << ": " << e.what();
    EXPECT_EQ(e.where().line, 3) << e.what();  // the line of `result = ...`
  }
}

INSTANTIATE_TEST_SUITE_P(
    Spec, ExpressionErrors,
    testing::Values(ErrorCase{"'abc'+1", "", 394}, ErrorCase{"1+'abc'", "", 394}, ErrorCase{"'a' - 'b'", "", 386},
                    ErrorCase{"1/0", "", 407}, ErrorCase{"1./0", "", 407}, ErrorCase{"(-2) ^ 0.5", "", 387}, ErrorCase{"0 ^ 0", "", 387},
                    ErrorCase{"999999999 + 1", "", 410}, ErrorCase{"a<<3>>", "global integer a<<2>>", 387},
                    ErrorCase{"a<<0>>", "global integer a<<2>>", 387},
                    ErrorCase{"a<<1.5>>", "global integer a<<2>>", 387}, ErrorCase{"-'x'", "", 386}));

TEST(Expressions, ConditionIsTrueWhenNotZero) {
  // Real posts test integer options directly (`if iSplit_ProgName_Num and ...` with the option at 2)
  // and SolidCAM runs them; storing such a value in a logical variable is still error 420.
  Post post("@t\n  r = 0\n  if 2 then\n    r = r + 1\n  endif\n  if 0.5\n    r = r + 10\n  endif\n"
            "  if 0\n    r = r + 100\n  endif\nendp\n");
  post.set("r", integer(0));
  post.call("@t");
  EXPECT_EQ(post.get("r"), integer(11));
  EXPECT_EQ(run_error("@t\nglobal logical l\nl = 0.5\nendp\n"), "3:1: error 420");
}

struct ConversionCase {
  const char* type;
  const char* value;
  gppl::Value expected;
};

class Conversions : public testing::TestWithParam<ConversionCase> {};

TEST_P(Conversions, OnAssignment) {
  const auto& c = GetParam();
  Post post(std::string("@t\nglobal ") + c.type + " v\nv = " + c.value + "\nendp\n");
  post.call("@t");
  EXPECT_EQ(post.get("v"), c.expected) << c.type << " = " << c.value;
}

INSTANTIATE_TEST_SUITE_P(
    Table45, Conversions,
    testing::Values(ConversionCase{"integer", "7", integer(7)}, ConversionCase{"integer", "7.9", integer(7)},
                    ConversionCase{"integer", "-7.9", integer(-7)}, ConversionCase{"integer", "2.9999999999", integer(3)},
                    ConversionCase{"integer", "TRUE", integer(1)}, ConversionCase{"numeric", "3", numeric(3.)},
                    ConversionCase{"numeric", "FALSE", numeric(0.)}, ConversionCase{"logical", "1", logical(true)},
                    ConversionCase{"logical", "0.", logical(false)}, ConversionCase{"string", "'x'", string("x")}));

TEST(Conversions, Errors) {
  EXPECT_EQ(run_error("@t\nglobal integer v\nv = 'x'\nendp\n"), "3:1: error 386");
  EXPECT_EQ(run_error("@t\nglobal string s\ns = 5\nendp\n"), "3:1: error 394");
  EXPECT_EQ(run_error("@t\nglobal logical l\nl = 2\nendp\n"), "3:1: error 420");
  EXPECT_EQ(run_error("@t\nglobal logical l\nl = 0.5\nendp\n"), "3:1: error 420");
  EXPECT_EQ(run_error("@t\nglobal integer i\ni = 1.E12\nendp\n"), "3:1: error 410");
}

}  // namespace
