// Generate statements and the output line model: every vector of spec 6.8, plus format lookup
// (6.4), block-number rules (6.3), directives (6.7) and clear_change_after_gen (behaviour 2a).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "support.hpp"

using namespace gppl_test;

namespace {

// The FANUC @init_post formats that 6.8 assumes.
const std::string kInit = R"(@init_post
global string tool_diameter_f
numeric_def_f = '5.3'
integer_def_f = '5.0(p)'
gcode_f = '2.0(p)'
xpos_f = '5.3'
ypos_f = '5.3'
zpos_f = '5.3'
feed_f = '4.3(p)'
blknum_f = '5.0(p)'
blknum_letter = 'N'
blknum_exist = TRUE
blknum_gen = FALSE
endp
)";

std::string generate(const std::string& body) {
  Post post(kInit + "@t\n" + body + "\nendp\n");
  post.run->start();
  post.call("@t");
  return post.text();
}

struct GenerateCase {
  const char* name;
  const char* body;
  const char* expected;
};

class Generate : public testing::TestWithParam<GenerateCase> {};

TEST_P(Generate, Output) { EXPECT_EQ(generate(GetParam().body), GetParam().expected) << GetParam().body; }

INSTANTIATE_TEST_SUITE_P(
    Spec68, Generate,
    testing::Values(
        GenerateCase{"modal_g_suppressed", R"(blknum_gen = TRUE
blknum = 125
gcode = 1
gcode = 1
xpos = 123.45
ypos = -12.3
{nb, ['G'gcode], ' X'xpos, ' Y'ypos})",
                     "N125 X123.45 Y-12.3"},
        GenerateCase{"one_group_per_word", R"(blknum_gen = TRUE
blknum = 125
xpos = 123.45
ypos = -12.3
change(xpos) = FALSE
{nb, [' X'xpos], [' Y'ypos]})",
                     "N125 Y-12.3"},
        GenerateCase{"one_required_item_prints_group", R"(blknum_gen = TRUE
blknum = 125
xpos = 123.45
ypos = -12.3
change(xpos) = FALSE
{nb, [' X'xpos, ' Y'ypos]})",
                     "N125 X123.45 Y-12.3"},
        GenerateCase{"first_line_then_nl", R"(program_number = 5000
g_file_name = 'OUT'
{'%'}
{nl, 'O'program_number, ' (', g_file_name, ')'})",
                     "%\nO5000 (OUT)"},
        GenerateCase{"expression_item", R"(tool_number = 1
tool_offset = 6.35
{nb, '(G10 L12 P', (tool_number+50), ' R'tool_offset, ')'})",
                     "(G10 L12 P51 R6.35)"},
        GenerateCase{"user_format_variable", R"(tool_diameter_f = '5.3/1'
tool_number = 14
tool_diameter = 10.
{nb, '(*TOOL 'tool_number, ' - DIA 'tool_diameter, '*)'})",
                     "(*TOOL 14 - DIA 10.0*)"},
        GenerateCase{"inactive_message", R"(label = 5
message = 'x'
active(message) = FALSE
{nb, 'M98 P'label}
{[' ('message, ')']})",
                     "M98 P5"},
        GenerateCase{"active_message", R"(label = 1
message = 'F-PR1-T1'
{nb, 'M98 P'label}
{[' ('message, ')']})",
                     "M98 P1 (F-PR1-T1)"},
        GenerateCase{"blank_g_field", R"(gcode = 1
xpos = 1.
ypos = 2.
gcode = 1
xpos = 1.
ypos = 2.
zpos = 2.
{nb}
if change(gcode) then
  {'G'gcode}
else
  {' '}
endif
{[' X'xpos], [' Y'ypos], [' Z'zpos]})",
                     "  Z2."},
        GenerateCase{"col", "{nb,col(7) 'M30'}", "      M30"},
        GenerateCase{"skipline_one_shot", R"({nb, 'G91 '}
skipline = FALSE
{nb, 'X1.'}
{nb, 'Y', skipline})",
                     "G91 X1.\nY1"},
        GenerateCase{"gcode_space", R"(gcode_space = TRUE
blknum_gen = TRUE
blknum = 15
gcode = 1
gcode = 1
xpos = 35.
ypos = 7.14
{nb, ['G' gcode], ' X' xpos, ' Y' ypos})",
                     "N15    X35. Y7.14"},
        GenerateCase{"remove_blanks", R"(remove_blanks = TRUE
gcode = 1
xpos = 5.
{nb, 'G'gcode, ' X'xpos})",
                     "G1X5."},
        GenerateCase{"while_lines", R"(local integer i
i = 1
while i <= 5
  {nl, 'I=', i}
  i = i + 1
endw)",
                     "I=1\nI=2\nI=3\nI=4\nI=5"}));

INSTANTIATE_TEST_SUITE_P(
    LineModel, Generate,
    testing::Values(
        GenerateCase{"separator_not_doubled", R"(blknum_gen = TRUE
blknum = 5
{nb, ' X1'}
{nb, 'Y2'})",
                     "N5 X1\nN10 Y2"},
        GenerateCase{"blknum_delta_and_letter", R"(blknum_gen = TRUE
blknum = 100
blknum_delta = 2
blknum_letter = 'n'
{nb, 'A'}
{nb, 'B'}
{nl, 'C'})",
                     "n100 A\nn102 B\nC"},
        GenerateCase{"blknum_needs_exist", R"(blknum_gen = TRUE
blknum_exist = FALSE
{nb, 'A'})",
                     "A"},
        // The blank after the number stays when nothing follows (SolidCAM: `N210370 `).
        GenerateCase{"numbered_empty_block", R"(blknum_gen = TRUE
{nb}
{nb, 'X'})",
                     "N5 \nN10 X"},
        GenerateCase{"items_append_to_open_line", "{nb, 'G91 G28 Z0.'}\n{' M5'}\n{nb, 'M6'}", "G91 G28 Z0. M5\nM6"},
        GenerateCase{"nl_on_empty_line", "{nl}\n{nl, 'A'}", "\nA"},
        GenerateCase{"colrel", "{nb, 'A' colrel(3) 'B' colrel(0) 'C'}", "A   BC"},
        GenerateCase{"col_already_past", "{nb, 'ABCDEF' col(3) 'G'}", "ABCDEFG"},
        GenerateCase{"end_block_text", "end_block_text = ';'\n{nb, 'A B'}\n{nb, 'C'}", "A B;\nC;"},
        GenerateCase{"directive_untouched", R"(remove_blanks = TRUE
end_block_text = '*'
{nb, 'G 1'}
{nl, '!! open file = A.SPF !!'}
{nl, 'X 1'})",
                     "G1*\n!! open file = A.SPF !!\nX1*"},
        GenerateCase{"no_commas", "xpos = 1.5\n{nb 'X'xpos ' Y'(2*xpos) ' Z'xpos:'5.3(*10)'}", "X1.5 Y3. Z15."},
        GenerateCase{"format_variable_item", "delay = 2.6\n{nb, ' P'delay:integer_def_f, ' Q'delay}", " P3 Q2.6"},
        GenerateCase{"format_blanks_around_colon", "d1 = 2.5\n{nb, d1 :integer_def_f}", "3"},
        GenerateCase{"format_expression", "f = '4.1'\n{nb, 12.25:(f)}", "12.3"},
        GenerateCase{"name_f_is_dynamic", R"(xpos = 10.
{nb, 'X'xpos}
xpos_f = '5.3(*2)'
{nb, 'X'xpos}
xpos_f = ''
{nb, 'X'xpos})",
                     "X10.\nX20.\nX10."},
        GenerateCase{"local_name_f", "local string n_f\nlocal numeric n\nn_f = '3.1'\nn = 1.25\n{nb, n}", "1.3"},
        GenerateCase{"array_element_default_format", R"(global numeric a<<2>>
global string a_f
a_f = '5.3(*100)'
a<<1>> = 1.5
{nb, a<<1>>})",
                     "1.5"},
        // A group's one required variable and a printed variable: a global (resolved to its cell
        // when compiled), a local and an array element (looked up at run time) behave alike.
        GenerateCase{"modal_global_local_and_element", R"(global numeric g
global numeric a<<2>>
local numeric v
g = 1
v = 2
a<<2>> = 3
{nb, [' G'g], [' V'v], [' A'a<<2>>]}
g = 1
v = 2
a<<2>> = 3
{nb, 'N', [' G'g], [' V'v], [' A'a<<2>>]}
g = 4
v = 5
a<<2>> = 6
{nb, [' G'g], [' V'v], [' A'a<<2>>]}
g = 7
v = 8
a<<2>> = 9
active(g) = FALSE
active(v) = FALSE
active(a<<2>>) = FALSE
{nb, 'N', [' G'g], [' V'v], [' A'a<<2>>]})",
                     " G1. V2. A3.\nN\n G4. V5. A6.\nN"},
        GenerateCase{"logical_and_integer_defaults", "integer_def_f = '3.0'\n{nb, TRUE, ' ', 7}", "1. 7."},
        GenerateCase{"empty_default_falls_back", "numeric_def_f = ''\n{nb, 1.23456}", "1.235"},
        GenerateCase{"string_ignores_format", "s = 'abc'\n{nb, s:'5.3'}", "abc"},
        GenerateCase{"function_item", "message = 'job'\n{nb, upper(message), [' ('upper(message)')']}",
                     "JOB (JOB)"},
        GenerateCase{"function_group_inactive", "message = 'job'\nactive(message) = FALSE\n{nb, 'A' [' ('upper(message)')']}",
                     "A"},
        GenerateCase{"literal_group_never_required", "{nb, 'A' [' B'] ['C' 5]}", "A"},
        GenerateCase{"clear_change_after_gen", R"(clear_change_after_gen = 1
xpos = 5.
{nb, 'A' [' X'xpos]}
{nb, 'B' [' X'xpos]}
xpos = 5.
{nb, 'C' [' X'xpos]}
xpos = 6.
{nb, 'D' [' X'xpos]})",
                     "A X5.\nB\nC\nD X6."},
        GenerateCase{"generation_keeps_change", "xpos = 5.\n{nb, 'A' [' X'xpos]}\n{nb, 'B' [' X'xpos]}",
                     "A X5.\nB X5."},
        GenerateCase{"tabs_and_case", "\tGCODE = 3\n\t{NB, 'G'Gcode}", "G3"}));

// The items generate() writes itself (a global number whose format is parsed already, and a group
// of a text then a value) against the same items where only render() can write them: an
// expression, a local, a string, a format text changed between two lines, a separator owed.
INSTANTIATE_TEST_SUITE_P(
    WrittenInPlace, Generate,
    testing::Values(
        GenerateCase{"pair_and_expression_pair", R"(xpos = 1.5
{nb, [' X'xpos], [' X'(xpos)], [' X', xpos]})",
                     " X1.5 X1.5 X1.5"},
        GenerateCase{"pair_after_block_number", R"(blknum_gen = TRUE
blknum = 7
xpos = -2.
{nb, ['X'xpos]}
{nb, [' X'xpos]})",
                     "N7 X-2.\nN12 X-2."},
        GenerateCase{"value_after_block_number_gets_the_blank", R"(blknum_gen = TRUE
blknum = 7
blknum_delta = 3
xpos = 3.
{nb, xpos}
{nb, [xpos]}
{nb, (xpos)})",
                     "N7 3.\nN10 3.\nN13 3."},
        GenerateCase{"name_format_changed_between_lines", R"(xpos = 1.23456
{nb, ['X'xpos]}
xpos_f = '5.1'
{nb, ['X'xpos]}
xpos_f = ''
{nb, ['X'xpos]}
xpos_f = '5.3'
{nb, ['X'xpos]})",
                     "X1.235\nX1.2\nX1.235\nX1.235"},
        GenerateCase{"default_format_changed_between_lines", R"(global numeric r
global integer k
r = 2.5
k = 4
{nb, ['R'r], ' K'k}
numeric_def_f = '5.0(p)'
integer_def_f = '3.2'
{nb, ['R'r], ' K'k}
numeric_def_f = ''
integer_def_f = ''
{nb, ['R'r], ' K'k})",
                     "R2.5 K4\nR3 K4.\nR2.5 K4"},
        GenerateCase{"value_kinds_in_pairs", R"(global numeric r
global integer k
global logical b
global string s
local numeric here
r = 0.25
k = -3
b = TRUE
s = 'txt'
here = 9.5
{nb, ['R'r], ['K'k], ['B'b], ['S's], ['H'here]})",
                     "R0.25K-3B1StxtH9.5"},
        GenerateCase{"pair_in_constant_format", "xpos = 1.\n{nb, ['X'xpos:'5.3(p)'], [' Y'xpos:'2.2']}", "X1 Y1."},
        GenerateCase{"pair_not_required", R"(xpos = 1.
ypos = 2.
change(xpos) = FALSE
{nb, 'G1', [' X'xpos], [' Y'ypos]})",
                     "G1 Y2."},
        GenerateCase{"pair_clears_change", R"(clear_change_after_gen = 1
xpos = 4.
{nb, 'A', [' X'xpos]}
{nb, 'B', [' X'xpos], [' X'(xpos)]})",
                     "A X4.\nB"},
        GenerateCase{"pair_opens_the_line", R"(xpos = 4.
{[' X'xpos]}
{nl, ['X'xpos], ' ', [xpos]})",
                     " X4.\nX4. 4."}));

TEST(Generate, BlockNumberTooBig) {
  EXPECT_EQ(run_error("@t\nblknum_gen = TRUE\nblknum = 32005\n{nb, 'X'}\nendp\n"), "4:2: error 452");
}

TEST(Generate, FormatErrorsAtRunTime) {
  EXPECT_EQ(run_error("@t\nx = 1.\n{nb, x:'5'}\nendp\n"), "3:6: error 421");
  EXPECT_EQ(run_error("@t\nglobal string x_f\nx = 1.\nx_f = '5.'\n{nb, x}\nendp\n"), "5:6: error 422");
  EXPECT_EQ(compile_error("@t\nx = 1.\n{nb, x:5}\nendp\n"), "3:8: error 390");  // a number is not a format
}

TEST(Generate, LineOrigins) {
  Post post("@a\n{nb, 'A'}\ncall @b\nendp\n@b\n{nb, 'B'}\n{' C'}\nendp\n");
  post.call("@a");
  post.run->finish();
  EXPECT_EQ(post.out.lines, (std::vector<std::string>{"A", "B C"}));
  EXPECT_EQ(post.out.procedures, (std::vector<std::string>{"@a", "@b"}));
}

// nb numbers the block and steps blknum without going through a Value: blknum's value and change
// flag must end up as the assignment `blknum = blknum + blknum_delta` leaves them, whether blknum
// was assigned before or not, its flag set or cleared, the step zero or not, and on a second nb.
TEST(Generate, BlockNumberStepMatchesAnAssignment) {
  const std::string report = "{nl, (change(blknum)):'1.0(p)', ' ', blknum}";
  for (const char* delta : {"0", "10", "-3"}) {
    for (const char* before : {"", "blknum = 10\n", "blknum = 10\nchange(blknum) = FALSE\n", "change(blknum) = TRUE\n"}) {
      const std::string setup = std::string("blknum_gen = TRUE\nblknum_delta = ") + delta + "\n" + before;
      const std::string step = "blknum = blknum + blknum_delta\n";
      const std::string by_nb = generate(setup + "{nb}\n" + report + "\n{nb}\n" + report);
      const std::string by_assignment = generate(setup + step + report + "\n" + step + report);
      // by_nb has the two numbered blocks in front of each report line.
      std::vector<std::string> lines;
      for (std::size_t at = 0, end; at <= by_nb.size(); at = end + 1) {
        end = std::min(by_nb.find('\n', at), by_nb.size());
        lines.push_back(by_nb.substr(at, end - at));
      }
      ASSERT_EQ(lines.size(), 4u) << by_nb;
      EXPECT_EQ(lines[1] + "\n" + lines[3], by_assignment) << "delta " << delta << ", before: " << before;
    }
  }
}

}  // namespace
