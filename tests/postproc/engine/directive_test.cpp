// Output directives as generated lines: what is one, what it says, and what is a malformed one.
#include <gtest/gtest.h>

#include "postproc/engine/directive.hpp"

namespace {

using postproc::Directive;
using postproc::parse_directive;
using Verb = Directive::Verb;

TEST(Directive, ReadsEverySpellingRealPostsUse) {
  struct Case {
    const char* line;
    Verb verb;
    const char* name;
  } cases[] = {
      {"!!open file=O1.SPF!!", Verb::Open, "O1.SPF"},
      {"!! open file = F_contour1.SPF !!", Verb::Open, "F_contour1.SPF"},
      {"  !!close file=O1.SPF!!  ", Verb::Close, "O1.SPF"},
      {"!! DELETE FILE = part 1.SPF !!", Verb::Delete, "part 1.SPF"},
      {"!!copy file=C:\\NC\\tmp.nc!!", Verb::Copy, "C:\\NC\\tmp.nc"},
      {"!!make dir=sub!!", Verb::MakeDir, "sub"},
      {"!!open file='quoted.nc'!!", Verb::Open, "quoted.nc"},
  };
  for (const auto& c : cases) {
    auto d = parse_directive(c.line);
    ASSERT_TRUE(d.has_value()) << c.line;
    EXPECT_EQ(d->verb, c.verb) << c.line;
    EXPECT_EQ(d->name, c.name) << c.line;
  }
}

TEST(Directive, OrdinaryLinesAreNotDirectives) {
  for (const char* line : {"", "G0 X1.", "(!! open file = X !!)", "!!", "!!!", "N10 !!open file=X!!", "M30 !!"})
    EXPECT_FALSE(parse_directive(line).has_value()) << line;
}

TEST(Directive, MalformedDirectivesSayWhatWasExpected) {
  struct Case {
    const char* line;
    const char* message;
  } cases[] = {
      {"!!rename file=X!!", "unknown output directive `!!rename file=X!!`: expected open, close, delete or copy file, or make dir"},
      {"!!open dir=X!!", "malformed output directive `!!open dir=X!!`: expected `open file = NAME`"},
      {"!!make file=X!!", "malformed output directive `!!make file=X!!`: expected `make dir = NAME`"},
      {"!!open file X!!", "malformed output directive `!!open file X!!`: expected `=` after `file`"},
      {"!!open file= !!", "malformed output directive `!!open file= !!`: the name is empty"},
  };
  for (const auto& c : cases) {
    try {
      parse_directive(c.line);
      ADD_FAILURE() << "no error for " << c.line;
    } catch (const postproc::DirectiveError& e) {
      EXPECT_STREQ(e.what(), c.message);
    }
  }
}

}  // namespace
