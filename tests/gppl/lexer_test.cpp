// Lexical structure (spec 2): the vectors of 2.7 observed through what the statements do, plus
// real-post text (CRLF, 8-bit bytes, ;#region markers, DOS end-of-file mark).
#include <gtest/gtest.h>

#include "support.hpp"

using namespace gppl_test;

namespace {

std::string output(const std::string& body) {
  Post post("@t\n" + body + "\nendp\n");
  post.call("@t");
  return post.text();
}

struct LexCase {
  const char* body;
  const char* expected;
};

class Lexer : public testing::TestWithParam<LexCase> {};

TEST_P(Lexer, Vector) { EXPECT_EQ(output(GetParam().body), GetParam().expected) << GetParam().body; }

INSTANTIATE_TEST_SUITE_P(
    Spec27, Lexer,
    testing::Values(
        LexCase{"gcode = 1\n{nb 'G'gcode}", "G1"},
        LexCase{"tool_number = 1\nTOOL_message = 'x'\n{nb, 'T'tool_number:'2/2.0(p)'' M06 (DIA ',TOOL_message ')'}",
                "T01 M06 (DIA x)"},
        LexCase{"f_name = 'P'\n{nb, f_name'_''.EIA!!'}", "P_.EIA!!"},
        LexCase{"global string job_def<<2,3>>\njob_count = 3\njob_name = 'j'\njob_def<<1,job_count>> = job_name\n"
                "{nb, job_def<<1,3>>}",
                "j"},
        LexCase{"job_type = 'pocket'\nx = TRUE\nif job_type <> '3-d model' and x\n{nb, 'yes'}\nendif", "yes"},
        LexCase{"gcode = 1 ; comment; 'x'\n{nb, gcode}", "1"},
        LexCase{"{nb, strlen('abc\\x04xyz'), ' ', strlen('abc\\txyz'), ' ', instr('abc\\txyz', '\\t')}", "7 7 4"},
        LexCase{"{nb, (\"abcdefg\" = 'abcdefg'), ('AbcdefG' = 'abcdefg')}", "10"},
        LexCase{"{nb, strlen(''), ' ', strlen('SUBROUTINES: ')}", "0 13"},
        LexCase{"{nb, 'a\\\\b', \"it's\", '\\x27'}", "a\\bit's'"},
        LexCase{"{nb, 'c:\\\\name.ext'}", "c:\\name.ext"},
        LexCase{"x = 1\ny = -123\nz = -99999\n{nb, x, y, z}", "1-123-99999"},
        LexCase{"{nb, 1. ' ' (-123.0):'5.1' ' ' .123 ' ' (-0.23)}", "1. -123. 0.123 -0.23"},
        LexCase{"{nb, 1.2E2, ' ', 1.2E-2, ' ', 1.2e+1}", "120. 0.012 12."},
        LexCase{"{nb, '[x]' 'C['cpos:'3.1' '+#100]'}", "[x]C[0.+#100]"},
        LexCase{"IF 1 = 1 THEN\nGLOBAL INTEGER Big\nBIG = 2\nENDIF\n{NB, big}", "2"},
        LexCase{"global integer a<<3>>\ni = 2\na<<i>>=1\n{nb, a<<2>>, a<<1>>}", "10"}));

TEST(Lexer, Errors) {
  EXPECT_EQ(compile_error("@t\nx = 'no, no, no!\"\nendp\n"), "2:18: error 389");
  EXPECT_EQ(compile_error("@t\n{nb, \"abc'}\nendp\n"), "2:12: error 390");
}

TEST(Lexer, UnknownEscapeKeptWithWarning) {
  Post post("@t\n{nb, 'a\\qb'}\nendp\n");
  post.call("@t");
  EXPECT_EQ(post.text(), "a\\qb");
  ASSERT_EQ(gppl::warnings(*post.program).size(), 1u);
  EXPECT_EQ(gppl::warnings(*post.program)[0], "test.gpp:2:6: warning: unknown escape '\\q' kept as written");
}

TEST(Lexer, CrLfAnd8BitText) {
  // Windows-1252 text, CRLF line ends, a DOS end-of-file mark: bytes pass through unchanged.
  Post post("; caf\xe9\r\n@t\r\n  {nb, 'Caf\xe9 \xb0'}\r\nendp\r\n\x1a");
  post.call("@t");
  EXPECT_EQ(post.text(), "Caf\xe9 \xb0");
}

TEST(Lexer, RegionMarkersAreComments) {
  EXPECT_EQ(compile_error(";#region procs\n@t\n;#region body\nx = 1\n;#endregion\nendp\n;#endregion\n"), "no error");
}

TEST(Lexer, NoPhantomLastLine) {
  EXPECT_EQ(compile_error("@t\nendp"), "no error");
  EXPECT_EQ(compile_error("@t\nendp\n\n"), "no error");
}

}  // namespace
