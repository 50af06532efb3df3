// Statements and attributes: the vectors of spec 3.6 and 5.10, procedures with typed parameters,
// locals, host change overrides, stop statements and runaway protection.
#include <gtest/gtest.h>

#include <sstream>

#include "support.hpp"

using namespace gppl_test;
using gppl::ChangeOverride;
using gppl::RunResult;

namespace {

struct AttributeCase {
  const char* steps;
  bool change;
  bool active;
};

class Attributes : public testing::TestWithParam<AttributeCase> {};

TEST_P(Attributes, AfterSteps) {
  Post post(std::string("@init_post\nglobal integer g\nendp\n@t\n") + GetParam().steps + "\nendp\n");
  post.run->start();
  post.call("@t");
  EXPECT_EQ(post.run->changed(post.id("g")), GetParam().change) << GetParam().steps;
  EXPECT_EQ(post.run->active(post.id("g")), GetParam().active) << GetParam().steps;
}

INSTANTIATE_TEST_SUITE_P(Spec36, Attributes,
                         testing::Values(AttributeCase{"g = 0", true, true}, AttributeCase{"g = 1\ng = 1", false, true},
                                         AttributeCase{"g = 1\ng = 2", true, true},
                                         AttributeCase{"g = 1\ng = 1\nchange(g) = TRUE", true, true},
                                         AttributeCase{"active(g) = FALSE\ng = 3", true, true},
                                         AttributeCase{"g = 1\nactive(g) = FALSE", true, false},
                                         AttributeCase{"g = 1\nchange(g) = 0", false, true},
                                         AttributeCase{"", false, true}, AttributeCase{"g = 1.4\ng = 1", false, true}));

TEST(Attributes, Errors) {
  EXPECT_EQ(run_error("@t\nglobal integer g\ng = 5\nchange(g) = 2\nendp\n"), "4:1: error 420");
  EXPECT_EQ(compile_error("@t\nglobal integer g\nactive(g - 1) = 0\nendp\n"), "3:10: error 389");
  EXPECT_EQ(compile_error("@t\nx = change(123)\nendp\n"), "2:12: error 389");
}

TEST(Attributes, HostOverrides) {
  Post post("@t\nx = xpos\nendp\n");
  post.set("xpos", numeric(1.));
  EXPECT_TRUE(post.run->changed(post.id("xpos")));
  post.set("xpos", numeric(1.));
  EXPECT_FALSE(post.run->changed(post.id("xpos")));
  post.set("xpos", numeric(1.), ChangeOverride::ForceChanged);
  EXPECT_TRUE(post.run->changed(post.id("xpos")));
  post.set("xpos", numeric(2.), ChangeOverride::ForceUnchanged);
  EXPECT_FALSE(post.run->changed(post.id("xpos")));
  EXPECT_EQ(post.get("xpos"), numeric(2.));
  post.run->set_active(post.id("xpos"), false);
  EXPECT_FALSE(post.run->active(post.id("xpos")));
  post.set("xpos", numeric(2.));
  EXPECT_TRUE(post.run->active(post.id("xpos")));
}

TEST(Statements, ChangeImplementsModality) {
  Post post("@t\n{nb}\ng = 1\nif change(g) then\n{'G'g}\nelse\n{' '}\nendif\nendp\n");
  post.call("@t");
  post.call("@t");
  EXPECT_EQ(post.text(), "G1\n ");
}

TEST(Statements, BreakLeavesInnermostLoop) {
  Post post(R"(@t
i = 0
while TRUE
  if i eq 3
    break
  endif
  i = i + 1
endw
j = 0
while j < 2
  while TRUE
    break
  endw
  j = j + 1
endw
break
endp
)");
  EXPECT_EQ(post.call("@t"), RunResult::Normal);
  EXPECT_EQ(post.get("i"), integer(3));
  EXPECT_EQ(post.get("j"), integer(2));
}

TEST(Statements, ReturnAndExit) {
  Post post(R"(@a
{nb, 'a1'}
call @b
{nb, 'a2'}
endp
@b
{nb, 'b1'}
if mode = 1
  return
endif
if mode = 2
  exit
endif
if mode = 3
  abort
endif
{nb, 'b2'}
endp
)");
  post.set("mode", integer(1));
  EXPECT_EQ(post.call("@a"), RunResult::Normal);
  post.set("mode", integer(2));
  EXPECT_EQ(post.call("@a"), RunResult::Exit);
  post.set("mode", integer(0));
  EXPECT_EQ(post.call("@a"), RunResult::Normal);
  post.set("mode", integer(3));
  EXPECT_EQ(post.call("@a"), RunResult::Abort);
  EXPECT_EQ(post.out.lines.back(), "b1");  // abort flushed the open line
  EXPECT_EQ(post.text(), "a1\nb1\na2\na1\nb1\na1\nb1\nb2\na2\na1\nb1");
}

TEST(Statements, ExitInInitPostEndsOnlyIt) {
  Post post("@init_post\nx = 1\nexit\nx = 2\nendp\n@init_inc\ny = 1\nendp\n");
  EXPECT_EQ(post.run->start(), RunResult::Normal);
  EXPECT_EQ(post.get("x"), integer(1));
  EXPECT_EQ(post.get("y"), integer(1));
}

TEST(Statements, LocalsAreFreshPerCall) {
  Post post("@t\nlocal integer n\nlocal string s<<2>>\nn = n + 1\ns<<2>> = s<<2>> + 'x'\n{nb, n, s<<2>>}\nendp\n");
  post.call("@t");
  post.call("@t");
  EXPECT_EQ(post.text(), "1x\n1x");
}

TEST(Statements, LocalsPerActivation) {
  Post post(R"(@t
local integer depth
depth = level
level = level + 1
if level < 4
  call @t
endif
{nb, depth}
endp
)");
  post.set("level", integer(1));
  post.call("@t");
  EXPECT_EQ(post.text(), "3\n2\n1");
}

TEST(Statements, GlobalDeclarationDoesNotReset) {
  Post post("@init_post\nglobal integer g\ng = 5\nendp\n@t\nglobal integer g\n{nb, g}\nendp\n");
  post.run->start();
  post.call("@t");
  EXPECT_EQ(post.text(), "5");
}

TEST(Statements, TypedParameters) {
  Post post(R"(@t
call @linear_move(1., 2 + 1)
call @linear_move(4, 5.5)
endp
@linear_move(numeric tx, numeric ty)
{nb, 'X'tx, ' Y'ty, [' C'count]}
endp
)");
  post.call("@t");
  EXPECT_EQ(post.text(), "X1. Y3.\nX4. Y5.5");
}

TEST(Statements, CallsCommandProcedures) {
  Post post("@t\ncall @rapid_move\ncall @RAPID_MOVE\nendp\n@Rapid_Move\n{nb, 'G0'}\nendp\n");
  post.call("@t");
  EXPECT_EQ(post.text(), "G0\nG0");
  EXPECT_TRUE(post.run->find_procedure("rapid_move").has_value());
  EXPECT_FALSE(post.run->find_procedure("@line").has_value());
}

TEST(Statements, RunawayRecursion) {
  Post post("@t\ncall @t\nendp\n");
  post.run->set_limits(1000, 50);
  try {
    post.call("@t");
    FAIL() << "no error";
  } catch (const gppl::Error& e) {
    EXPECT_EQ(e.number(), 405);
    EXPECT_EQ(e.where().line, 2);
  }
}

TEST(Statements, RunawayLoop) {
  Post post("@t\nwhile TRUE\nendw\nendp\n");
  post.run->set_limits(1000, 50);
  try {
    post.call("@t");
    FAIL() << "no error";
  } catch (const gppl::Error& e) {
    EXPECT_EQ(e.number(), 405);
    EXPECT_EQ(e.where().line, 2);
  }
  // The budget is per procedure run: a fresh call may loop again.
  Post bounded("@t\ni = 0\nwhile i < 600\ni = i + 1\nendw\nendp\n");
  bounded.run->set_limits(1000, 50);
  EXPECT_EQ(bounded.call("@t"), RunResult::Normal);
  EXPECT_EQ(bounded.call("@t"), RunResult::Normal);
}

TEST(Statements, InitIncRunsAfterInitPost) {
  Post post("@init_inc\ny = x + 1\nendp\n@init_post\nx = 1\nendp\n");
  post.run->start();
  EXPECT_EQ(post.get("y"), integer(2));
}

TEST(Statements, HostArrays) {
  gppl::CompileOptions options;
  options.host_variables.push_back({"wire_table", gppl::Type::Numeric, false, {3, 4}});
  Post post("@t\nif change(wire_table<<3,2>>) then\n{nb, wire_table<<3,2>>}\nendif\nendp\n", options);
  const int index[] = {3, 2};
  post.run->assign_element(post.id("wire_table"), index, numeric(2.5));
  post.call("@t");
  EXPECT_EQ(post.text(), "2.5");
}

TEST(Statements, StrictModeRejectsUndeclared) {
  gppl::CompileOptions strict;
  strict.implicit_host_variables = false;
  EXPECT_EQ(compile_error("@t\nx = y\nendp\n", strict), "2:1: error 404");
  EXPECT_EQ(compile_error("@t\ngcode = y\nendp\n", strict), "2:9: error 383");
  strict.host_variables.push_back({"y", gppl::Type::Numeric, true, {}});
  EXPECT_EQ(compile_error("@t\ngcode = y\nendp\n", strict), "no error");
  EXPECT_EQ(compile_error("@t\ny = 1\nendp\n", strict), "2:1: error 402");
}

TEST(Statements, ImplicitVariablesWarn) {
  Post post("@t\nx = 1\nx = 2\nendp\n");
  ASSERT_EQ(gppl::warnings(*post.program).size(), 1u);
  EXPECT_EQ(gppl::warnings(*post.program)[0], "test.gpp:2:1: warning: 'x' is not declared: treated as a host variable");
}

}  // namespace
