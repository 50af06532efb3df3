// `input` and `print` (docs/gppl-language.md, "Beyond the manual"): parsing and its errors, the
// run log, answers converted to the variable's type, and the checks of check_answers.
#include <gtest/gtest.h>

#include <sstream>

#include "support.hpp"

using namespace gppl_test;

namespace {

struct Logged {
  explicit Logged(const std::string& source, std::vector<gppl::Answer> answers = {}) : post(source) {
    post.run->set_log_stream(&log);
    post.run->set_answers(answers);
    post.run->start();
    post.call("@t");
  }
  Post post;
  std::ostringstream log;
};

struct DialogCase {
  const char* body;
  std::vector<gppl::Answer> answers;
  const char* log;
};

class Dialog : public testing::TestWithParam<DialogCase> {};

TEST_P(Dialog, LogsAndAssigns) {
  const std::string source = std::string(R"(@init_post
global integer tool
global numeric feed
global logical coolant
global string name
global integer slots<<3>>
tool = 7
feed = 250.
name = 'P1'
endp
@t
)") + GetParam().body + "\nendp\n";
  Logged run(source, GetParam().answers);
  EXPECT_EQ(run.log.str(), GetParam().log) << GetParam().body;
  EXPECT_TRUE(run.post.out.lines.empty());  // never into the NC output
}

INSTANTIATE_TEST_SUITE_P(
    Statements, Dialog,
    testing::Values(
        DialogCase{"input 'Tool number?' tool", {}, "test.gpp:12:1: input 'Tool number?': tool = 7 (no answer: value kept)\n"},
        DialogCase{"Input \"Tool number?\", tool", {{"TOOL", "12", "--answer TOOL=12"}},
                   "test.gpp:12:1: input 'Tool number?': tool = 12 (answer from --answer TOOL=12)\n"},
        DialogCase{"  INPUT 'Feed ' + tostr(feed:'5.0(p)') + '?' feed", {{"feed", " 1.5e2 ", "a.txt:3"}},
                   "test.gpp:12:3: input 'Feed 250?': feed = 150 (answer from a.txt:3)\n"},
        DialogCase{"input 'Coolant' coolant", {{"coolant", "TRUE", "x"}},
                   "test.gpp:12:1: input 'Coolant': coolant = TRUE (answer from x)\n"},
        DialogCase{"input 'Name', name", {{"name", "a b", "x"}}, "test.gpp:12:1: input 'Name': name = 'a b' (answer from x)\n"},
        DialogCase{"input 'Slot' slots<<2>>", {{"slots", "4", "x"}},
                   "test.gpp:12:1: input 'Slot': slots = 4 (answer from x)\n"},
        DialogCase{"input 'Twice' tool\ninput 'Twice' tool", {{"tool", "1", "a"}, {"tool", "2", "b"}},
                   "test.gpp:12:1: input 'Twice': tool = 2 (answer from b)\n"
                   "test.gpp:13:1: input 'Twice': tool = 2 (answer from b)\n"},
        DialogCase{"print 'tool ' tool ', feed ', feed", {}, "test.gpp:12:1: print: tool 7, feed 250\n"},
        DialogCase{"Print 'text'", {}, "test.gpp:12:1: print: text\n"},
        DialogCase{"PRINT 'x=', 1 + 2, ' ', feed:'5.1z', ,", {}, "test.gpp:12:1: print: x=3 250.0\n"},
        DialogCase{"print", {}, "test.gpp:12:1: print: \n"}));

TEST(Dialog, AnswerSetsChange) {
  Post post("@init_post\nglobal integer t\nt = 3\nendp\n@t\ninput 't' t\n{nb [' T't]}\nendp\n");
  const gppl::Answer answer[] = {{"t", "3", "x"}};
  post.run->set_answers(answer);
  post.run->start();
  post.call("@t");  // the same value: not a change (assignment rules)
  EXPECT_EQ(post.text(), "");  // one empty block
  const gppl::Answer other[] = {{"t", "4", "x"}};
  post.run->set_answers(other);
  post.call("@t");
  EXPECT_EQ(post.text(), "\n T4");
}

// An implicit host variable takes a number when the answer reads as one, else the text.
TEST(Dialog, UntypedTarget) {
  const std::vector<gppl::Answer> answers = {{"u", "2.5", "x"}, {"v", "abc", "y"}};
  Logged run("@t\ninput 'u' u\ninput 'v' v\nendp\n", answers);
  EXPECT_EQ(run.post.get("u"), numeric(2.5));
  EXPECT_EQ(run.post.get("v"), string("abc"));
}

TEST(Dialog, WithoutLogNothingIsWritten) {
  Post post("@t\nprint 'a' 1\ninput 'b' x\nendp\n");
  post.call("@t");
  EXPECT_EQ(post.text(), "");
}

struct BadAnswer {
  const char* declaration;
  const char* value;
  const char* expected;  // the error's what()
};

class BadAnswers : public testing::TestWithParam<BadAnswer> {};

TEST_P(BadAnswers, NameTheSourceAndTheType) {
  const std::string source = std::string("@t\n") + GetParam().declaration + "\n  input 'q' v\nendp\n";
  auto program = gppl::compile_source(source, "p.gpp", {});
  const gppl::Answer answers[] = {{"v", GetParam().value, std::string("--answer v=") + GetParam().value}};
  try {
    gppl::check_answers(*program, answers);
    FAIL() << "no error";
  } catch (const gppl::Errors& e) {
    ASSERT_EQ(e.all().size(), 1u);
    EXPECT_EQ(std::string(e.all()[0].what()), GetParam().expected);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Types, BadAnswers,
    testing::Values(
        BadAnswer{"local integer v", "abc",
                  "p.gpp:3:3: error 386: Variable is not numeric: --answer v=abc: v needs an integer, not 'abc'"},
        BadAnswer{"local integer v", "2.5",
                  "p.gpp:3:3: error 386: Variable is not numeric: --answer v=2.5: v needs an integer, not '2.5'"},
        BadAnswer{"local integer v", "1e12",
                  "p.gpp:3:3: error 410: Val: number out of range: --answer v=1e12: v needs an integer within "
                  "±999999999, not '1e12'"},
        BadAnswer{"local numeric v", "12,5",
                  "p.gpp:3:3: error 386: Variable is not numeric: --answer v=12,5: v needs a number, not '12,5'"},
        BadAnswer{"local logical v", "yes",
                  "p.gpp:3:3: error 420: Numeric expression is not of logical type: --answer v=yes: v needs a "
                  "logical (0, 1, TRUE or FALSE), not 'yes'"}));

TEST(Dialog, UnusedAnswersWarnOnce) {
  auto program = gppl::compile_source("@t\ninput 'q' v\nendp\n", "p.gpp", {});
  const gppl::Answer answers[] = {{"V", "1", "a"}, {"w", "1", "b"}, {"w", "2", "c"}};
  const auto warnings = gppl::check_answers(*program, answers);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "c: warning: no input statement reads 'w'");
}

struct BrokenDialog {
  const char* what;
  const char* source;
  const char* expected;
};

class DialogErrors : public testing::TestWithParam<BrokenDialog> {};

TEST_P(DialogErrors, NumberAndPosition) { EXPECT_EQ(compile_error(GetParam().source), GetParam().expected) << GetParam().what; }

INSTANTIATE_TEST_SUITE_P(
    Catalogue, DialogErrors,
    testing::Values(BrokenDialog{"input without prompt", "@t\ninput\nendp\n", "2:6: error 385"},
                    BrokenDialog{"input without variable", "@t\ninput 'x'\nendp\n", "2:10: error 385"},
                    BrokenDialog{"input into a number", "@t\ninput 'x', 5\nendp\n", "2:12: error 385"},
                    BrokenDialog{"input with junk", "@t\ninput 'x' a b\nendp\n", "2:13: error 385"},
                    BrokenDialog{"input into a read-only variable", "@t\ninput 'x' PI\nendp\n", "2:11: error 402"},
                    BrokenDialog{"input into start_line", "@t\ninput 'x' start_line\nendp\n", "2:11: error 389"},
                    BrokenDialog{"prompt is start_line", "@t\ninput start_line x\nendp\n", "2:7: error 383"},
                    BrokenDialog{"print start_line", "@t\nprint 'a' end_line\nendp\n", "2:11: error 383"},
                    BrokenDialog{"print unterminated", "@t\nprint 'a\nendp\n", "2:9: error 385"},
                    BrokenDialog{"print with a bad format", "@t\nprint 1:\nendp\n", "2:9: error 385"},
                    BrokenDialog{"print unknown name (strict)", "@t\nprint tool_nr\nendp\n", "no error"}));

TEST(Dialog, RunTimeErrorsHaveThePosition) {
  EXPECT_EQ(run_error("@t\nprint 'a' + 1\nendp\n"), "2:11: error 394");
  EXPECT_EQ(run_error("@t\nlocal integer a<<2>>\ninput 'x' a<<3>>\nendp\n"), "3:1: error 387");
}

}  // namespace
