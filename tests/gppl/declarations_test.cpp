// Declarations of names the system already has (docs/gppl-language.md, "Names"): a local copy
// shadows the system variable in its procedure only; a global of a compatible type is the system
// variable; a global of text for a number (or the reverse) and any redeclaration of PI, TRUE,
// FALSE stay error 418.
#include <gtest/gtest.h>

#include "tests/gppl/support.hpp"

namespace {

using namespace gppl_test;

TEST(Declarations, SystemNamesTable) {
  struct Case {
    const char* what;
    const char* source;
    const char* expected;
  } cases[] = {
      {"local copy", "@t\nlocal numeric xpos, ypos, zpos, apos\nxpos = 1\nendp\n", "no error"},
      {"procedure parameter", "@t(numeric xpos)\nendp\n", "no error"},
      {"global numeric of an integer", "@t\nglobal numeric gcode\nendp\n", "no error"},
      {"global of the same type", "@t\nglobal string part_name\nendp\n", "no error"},
      {"global logical of a numeric", "@t\nglobal logical flood_coolant\nendp\n", "no error"},
      {"global of a drill-cycle name the host declares", "@t\nglobal numeric f_drill\nendp\n", "no error"},
      {"global text of a number", "@t\nglobal string gcode\nendp\n", "2:15: error 418"},
      {"global number of a text", "@t\nglobal numeric  part_name\nendp\n", "2:17: error 418"},
      {"global scalar of an array", "@t\nglobal string chng_cond\nendp\n", "2:15: error 418"},
      {"local PI", "@t\nlocal numeric pi\nendp\n", "2:15: error 418"},
      {"global TRUE", "@t\nglobal logical TRUE\nendp\n", "2:16: error 418"},
      {"parameter FALSE", "@t(logical false)\nendp\n", "1:12: error 418"},
  };
  gppl::CompileOptions strict;
  strict.implicit_host_variables = false;
  strict.host_variables.push_back({"F_Drill", gppl::Type::Integer, true, {}});
  for (const auto& c : cases) EXPECT_EQ(compile_error(c.source, strict), c.expected) << c.what;
}

// The local copy is the procedure's own; elsewhere the name is the system variable.
TEST(Declarations, LocalShadowsInItsProcedureOnly) {
  Post post(
      "@copy\nlocal numeric xpos\nxpos = 7\n{nb, 'local ', xpos}\nendp\n"
      "@show\n{nb, 'system ', xpos}\nendp\n");
  post.set("xpos", numeric(2.5));
  post.call("@copy");
  post.call("@show");
  EXPECT_EQ(post.text(), "local 7\nsystem 2.5");
}

// A global declaration of a system name is the system variable: the host's value reaches it.
TEST(Declarations, GlobalOfSystemNameIsTheSystemVariable) {
  Post post("@t\nglobal numeric tool_number\n{nb, tool_number}\nendp\n");
  post.set("tool_number", integer(12));
  post.call("@t");
  EXPECT_EQ(post.text(), "12");
}

}  // namespace

namespace {

// What the engine needs for its "a misspelling?" hints: the post's procedures, whether a `call`
// names them, and the nearest of a list of names.
TEST(Procedures, NamedAndCalled) {
  auto program = gppl::compile_source("@line\n  call @helper\nendp\n@helper\nendp\n@rapid_mvoe\nendp\n", "p.gpp", {});
  auto procs = gppl::procedures(*program);
  ASSERT_EQ(procs.size(), 3u);
  EXPECT_EQ(procs[0].name, "@line");
  EXPECT_FALSE(procs[0].called);
  EXPECT_EQ(procs[1].name, "@helper");
  EXPECT_TRUE(procs[1].called);
  EXPECT_EQ(procs[2].position.line, 6);
}

TEST(Procedures, NearestName) {
  const std::string_view names[] = {"@rapid_mvoe", "@lien", "@usr_header", "@arc"};
  struct Case {
    const char* name;
    const char* nearest;
  } cases[] = {
      {"@rapid_move", "@rapid_mvoe"},  // a swapped pair is one edit
      {"@line", "@lien"},
      {"@LINE", "@lien"},              // case does not count
      {"@drill", ""},                  // nothing close
      {"@arc", ""},                    // the same name is no hint
      {"@ar", "@arc"},
  };
  for (const Case& c : cases) EXPECT_EQ(gppl::nearest_name(c.name, names), c.nearest) << c.name;
}

}  // namespace
