// Syntax real posts use beyond the manual (docs/gppl-language.md, "Beyond the manual"): elseif
// chains, generate lists with stray commas, `+` inside generate items, and keywords in any case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "support.hpp"

using namespace gppl_test;

namespace {

// --- elseif ---------------------------------------------------------------------------------

constexpr const char* kChain = R"(@t
if x eq 1
  {nb 'one'}
elseif x eq 2 then
  {nb 'two'}
ElseIf x eq 3
  {nb 'three'}
ELSEIF x eq 4 THEN
else
  {nb 'other'}
endif
{nb 'end'}
endp
)";

struct ChainCase {
  int x;
  const char* output;
};

class ElseIf : public testing::TestWithParam<ChainCase> {};

TEST_P(ElseIf, TakesTheFirstTrueBranch) {
  Post post(kChain);
  post.set("x", integer(GetParam().x));
  post.call("@t");
  EXPECT_EQ(post.text(), GetParam().output) << "x = " << GetParam().x;
}

INSTANTIATE_TEST_SUITE_P(Chain, ElseIf,
                         testing::Values(ChainCase{1, "one\nend"}, ChainCase{2, "two\nend"}, ChainCase{3, "three\nend"},
                                         ChainCase{4, "end"}, ChainCase{5, "other\nend"}));

TEST(ElseIf, WithoutElseAndNested) {
  Post post(R"(@t
if a
  if b
    {nb 'ab'}
  elseif c
    {nb 'ac'}
  endif
elseif b
  {nb 'b'}
  while i < 2
    if i eq 0
      {nb 'i0'}
    elseif i eq 1
      {nb 'i1'}
    endif
    i = i + 1
  endw
endif
endp
)");
  auto run = [&](int a, int b, int c) {
    post.set("a", logical(a)), post.set("b", logical(b)), post.set("c", logical(c)), post.set("i", integer(0));
    post.call("@t");
  };
  run(1, 1, 0);
  run(1, 0, 1);
  run(1, 0, 0);
  run(0, 1, 0);
  run(0, 0, 1);
  EXPECT_EQ(post.text(), "ab\nac\nb\ni0\ni1");
}

// Eight nested IFs are the limit; ELSEIF branches stay at their IF's depth.
TEST(ElseIf, DoesNotCountAsNesting) {
  std::string source = "@t\n";
  for (int i = 0; i < 8; ++i) source += "if a\n";
  for (int i = 0; i < 30; ++i) source += "elseif b\n";
  for (int i = 0; i < 8; ++i) source += "elseif c\nendif\n";
  source += "endp\n";
  EXPECT_EQ(compile_error(source), "no error");
}

struct BrokenChain {
  const char* what;
  const char* source;
  const char* expected;
};

class ElseIfErrors : public testing::TestWithParam<BrokenChain> {};

TEST_P(ElseIfErrors, NumberAndPosition) { EXPECT_EQ(compile_error(GetParam().source), GetParam().expected) << GetParam().what; }

INSTANTIATE_TEST_SUITE_P(
    Catalogue, ElseIfErrors,
    testing::Values(BrokenChain{"without if", "@t\n  elseif a\nendp\n", "2:3: error 385"},
                    BrokenChain{"inside a while of the if", "@t\nif a\nwhile b\nelseif c\nendw\nendif\nendp\n",
                                "4:1: error 385"},
                    BrokenChain{"after else", "@t\nif a\nelse\nelseif b\nendif\nendp\n", "4:1: error 392"},
                    BrokenChain{"no condition", "@t\nif a\nelseif\nendif\nendp\n", "3:7: error 392"},
                    BrokenChain{"junk after then", "@t\nif a\nelseif b then c\nendif\nendp\n", "3:15: error 392"},
                    BrokenChain{"endif missing", "@t\nif a\nelseif b\nendp\n", "4:1: error 194"},
                    BrokenChain{"nine nested ifs through elseif",
                                "@t\nif a\nif a\nif a\nif a\nif a\nif a\nif a\nif a\nelseif b\n  if a\n  endif\n"
                                "endif\nendif\nendif\nendif\nendif\nendif\nendif\nendif\nendp\n",
                                "11:3: error 384"}));

// --- generate lists ---------------------------------------------------------------------------

struct GenerateCase {
  const char* statement;
  const char* output;
};

class RealGenerate : public testing::TestWithParam<GenerateCase> {};

TEST_P(RealGenerate, Output) {
  Post post(std::string("@t\nlocal string s\ns = 'a=1'\nx = 2.5\n") + GetParam().statement + "\nendp\n");
  post.call("@t");
  EXPECT_EQ(post.text(), GetParam().output) << GetParam().statement;
}

INSTANTIATE_TEST_SUITE_P(
    Forms, RealGenerate,
    testing::Values(GenerateCase{"{,nb 'x'}", "x"}, GenerateCase{"{nb,,'a',,'b',}", "ab"},
                    GenerateCase{"{nb, , ,'a' ,, x}", "a2.5"}, GenerateCase{"{,}", ""},
                    GenerateCase{"{nb [,' X'x,,]}", " X2.5"},
                    GenerateCase{"{nb, 'CYCLE832(' + s + ',1)'}", "CYCLE832(a=1,1)"},
                    GenerateCase{"{nb 'T' + s 'U'}", "Ta=1U"},
                    GenerateCase{"{nb [' X' + tostr(x:'5.2')]}", " X2.5"},
                    GenerateCase{"{nb, x + 1}", "3.5"},
                    GenerateCase{"{nb, x + 1 :'5.2z'}", "3.50"},
                    GenerateCase{"s = s + 'b' + ';'\n{nb s}", "a=1b;"}));

TEST(RealGenerate, Errors) {
  EXPECT_EQ(compile_error("@t\n{nb 'a' + }\nendp\n"), "2:11: error 390");
  EXPECT_EQ(compile_error("@t\n{nb ['a' + ]}\nendp\n"), "2:12: error 390");
  EXPECT_EQ(run_error("@t\n{nb 'a' + 1}\nendp\n"), "2:9: error 394");
}

// A modal group whose item is a concatenation prints when a variable in it changed.
TEST(RealGenerate, ConcatenationInModalGroup) {
  Post post("@t\n{nb 'L' [' X' + tostr(x:'5.1')]}\nendp\n");
  post.set("x", numeric(1.));
  post.call("@t");
  post.set("x", numeric(1.));
  post.call("@t");
  EXPECT_EQ(post.text(), "L X1.\nL");
}

// --- keywords in any case -----------------------------------------------------------------------

// The same post in three spellings posts the same lines.
constexpr const char* kMixedCase = R"(@init_post
global integer g
global string s
endp
@t
local numeric n<<2>>
n<<1>> = 1.5
g = 0
while g lt 3
  g = g + 1
  if g eq 2 then
    break
  endif
endw
if not (g ne 2) and (1 le 2 or 1 ge 2) and 1 gt 0
  {nb 'G' g, col(8), 'N' n<<1>>, colrel(1), 'x'}
elseif g == 3
  {nl 'never'}
else
  {nl 'never'}
endif
change(g) = false
active(g) = true
if change(g) eq FALSE and active(g) = TRUE
  {nb 'flags'}
endif
s = upper('abc') + trim('d ')
print 'print ' s
input 'ask' s
call @u
trace "@u":0
endp
@u
{nb s}
return
endp
)";

std::string spelled(const std::string& source, bool upper) {
  // Upper-case every keyword, operator word and function name; mixed case turns `if` into `If`.
  const char* words[] = {"global", "integer", "string", "numeric", "local", "while", "endw", "if", "then", "break",
                         "endif", "elseif", "else", "not", "and", "or", "ne", "le", "ge", "gt", "lt", "eq", "nb",
                         "nl", "col", "colrel", "change", "active", "false", "true", "upper", "trim", "print",
                         "input", "call", "trace", "return", "endp"};
  std::string out = source;
  for (const char* w : words) {
    const std::string word = w;
    std::string replacement = word;
    for (std::size_t i = 0; i < replacement.size(); ++i)
      if (upper || i == 0) replacement[i] = char(replacement[i] - 'a' + 'A');
    auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '@'; };
    for (std::size_t at = out.find(word); at != std::string::npos; at = out.find(word, at + word.size())) {
      const bool starts = at == 0 || !is_word(out[at - 1]);
      const bool ends = at + word.size() >= out.size() || !is_word(out[at + word.size()]);
      const bool quoted = out.rfind('\'', at) != std::string::npos &&
                          std::count(out.begin() + std::ptrdiff_t(out.rfind('\n', at) + 1), out.begin() + std::ptrdiff_t(at), '\'') % 2 == 1;
      if (starts && ends && !quoted) out.replace(at, word.size(), replacement);
    }
  }
  return out;
}

TEST(KeywordCase, AnySpellingPostsTheSameLines) {
  std::string outputs[3];
  const std::string sources[3] = {kMixedCase, spelled(kMixedCase, true), spelled(kMixedCase, false)};
  ASSERT_NE(sources[1].find("ELSEIF g == 3"), std::string::npos);
  ASSERT_NE(sources[2].find("Input 'ask' s"), std::string::npos);
  for (int i = 0; i < 3; ++i) {
    Post post(sources[i]);
    post.run->start();
    post.call("@t");
    outputs[i] = post.text();
  }
  EXPECT_EQ(outputs[0], "G2     N1.5 x\nflags\nABCd");
  EXPECT_EQ(outputs[1], outputs[0]);
  EXPECT_EQ(outputs[2], outputs[0]);
}

// The words of the file level and the stop statements, in upper and mixed case.
TEST(KeywordCase, FileLevelAndStopWords) {
  const auto dir = std::filesystem::temp_directory_path() / "gppl-keyword-case";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "sub.gpp") << "PROC @Sub\n  Local Logical done\n  done = TRUE\n  {NB 'sub'}\n  RETURN\nENDP\n";
  std::ofstream(dir / "main.gpp") << "INCLUDE 'sub.gpp'\n"
                                     "@T\n  CALL @SUB\n  IF stop EQ 1 THEN\n    EXIT\n  ELSEIF stop EQ 2\n    Abort\n"
                                     "  ENDIF\n  {Nb 'rest'}\nEndP\n";
  auto program = gppl::compile_file((dir / "main.gpp").string(), {});
  CapturedLines out;
  gppl::Interpreter run(program, out);
  const auto stop = run.add_variable("stop");
  const auto t = *run.find_procedure("@t");
  EXPECT_EQ(run.call(t), gppl::RunResult::Normal);
  run.assign(stop, integer(1));
  EXPECT_EQ(run.call(t), gppl::RunResult::Exit);
  run.assign(stop, integer(2));
  EXPECT_EQ(run.call(t), gppl::RunResult::Abort);
  run.finish();
  EXPECT_EQ(out.lines, (std::vector<std::string>{"sub", "rest", "sub", "sub"}));
  std::filesystem::remove_all(dir);
}

// A variable may still be called input or print: such a line is an assignment.
TEST(KeywordCase, InputAndPrintAsVariableNames) {
  Post post("@t\nprint = 2\ninput = print + 1\n{nb input}\nendp\n");
  post.call("@t");
  EXPECT_EQ(post.text(), "3");
}

}  // namespace
