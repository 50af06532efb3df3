// Interpreter::unread_type: the variables a host may leave unassigned because nothing in the post
// reads them. Any mention counts as a read (an expression, a condition, change/active, an item, the
// name_f format of a printed variable, an assignment); so do the generator's own variables.
#include <gtest/gtest.h>

#include <optional>
#include <sstream>

#include "support.hpp"

using namespace gppl_test;

namespace {

struct UnreadCase {
  const char* what;
  const char* source;
  const char* variable;
  std::optional<gppl::Type> expected;
};

class UnreadType : public testing::TestWithParam<UnreadCase> {};

TEST_P(UnreadType, OnlyWhatNothingNames) {
  const UnreadCase& c = GetParam();
  Post post(c.source);
  EXPECT_EQ(post.run->unread_type(post.id(c.variable)), c.expected) << c.what;
}

constexpr auto N = gppl::Type::Numeric;
constexpr auto S = gppl::Type::String;
constexpr auto I = gppl::Type::Integer;

INSTANTIATE_TEST_SUITE_P(
    Table, UnreadType,
    testing::Values(
        UnreadCase{"a numeric system variable nothing names", "@t\nendp\n", "xcenter", N},
        UnreadCase{"a string system variable nothing names", "@t\nendp\n", "prev_command", S},
        UnreadCase{"a global the post declares and never uses", "@init_post\n  global integer g\nendp\n@t\nendp\n", "g", I},
        UnreadCase{"printed by a generate item", "@t\n  {' X'xcenter}\nendp\n", "xcenter", std::nullopt},
        UnreadCase{"in a modal group", "@t\n  {nb, [' X'xcenter]}\nendp\n", "xcenter", std::nullopt},
        UnreadCase{"the name_f of a printed variable", "@t\n  {' X'xpos}\nendp\n", "xpos_f", std::nullopt},
        UnreadCase{"tested by a condition", "@t\n  if xcenter gt 0\n  endif\nendp\n", "xcenter", std::nullopt},
        UnreadCase{"its change attribute", "@t\n  if change(xcenter)\n  endif\nendp\n", "xcenter", std::nullopt},
        UnreadCase{"its active attribute", "@t\n  if active(xcenter)\n  endif\nendp\n", "xcenter", std::nullopt},
        UnreadCase{"in an expression", "@t\n  local numeric y\n  y = xcenter * 2\nendp\n", "xcenter", std::nullopt},
        UnreadCase{"a function argument", "@t\n  local numeric y\n  y = abs(xcenter)\nendp\n", "xcenter", std::nullopt},
        UnreadCase{"assigned by the post", "@t\n  xcenter = 5\nendp\n", "xcenter", std::nullopt},
        UnreadCase{"assigned in @init_post", "@init_post\n  numeric_def_f = '5.3'\nendp\n", "numeric_def_f",
                   std::nullopt},
        UnreadCase{"block numbering reads blknum", "@t\nendp\n", "blknum", std::nullopt},
        UnreadCase{"the default formats are the generator's", "@t\nendp\n", "integer_def_f", std::nullopt},
        UnreadCase{"gcode_space pads groups holding gcode", "@t\nendp\n", "gcode", std::nullopt},
        UnreadCase{"the line end text", "@t\nendp\n", "end_block_text", std::nullopt}),
    [](const testing::TestParamInfo<UnreadCase>& info) { return "case" + std::to_string(info.index); });

// A trace dumps what the host assigned: with a trace stream every variable counts as read.
TEST(UnreadTypeTrace, NothingIsUnreadWhileTracing) {
  Post post("@t\nendp\n");
  ASSERT_EQ(post.run->unread_type(post.id("xcenter")), gppl::Type::Numeric);
  std::ostringstream trace;
  post.run->set_trace_stream(&trace);
  EXPECT_EQ(post.run->unread_type(post.id("xcenter")), std::nullopt);
}

}  // namespace
