// The corpus of broken posts: one or more per GPPTool error number that a source file can raise
// (spec 13), each asserting the number and the position. Load-time errors are all collected.
#include <gtest/gtest.h>

#include "support.hpp"

using namespace gppl_test;

namespace {

struct BrokenPost {
  const char* what;
  const char* source;
  const char* expected;  // "line:column: error N" of the first error
};

class LoadErrors : public testing::TestWithParam<BrokenPost> {};

TEST_P(LoadErrors, NumberAndPosition) {
  EXPECT_EQ(compile_error(GetParam().source), GetParam().expected) << GetParam().what;
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, LoadErrors,
    testing::Values(
        BrokenPost{"194 endif missing", "@t\nif x\n  y = 1\nendp\n", "4:1: error 194"},
        BrokenPost{"194 endw missing", "@t\nwhile x\nendp\n", "3:1: error 194"},
        BrokenPost{"384 nine nested ifs",
                   "@t\nif a\nif a\nif a\nif a\nif a\nif a\nif a\nif a\n  if a\n  endif\nendif\nendif\nendif\n"
                   "endif\nendif\nendif\nendif\nendif\nendp\n",
                   "10:3: error 384"},
        BrokenPost{"384 nine nested whiles",
                   "@t\nwhile a\nwhile a\nwhile a\nwhile a\nwhile a\nwhile a\nwhile a\nwhile a\nwhile a\nendw\n"
                   "endw\nendw\nendw\nendw\nendw\nendw\nendw\nendw\nendp\n",
                   "10:1: error 384"},
        BrokenPost{"385 statement outside a procedure", "@a\nendp\nx = 1\n@b\nendp\n", "3:1: error 385"},
        BrokenPost{"385 endif without if", "@t\n  endif\nendp\n", "2:3: error 385"},
        BrokenPost{"385 else without if", "@t\nelse\nendp\n", "2:1: error 385"},
        BrokenPost{"385 endw without while", "@t\nendw\nendp\n", "2:1: error 385"},
        BrokenPost{"385 misspelt keyword", "@t\nendiff\nendp\n", "2:1: error 385"},
        BrokenPost{"385 junk line", "@t\n+ 3\nendp\n", "2:1: error 385"},
        BrokenPost{"385 unterminated string in trace", "@t\ntrace 'all:1\nendp\n", "2:13: error 385"},
        BrokenPost{"385 trace without level", "@t\ntrace 'all'\nendp\n", "2:12: error 385"},
        BrokenPost{"385 inc inside a procedure", "@t\ninc 'other'\nendp\n", "2:1: error 385"},
        BrokenPost{"385 endp outside a procedure", "endp\n", "1:1: error 385"},
        BrokenPost{"385 integer literal too large", "@t\nx = 1000000000\nendp\n", "2:5: error 385"},
        BrokenPost{"385 \\x00 in a string", "@t\nx = 'a\\x00'\nendp\n", "2:5: error 385"},
        BrokenPost{"385 format outside tostr", "@t\nx = upper('a':'5.3')\nendp\n", "2:14: error 385"},
        BrokenPost{"385 wrong argument count", "@t\nx = left('a')\nendp\n", "2:5: error 385"},
        BrokenPost{"385 break with junk", "@t\nbreak now\nendp\n", "2:7: error 385"},
        BrokenPost{"385 expression nests too deeply",
                   "@t\nx = ((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((("
                   "((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((("
                   "((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((("
                   "((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((("
                   "((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((1\nendp\n",
                   "2:1: error 384"},
        BrokenPost{"386/389: only variables have attributes", "@t\nactive(x - 1) = 0\nendp\n", "2:10: error 389"},
        BrokenPost{"387 scalar used with an index", "@t\nglobal integer a\nx = a<<1>>\nendp\n", "3:5: error 387"},
        BrokenPost{"387 array used without index", "@t\nglobal integer a<<3>>\nx = a\nendp\n", "3:5: error 387"},
        BrokenPost{"387 wrong number of indices", "@t\nglobal integer a<<3>>\nx = a<<1,2>>\nendp\n", "3:5: error 387"},
        BrokenPost{"388 header before endp", "@a\nx = 1\n@b\nendp\n", "3:1: error 388"},
        BrokenPost{"388 endp missing at end of file", "@a\nx = 1\n", "2:1: error 388"},
        BrokenPost{"388 procedures do not nest", "@a\n  proc @b\nendp\n", "2:3: error 388"},
        BrokenPost{"389 assignment without value", "@t\nx =\nendp\n", "2:4: error 389"},
        BrokenPost{"389 unterminated string", "@t\nx = 'no, no, no!\"\nendp\n", "2:18: error 389"},
        BrokenPost{"389 function as target", "@t\nround = 1\nendp\n", "2:1: error 389"},
        BrokenPost{"389 missing operand", "@t\nx = 1 +\nendp\n", "2:8: error 389"},
        BrokenPost{"389 unbalanced parenthesis", "@t\nx = (1 + 2\nendp\n", "2:11: error 389"},
        BrokenPost{"390 generate not closed", "@t\n{nb, 'G'gcode\nendp\n", "2:14: error 390"},
        BrokenPost{"390 nb inside a modal group", "@t\n{[nb 'X']}\nendp\n", "2:3: error 390"},
        BrokenPost{"390 modal group not closed", "@t\n{[' X'xpos}\nendp\n", "2:11: error 390"},
        BrokenPost{"390 unparenthesised expression", "@t\n{nb, xpos*2}\nendp\n", "2:10: error 390"},
        BrokenPost{"391 call without procedure name", "@t\ncall stop_tool\nendp\n", "2:6: error 391"},
        BrokenPost{"391 call with wrong argument count", "@t\ncall @m(1)\nendp\n@m(numeric a, numeric b)\nendp\n",
                   "2:6: error 391"},
        BrokenPost{"392 if without condition", "@t\nif then\nendif\nendp\n", "2:4: error 392"},
        BrokenPost{"392 junk after endif", "@t\nif a\nendif a\nendp\n", "3:7: error 392"},
        BrokenPost{"392 second else", "@t\nif a\nelse\nelse\nendif\nendp\n", "4:1: error 392"},
        BrokenPost{"396 procedure defined twice", "@line\nendp\n@LINE\nendp\n", "3:1: error 396"},
        BrokenPost{"396 two @init_inc in one file", "@init_inc\nendp\n@init_inc\nendp\n", "3:1: error 396"},
        BrokenPost{"400 global without type", "@t\nglobal x\nendp\n", "2:8: error 400"},
        BrokenPost{"400 global trailing comma", "@t\nglobal integer a,\nendp\n", "2:17: error 400"},
        BrokenPost{"400 global array size 0", "@t\nglobal integer a<<0>>\nendp\n", "2:19: error 400"},
        BrokenPost{"400 global array size 10000", "@t\nglobal integer a<<10000>>\nendp\n", "2:19: error 400"},
        BrokenPost{"400 global with a function name", "@t\nglobal numeric sin\nendp\n", "2:16: error 400"},
        BrokenPost{"401 local without name", "@t\nlocal string\nendp\n", "2:13: error 401"},
        BrokenPost{"402 assignment to PI", "@t\nPI = 3\nendp\n", "2:1: error 402"},
        BrokenPost{"402 assignment to TRUE", "@t\n  true = 0\nendp\n", "2:3: error 402"},
        BrokenPost{"403 array too large", "@t\nglobal numeric a<<9999,9999>>\nendp\n", "2:16: error 403"},
        BrokenPost{"404 call of a missing procedure", "@t\ncall @nothere\nendp\n", "2:6: error 404"},
        BrokenPost{"411 global with another type", "@a\nglobal integer g\nendp\n@b\nglobal numeric g\nendp\n",
                   "5:16: error 411"},
        BrokenPost{"412 local with another type", "@a\nlocal integer l\nlocal string l\nendp\n", "3:14: error 412"},
        BrokenPost{"415 global already local", "@a\nlocal integer v\nendp\n@b\nglobal integer v\nendp\n",
                   "5:16: error 415"},
        BrokenPost{"416 local already global", "@a\nglobal integer v\nendp\n@b\nlocal integer v\nendp\n",
                   "5:15: error 416"},
        BrokenPost{"416 parameter already global", "@a\nglobal integer v\nendp\n@b(integer v)\nendp\n",
                   "4:12: error 416"},
        BrokenPost{"418 system variable declared as text", "@t\nglobal string gcode\nendp\n", "2:15: error 418"},
        BrokenPost{"418 read-only system variable declared", "@t\nlocal numeric pi\nendp\n", "2:15: error 418"}));

TEST(LoadErrors, UndefinedNamesWhenHostListsAll) {
  gppl::CompileOptions strict;
  strict.implicit_host_variables = false;
  EXPECT_EQ(compile_error("@t\nglobal integer a\na = b + 1\nendp\n", strict), "3:5: error 383");
  EXPECT_EQ(compile_error("@t\nb = 1\nendp\n", strict), "2:1: error 404");
  EXPECT_EQ(compile_error("@t\nactive(b) = 1\nendp\n", strict), "2:8: error 404");
}

// A name nothing declares gets the nearest declared, local or system name as a hint.
TEST(LoadErrors, UndefinedNamesSuggestTheNearest) {
  gppl::CompileOptions strict;
  strict.implicit_host_variables = false;
  auto message = [&](const std::string& source) {
    try {
      gppl::compile_source(source, "e.gpp", strict);
    } catch (const gppl::Errors& e) {
      return std::string(e.all().front().what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("@t\n{nb, xpso}\nendp\n"), "e.gpp:2:6: error 383: Variable 'xpso' is not defined: did you mean 'xpos'?");
  EXPECT_EQ(message("@t\nlocal numeric depth\ndepht = 2\nendp\n"),
            "e.gpp:3:1: error 404: Symbol 'depht' does not exist: did you mean 'depth'?");
  EXPECT_EQ(message("@t\nqqqq = 2\nendp\n"), "e.gpp:2:1: error 404: Symbol 'qqqq' does not exist");
}

// `check` (check_constant_assignments) checks an assignment of a constant at its line, as the run
// would when the line runs; a run still compiles such a post and stops only if the line runs.
TEST(LoadErrors, ConstantAssignmentsAreCheckedWhereTheyStand) {
  gppl::CompileOptions checking;
  checking.check_constant_assignments = true;
  struct Case {
    const char* source;
    const char* error;
  } cases[] = {
      {"@t\nxpos_f = '5.3p'\nendp\n",
       "e.gpp:2:10: error 423: Format: Invalid format option, unexpected 'p' in '5.3p' (the display format of xpos_f); "
       "did you mean '5.3(p)'?"},
      {"@t\nfeed_f = '4.1 d'\nendp\n",
       "e.gpp:2:10: error 423: Format: Invalid format option, unexpected 'd' in '4.1 d' (the display format of feed_f); "
       "did you mean '4.1 (d)'?"},
      {"@t\nzpos_f = '5'\nendp\n", "e.gpp:2:10: error 421: Format: No decimal point in '5' (the display format of zpos_f)"},
      {"@t\nfeed_f = 5.0\nendp\n", "e.gpp:2:10: error 394: Variable 'feed_f' is not string variable: a number assigned to a text variable"},
      {"@t\ngcode = 'G1'\nendp\n", "e.gpp:2:9: error 386: Variable 'gcode' is not numeric: text assigned to a number variable"},
      {"@t\nxpos_f = '5.3(p)'\ngcode = 1\nfeed_f = '4.1' + 'z'\nendp\n", "no error"},
  };
  for (const Case& c : cases) {
    std::string got = "no error";
    try {
      gppl::compile_source(c.source, "e.gpp", checking);
    } catch (const gppl::Errors& e) {
      got = e.all().front().what();
    }
    EXPECT_EQ(got, c.error) << c.source;
    EXPECT_EQ(compile_error(c.source), "no error") << "a run compiles it: " << c.source;
  }
}

TEST(LoadErrors, CollectsEveryError) {
  try {
    gppl::compile_source("@t\nif a\nx =\n{nb\nendp\nstray\n", "e.gpp", {});
    FAIL() << "no error";
  } catch (const gppl::Errors& e) {
    std::vector<int> numbers;
    for (const auto& one : e.all()) numbers.push_back(one.number());
    EXPECT_EQ(numbers, (std::vector<int>{389, 390, 385, 194}));
    EXPECT_EQ(std::string(e.all()[3].what()),
              "e.gpp:5:1: error 194: ENDIF statement missing: the IF at line 2 is not closed");
    EXPECT_EQ(std::string(e.all()[0].what()), "e.gpp:3:4: error 389: Invalid ASSIGNMENT statement: expected an expression");
  }
}

TEST(LoadErrors, MessagesNameTheSymbol) {
  try {
    gppl::compile_source("@a\nglobal integer g\nendp\n@b\nglobal string g\nendp\n", "post.gpp", {});
    FAIL() << "no error";
  } catch (const gppl::Errors& e) {
    EXPECT_EQ(std::string(e.all()[0].what()), "post.gpp:5:15: error 411: Global variable 'g' is multiply defined");
  }
}

TEST(LoadErrors, MissingMainFile) {
  try {
    gppl::compile_file("gppl/data/does-not-exist.gpp", {});
    FAIL() << "no error";
  } catch (const gppl::Errors& e) {
    EXPECT_EQ(e.all()[0].number(), 399);
    EXPECT_EQ(std::string(e.all()[0].what()),
              "gppl/data/does-not-exist.gpp:1:1: error 399: Can't open file 'gppl/data/does-not-exist.gpp'");
  }
}

struct RunCase {
  const char* what;
  const char* source;  // procedure @t runs after @init_post
  const char* expected;
};

class RunErrors : public testing::TestWithParam<RunCase> {};

TEST_P(RunErrors, NumberAndPosition) { EXPECT_EQ(run_error(GetParam().source), GetParam().expected) << GetParam().what; }

INSTANTIATE_TEST_SUITE_P(
    Catalogue, RunErrors,
    testing::Values(RunCase{"386 string where a number is needed", "@t\nglobal integer i\ni = 'a'\nendp\n", "3:1: error 386"},
                    RunCase{"387 function argument", "@t\nx = sqrt(-4)\nendp\n", "2:5: error 387"},
                    RunCase{"387 index out of range", "@t\nglobal string s<<2>>\ns<<3>> = 'x'\nendp\n", "3:1: error 387"},
                    RunCase{"394 number where a string is needed", "@t\nglobal string s\ns = 1\nendp\n", "3:1: error 394"},
                    RunCase{"394 string function argument", "@t\nx = upper(5)\nendp\n", "2:5: error 394"},
                    RunCase{"405 runaway recursion", "@t\ncall @t\nendp\n", "2:1: error 405"},
                    RunCase{"407 zero divide", "@t\nx = 0\ny = 5 / x\nendp\n", "3:7: error 407"},
                    RunCase{"407 mod by zero", "@t\nx = mod(7, 0)\nendp\n", "2:5: error 407"},
                    RunCase{"408 format without digits", "@t\n{nb, 1.:'.3'}\nendp\n", "2:6: error 408"},
                    RunCase{"409 bad scale", "@t\n{nb, 1.:'5.3(*)'}\nendp\n", "2:6: error 409"},
                    RunCase{"410 number too large to print", "@t\n{nb, 1.E101}\nendp\n", "2:6: error 410"},
                    RunCase{"410 integer overflow", "@t\nx = 999999999 * 2\nendp\n", "2:15: error 410"},
                    RunCase{"420 logical variable", "@t\nglobal logical l\nl = 2\nendp\n", "3:1: error 420"},
                    RunCase{"420 attribute value", "@t\nchange(x) = 3\nendp\n", "2:1: error 420"},
                    RunCase{"421 format without point", "@t\n{nb, 1.:'5'}\nendp\n", "2:6: error 421"},
                    RunCase{"422 format without fraction", "@t\n{nb, 1.:'5.'}\nendp\n", "2:6: error 422"},
                    RunCase{"423 bad format option", "@t\n{nb, 1.:'5.3(q)'}\nendp\n", "2:6: error 423"},
                    RunCase{"423 format by tostr", "@t\nx = tostr(1.:'5.3(q)')\nendp\n", "2:5: error 423"},
                    RunCase{"452 block number too big",
                            "@t\nblknum_gen = TRUE\nblknum_max = 10\nblknum = 10\n{nb}\n{nb}\nendp\n",
                            "6:2: error 452"},
                    RunCase{"385 trace level out of range", "@t\ntrace 'all':6\nendp\n", "2:1: error 385"}));

}  // namespace
