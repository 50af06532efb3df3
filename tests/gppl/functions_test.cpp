// Internal functions: every example of the language spec for the numeric and logical functions
// (sections 9.2, 9.5; the string functions are in functions_string_test.cpp), every error case
// with its number, and the signature table the interpreter relies on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "gppl/builtins/functions.hpp"
#include "tests/gppl/function_call.hpp"

namespace {

using gppl::Type;
using gppl::Value;
using namespace function_test;

double as_number(const Value& v) { return v.type == Type::Numeric ? v.numeric : static_cast<double>(v.integer); }

// ---------------------------------------------------------------------------------------------
// Numeric functions (spec 9.2)

constexpr double exact = 0;

struct NumericCase {
  const char* call;  // for the failure message
  Value result;
  double expected;
  double tolerance = 1e-9;  // 0: exact
};

std::ostream& operator<<(std::ostream& os, const NumericCase& c) { return os << c.call; }

std::vector<NumericCase> numeric_cases() {
  const double pi = std::numbers::pi;
  return {
      {"abs(12.3-8)", call("abs", {num(12.3 - 8)}), 4.3},
      {"abs(8-12.3)", call("abs", {num(8 - 12.3)}), 4.3},
      {"acos(1)", call("acos", {integer(1)}), 0, exact},
      {"acos(-1)", call("acos", {integer(-1)}), 180, exact},
      {"ang(5,5)", call("ang", {integer(5), integer(5)}), 45, exact},
      {"ang(-3, 0)", call("ang", {integer(-3), integer(0)}), 180, exact},
      {"ang(5, -5)", call("ang", {integer(5), integer(-5)}), -45, exact},
      {"asin(1)", call("asin", {integer(1)}), 90, exact},
      {"asin(-0.5)", call("asin", {num(-0.5)}), -30, exact},
      {"atan(1)", call("atan", {integer(1)}), 45, exact},
      {"atan(-1)", call("atan", {integer(-1)}), -45, exact},
      {"atan2(5,5)", call("atan2", {integer(5), integer(5)}), 45, exact},
      {"atan2(-3, 0)", call("atan2", {integer(-3), integer(0)}), -90, exact},
      {"atan2(5, -5)", call("atan2", {integer(5), integer(-5)}), 135, exact},
      {"cos(90)", call("cos", {integer(90)}), 0, exact},
      {"cos(810)", call("cos", {integer(810)}), 0, exact},
      {"cos(540)", call("cos", {integer(540)}), -1, exact},
      {"cos(acos(1))", call("cos", {call("acos", {integer(1)})}), 1, exact},
      {"dist(3, 4)", call("dist", {integer(3), integer(4)}), 5, exact},
      {"dist(-3, 4)", call("dist", {integer(-3), integer(4)}), 5, exact},
      {"dist(12, -5)", call("dist", {integer(12), integer(-5)}), 13, exact},
      {"exp(0)", call("exp", {integer(0)}), 1, exact},
      {"exp(1)", call("exp", {integer(1)}), 2.718281828459045},
      {"exp(-0.5)", call("exp", {num(-0.5)}), 0.6065306597126334},
      {"frac(12.345)", call("frac", {num(12.345)}), 0.345, exact},
      {"frac(-12.345)", call("frac", {num(-12.345)}), 0.345, exact},
      {"frac(12)", call("frac", {integer(12)}), 0, exact},
      {"int(12.345)", call("int", {num(12.345)}), 12, exact},
      {"int(-12.345)", call("int", {num(-12.345)}), -12, exact},
      {"int(frac(12.3))", call("int", {call("frac", {num(12.3)})}), 0, exact},
      {"log(1)", call("log", {integer(1)}), 0, exact},
      {"log(2.718281828)", call("log", {num(2.718281828)}), 1},
      {"log10(1)", call("log10", {integer(1)}), 0, exact},
      {"log10(10)", call("log10", {integer(10)}), 1, exact},
      {"log10(1000)", call("log10", {integer(1000)}), 3, exact},
      {"mod(5, 2)", call("mod", {integer(5), integer(2)}), 1, exact},
      {"mod(-17, 3)", call("mod", {integer(-17), integer(3)}), -2, exact},
      {"mod(9.2, 4)", call("mod", {num(9.2), integer(4)}), 1.2, exact},
      {"pow(10, 3)", call("pow", {integer(10), integer(3)}), 1000, exact},
      {"pow(0, 12)", call("pow", {integer(0), integer(12)}), 0, exact},
      {"pow(25, 0.5)", call("pow", {integer(25), num(0.5)}), 5, exact},
      {"pow(-2, 2)", call("pow", {integer(-2), integer(2)}), 4, exact},
      {"4 ^ 3 ^ 2", call("pow", {integer(4), call("pow", {integer(3), integer(2)})}), 262144, exact},
      {"round(12.3456, 1)", call("round", {num(12.3456), integer(1)}), 12.3, exact},
      {"round(12.3456, 3)", call("round", {num(12.3456), integer(3)}), 12.346, exact},
      {"round(12.5, 0)", call("round", {num(12.5), integer(0)}), 13, exact},
      {"round(-12.5, 0)", call("round", {num(-12.5), integer(0)}), -13, exact},
      {"round(123.4, -1)", call("round", {num(123.4), integer(-1)}), 120, exact},
      {"round(126.4, -1)", call("round", {num(126.4), integer(-1)}), 130, exact},
      {"round(123, -3)", call("round", {integer(123), integer(-3)}), 0, exact},
      {"round2val(730, 360)", call("round2val", {integer(730), integer(360)}), 720, exact},
      {"round2val(17.5, 2)", call("round2val", {num(17.5), integer(2)}), 18, exact},
      {"round2val(8.5, 2.1)", call("round2val", {num(8.5), num(2.1)}), 8.4, exact},
      {"sign(123.4)", call("sign", {num(123.4)}), 1, exact},
      {"sign(-123.4)", call("sign", {num(-123.4)}), -1, exact},
      {"sign(cos(90))", call("sign", {call("cos", {integer(90)})}), 0, exact},
      {"sin(90)", call("sin", {integer(90)}), 1, exact},
      {"sin(990)", call("sin", {integer(990)}), -1, exact},
      {"sin(540)", call("sin", {integer(540)}), 0, exact},
      {"sin(asin(1))", call("sin", {call("asin", {integer(1)})}), 1, exact},
      {"sqrt(25)", call("sqrt", {integer(25)}), 5, exact},
      {"sqrt(0)", call("sqrt", {integer(0)}), 0, exact},
      {"square(5)", call("square", {integer(5)}), 25, exact},
      {"square(-5)", call("square", {integer(-5)}), 25, exact},
      {"square(0)", call("square", {integer(0)}), 0, exact},
      {"tan(45)", call("tan", {integer(45)}), 1, exact},
      {"tan(540)", call("tan", {integer(540)}), 0, exact},
      {"todeg(0)", call("todeg", {integer(0)}), 0, exact},
      {"todeg(1)", call("todeg", {integer(1)}), 57.29577951308232},
      {"todeg(pi)", call("todeg", {num(pi)}), 180, exact},
      {"torad(0)", call("torad", {integer(0)}), 0, exact},
      {"torad(57.295779)", call("torad", {num(57.295779)}), 1, 1e-7},  // the manual's "1 (approximately)"
      {"torad(180)", call("torad", {integer(180)}), pi, exact},
      // beyond the manual: negative angles, other exact angles, numeric arguments of generic functions
      {"sin(-90)", call("sin", {integer(-90)}), -1, exact},
      {"sin(30)", call("sin", {integer(30)}), 0.5, exact},
      {"cos(-120)", call("cos", {integer(-120)}), -0.5, exact},
      {"cos(0.5)", call("cos", {num(0.5)}), 0.9999619230641713},
      {"tan(-45)", call("tan", {integer(-45)}), -1, exact},
      {"tan(30)", call("tan", {integer(30)}), 0.5773502691896257},
      {"ang(-3, -0.0)", call("ang", {integer(-3), num(-0.0)}), 180, exact},
      {"atan2(0, 1)", call("atan2", {integer(0), integer(1)}), 0, exact},
      {"atan(1e300)", call("atan", {num(1e300)}), 90, exact},
      {"mod(-9.5, 4)", call("mod", {num(-9.5), integer(4)}), -1.5, exact},
      {"mod(7, -3)", call("mod", {integer(7), integer(-3)}), 1, exact},
      {"square(1.5)", call("square", {num(1.5)}), 2.25, exact},
      {"abs(-7)", call("abs", {integer(-7)}), 7, exact},
      {"int(2.9999999999)", call("int", {num(2.9999999999)}), 3, exact},
      {"int(-999999999.)", call("int", {num(-999999999.)}), -999999999, exact},
      {"round(2.675, 2)", call("round", {num(2.675), integer(2)}), 2.68, exact},
      {"round(1.5, 2.0000000001)", call("round", {num(1.5), num(2.0000000001)}), 1.5, exact},
      {"round2val(-3, 2)", call("round2val", {integer(-3), integer(2)}), -4, exact},
      {"round2val(0.3, 0.1)", call("round2val", {num(0.3), num(0.1)}), 0.3, exact},
      {"pow(-2, 3)", call("pow", {integer(-2), integer(3)}), -8, exact},
      {"pow(2, -1)", call("pow", {integer(2), integer(-1)}), 0.5, exact},
      {"exp(-1000)", call("exp", {integer(-1000)}), 0, exact},
  };
}

class NumericFunctions : public testing::TestWithParam<NumericCase> {};

TEST_P(NumericFunctions, MatchTheManual) {
  const NumericCase& c = GetParam();
  if (c.tolerance == exact)
    EXPECT_EQ(as_number(c.result), c.expected);
  else
    EXPECT_NEAR(as_number(c.result), c.expected, c.tolerance);
}

INSTANTIATE_TEST_SUITE_P(Spec, NumericFunctions, testing::ValuesIn(numeric_cases()));

TEST(NumericFunctions, TanOfNinetyIsHugeNotAnError) {
  EXPECT_GT(call("tan", {integer(90)}).numeric, 1e15);
  EXPECT_GT(std::fabs(call("tan", {integer(-90)}).numeric), 1e15);  // the period is 180 degrees
}

TEST(NumericFunctions, ResultTypes) {
  EXPECT_EQ(call("int", {num(12.3)}).type, Type::Integer);
  EXPECT_EQ(call("sign", {num(-2.)}).type, Type::Integer);
  EXPECT_EQ(call("abs", {integer(-3)}), integer(3));
  EXPECT_EQ(call("abs", {num(-3.)}), num(3.));
  EXPECT_EQ(call("abs", {Value::of_logical(true)}), integer(1));
  EXPECT_EQ(call("square", {integer(-4)}), integer(16));
  EXPECT_EQ(call("mod", {integer(5), integer(2)}), integer(1));
  EXPECT_EQ(call("mod", {num(5.), integer(2)}), num(1.));
  EXPECT_EQ(call("pow", {integer(10), integer(3)}).type, Type::Numeric);
  EXPECT_EQ(call("sqrt", {integer(25)}).type, Type::Numeric);
  EXPECT_EQ(call("cos", {integer(90)}), num(0.));  // not -0.
}

TEST(NumericFunctions, ResultTypeFollowsIntegerArguments) {
  const gppl::FunctionSignature* abs = gppl::find_function("ABS");
  ASSERT_NE(abs, nullptr);
  EXPECT_TRUE(abs->integer_if_integer_args);
  const Type ints[] = {Type::Integer, Type::Logical};
  const Type mixed[] = {Type::Integer, Type::Numeric};
  EXPECT_EQ(gppl::result_type(*abs, std::span(ints, 1)), Type::Integer);
  EXPECT_EQ(gppl::result_type(*gppl::find_function("mod"), ints), Type::Integer);
  EXPECT_EQ(gppl::result_type(*gppl::find_function("mod"), mixed), Type::Numeric);
  EXPECT_EQ(gppl::result_type(*gppl::find_function("sqrt"), std::span(ints, 1)), Type::Numeric);
  EXPECT_EQ(gppl::result_type(*gppl::find_function("int"), std::span(mixed + 1, 1)), Type::Integer);
}

// ---------------------------------------------------------------------------------------------
// Logical functions (spec 9.5)

TEST(LogicalFunctions, EvenAndOdd) {
  auto is = [](const char* name, Value v) { return call(name, {std::move(v)}); };
  EXPECT_EQ(is("even", integer(8)), Value::of_logical(true));
  EXPECT_EQ(is("even", integer(13)), Value::of_logical(false));
  EXPECT_EQ(is("even", num(4.2)), Value::of_logical(false));
  EXPECT_EQ(is("odd", integer(7)), Value::of_logical(true));
  EXPECT_EQ(is("odd", integer(14)), Value::of_logical(false));
  EXPECT_EQ(is("odd", num(3.2)), Value::of_logical(false));
  EXPECT_EQ(is("even", integer(-2)), Value::of_logical(true));
  EXPECT_EQ(is("odd", integer(-3)), Value::of_logical(true));
  EXPECT_EQ(is("even", integer(0)), Value::of_logical(true));
  EXPECT_EQ(is("even", num(4.0000000001)), Value::of_logical(true));  // representation noise
  EXPECT_EQ(is("odd", num(4.5)), Value::of_logical(false));
}

// ---------------------------------------------------------------------------------------------
// Errors: every domain error with its GPPTool number (spec 9, 13)

struct ErrorCase {
  const char* call;
  const char* name;
  std::vector<Value> args;
  int error;
};

std::ostream& operator<<(std::ostream& os, const ErrorCase& c) { return os << c.call; }

class FunctionErrors : public testing::TestWithParam<ErrorCase> {};

TEST_P(FunctionErrors, ThrowTheirNumber) {
  const ErrorCase& c = GetParam();
  try {
    Value v = call(c.name, c.args);
    FAIL() << c.call << " returned a value";
  } catch (const gppl::Error& e) {
    EXPECT_EQ(e.number(), c.error) << c.call << ": " << e.what();
    EXPECT_TRUE(e.where().file.empty());
  }
}

INSTANTIATE_TEST_SUITE_P(
    Spec, FunctionErrors,
    testing::Values(
        ErrorCase{"pow(-2, 3.5)", "pow", {integer(-2), num(3.5)}, 387},
        ErrorCase{"sqrt(-4)", "sqrt", {integer(-4)}, 387},
        ErrorCase{"mod(7, 0)", "mod", {integer(7), integer(0)}, 407},
        ErrorCase{"mod(7.5, 0)", "mod", {num(7.5), integer(0)}, 407},
        ErrorCase{"log(0)", "log", {integer(0)}, 387},
        ErrorCase{"log(-1)", "log", {integer(-1)}, 387},
        ErrorCase{"log10(0)", "log10", {integer(0)}, 387},
        ErrorCase{"acos(1.5)", "acos", {num(1.5)}, 387},
        ErrorCase{"asin(-1.5)", "asin", {num(-1.5)}, 387},
        ErrorCase{"ang(0, 0)", "ang", {integer(0), integer(0)}, 387},
        ErrorCase{"atan2(0, 0)", "atan2", {integer(0), integer(0)}, 387},
        ErrorCase{"pow(0, 0)", "pow", {integer(0), integer(0)}, 387},
        ErrorCase{"pow(0, -1)", "pow", {integer(0), integer(-1)}, 387},
        ErrorCase{"round2val(5, 0)", "round2val", {integer(5), integer(0)}, 407},
        ErrorCase{"round(1.5, 0.5)", "round", {num(1.5), num(0.5)}, 387},
        ErrorCase{"int(1e10)", "int", {num(1e10)}, 387},
        ErrorCase{"exp(1000)", "exp", {integer(1000)}, 410},
        ErrorCase{"pow(10, 400)", "pow", {integer(10), integer(400)}, 410},
        ErrorCase{"square(1e200)", "square", {num(1e200)}, 410},
        ErrorCase{"square(100000)", "square", {integer(100000)}, 410},
        ErrorCase{"left('abcdef', -2)", "left", {str("abcdef"), integer(-2)}, 387},
        ErrorCase{"right('abcdef',-2)", "right", {str("abcdef"), integer(-2)}, 387},
        ErrorCase{"space(-3)", "space", {integer(-3)}, 387},
        ErrorCase{"dup('a', -1)", "dup", {str("a"), integer(-1)}, 387},
        ErrorCase{"dup('abc', 999999999)", "dup", {str("abc"), integer(999999999)}, 387},
        ErrorCase{"substr('abcdefg',9,2)", "substr", {str("abcdefg"), integer(9), integer(2)}, 387},
        ErrorCase{"substr('abcdefg',0,2)", "substr", {str("abcdefg"), integer(0), integer(2)}, 387},
        ErrorCase{"substr('abc',1,-1)", "substr", {str("abc"), integer(1), integer(-1)}, 387},
        ErrorCase{"substr('',1,0)", "substr", {str(""), integer(1), integer(0)}, 387},
        ErrorCase{"tonum('abc')", "tonum", {str("abc")}, 387},
        ErrorCase{"tonum('')", "tonum", {str("")}, 387},
        ErrorCase{"tonum('12x')", "tonum", {str("12x")}, 387},
        ErrorCase{"tonum('1 2')", "tonum", {str("1 2")}, 387},
        ErrorCase{"tonum('.')", "tonum", {str(".")}, 387},
        ErrorCase{"tonum('e5')", "tonum", {str("e5")}, 387},
        ErrorCase{"tonum('1e')", "tonum", {str("1e")}, 387},
        ErrorCase{"tonum('1e999')", "tonum", {str("1e999")}, 410},
        ErrorCase{"replace(123, 'a', 'b', 0)", "replace", {integer(123), str("a"), str("b"), integer(0)}, 394},
        ErrorCase{"upper(5)", "upper", {integer(5)}, 394},
        ErrorCase{"sqrt('4')", "sqrt", {str("4")}, 386},
        ErrorCase{"tostr('x')", "tostr", {str("x")}, 386},
        ErrorCase{"tostr(1:'5')", "tostr", {integer(1), str("5")}, 421},
        ErrorCase{"tostr(1:'5.3(q)')", "tostr", {integer(1), str("5.3(q)")}, 423},
        ErrorCase{"tostr(1e101)", "tostr", {num(1e101)}, 410}));

// ---------------------------------------------------------------------------------------------
// The table

TEST(FunctionTable, LookupIsCaseInsensitive) {
  EXPECT_EQ(gppl::find_function("Round2Val"), gppl::find_function("round2val"));
  EXPECT_NE(gppl::find_function("SQRT"), nullptr);
  EXPECT_EQ(gppl::find_function("sqr"), nullptr);
  EXPECT_EQ(gppl::find_function("change"), nullptr);  // attributes are the interpreter's
  EXPECT_EQ(gppl::find_function("active"), nullptr);
  EXPECT_EQ(gppl::find_function(""), nullptr);
}

TEST(FunctionTable, EveryFunctionOfTheSpec) {
  const char* names[] = {"abs",  "acos", "ang",   "asin",  "atan",    "atan2", "cos",   "dist",   "exp",
                         "frac", "int",  "log",   "log10", "mod",     "pow",   "round", "round2val", "sign",
                         "sin",  "sqrt", "square", "tan",  "todeg",   "torad", "date",  "dup",    "instr",
                         "left", "lower", "replace", "rev", "right",  "space", "strlen", "substr", "time",
                         "tonum", "tostr", "trim", "upper", "even",   "odd",   "norm360", "adims", "alen",
                         "asize"};
  EXPECT_EQ(gppl::all_functions().size(), std::size(names));
  for (const char* n : names) EXPECT_NE(gppl::find_function(n), nullptr) << n;
}

TEST(FunctionTable, OptionalArgumentsAndSpecialForms) {
  const auto* replace_f = gppl::find_function("replace");
  EXPECT_EQ(replace_f->min_args, 3u);
  EXPECT_EQ(replace_f->parameters.size(), 4u);
  const auto* tostr = gppl::find_function("tostr");
  EXPECT_EQ(tostr->min_args, 1u);
  EXPECT_TRUE(tostr->format_argument);
  EXPECT_EQ(tostr->parameters, (std::vector<Type>{Type::Numeric, Type::String}));
  EXPECT_TRUE(gppl::find_function("date")->no_parentheses);
  EXPECT_TRUE(gppl::find_function("time")->parameters.empty());
  EXPECT_EQ(gppl::find_function("substr")->min_args, 3u);
  EXPECT_EQ(gppl::find_function("even")->result, Type::Logical);
  EXPECT_EQ(gppl::find_function("instr")->result, Type::Integer);
}

TEST(FunctionTable, WrongArgumentCountIsAProgrammingError) {
  EXPECT_THROW(gppl::call_function(*gppl::find_function("sqrt"), {}), std::invalid_argument);
  std::vector<Value> three = {integer(1), integer(2), integer(3)};
  EXPECT_THROW(gppl::call_function(*gppl::find_function("pow"), three), std::invalid_argument);
}

TEST(FunctionTable, ACopiedSignatureStillWorks) {
  gppl::FunctionSignature copy = *gppl::find_function("sqrt");
  std::vector<Value> args = {integer(16)};
  EXPECT_EQ(gppl::call_function(copy, args), num(4.));
}

}  // namespace
