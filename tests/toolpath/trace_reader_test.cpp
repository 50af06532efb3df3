// The `.trace` reader: both layouts, every value form, and one clear message per malformed input.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "toolpath/trace_reader.hpp"

using toolpath::ChangeFlag;
using toolpath::Command;
using toolpath::TraceLine;
using toolpath::TraceReader;
using toolpath::Value;
using toolpath::ValueKind;

namespace {

std::vector<Command> read_all(const std::string& text, const std::string& name = "t.trace") {
  std::istringstream in(text);
  TraceReader reader(in, name);
  std::vector<Command> all;
  Command c;
  while (reader.next(c)) all.push_back(c);
  return all;
}

std::string read_error(const std::string& text) {
  try {
    read_all(text);
  } catch (const toolpath::InputError& e) {
    return e.what();
  }
  return "no error";
}

struct ValueCase {
  const char* text;
  Value expected;
};

TEST(ParseValue, EveryForm) {
  const ValueCase cases[] = {
      {"'PART.MPF'", Value::make_string("PART.MPF")},
      {"\"it's\"", Value::make_string("it's")},
      {"'  0:00:12'", Value::make_string("  0:00:12")},
      {"''", Value::make_string("")},
      {"", Value::make_string("")},
      {"1000", Value::make_integer(1000)},
      {"-7", Value::make_integer(-7)},
      {"+7", Value::make_integer(7)},
      {"10T", Value::make_integer(10, ChangeFlag::Changed)},
      {"10F", Value::make_integer(10, ChangeFlag::Unchanged)},
      {"61.550", Value::make_numeric(61.55)},
      {"-45.4760057628T", Value::make_numeric(-45.4760057628, ChangeFlag::Changed)},
      {"33.000F", Value::make_numeric(33.0, ChangeFlag::Unchanged)},
      {"1.", Value::make_numeric(1.0)},
      {".5", Value::make_numeric(0.5)},
      {"1.2E-2", Value::make_numeric(0.012)},
      {"3e2", Value::make_numeric(300.0)},
      {"0.1234567890123", Value::make_numeric(0.1234567890123)},
      {"TRUE", Value::make_logical(true)},
      {"false", Value::make_logical(false)},
      {"CW", Value::make_enum("CW")},
      {"cw", Value::make_enum("CW")},  // enumeration words compare case-insensitively
      {"axis4_none", Value::make_enum("AXIS4_NONE")},
      {"Salamat Abzar Check Shavad!!", Value::make_string("Salamat Abzar Check Shavad!!")},
      {"12abc", Value::make_string("12abc")},
      {"'x'   ", Value::make_string("x")},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    EXPECT_EQ(toolpath::parse_value(c.text, {"f", 1, 1}), c.expected);
  }
}

TEST(TraceReader, BlockForm) {
  auto all = read_all(
      "; a comment line\n"
      "(0)@start_of_file\n"
      "  ; comments may sit between parameters\n"
      "program_number : 5000\n"
      "g_file_name : 'OUT'\n"
      "rotate_used : FALSE\n"
      "\n"
      "(1)@arc\n"
      "  xpos : -8.35\n"
      "arc_direction : CW\n"
      "@end_of_file\n");
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].name, "@start_of_file");
  EXPECT_EQ(all[0].index, 0u);
  EXPECT_EQ(all[0].depth, 1);  // in the block form (N) numbers the command; it is not a depth
  EXPECT_EQ(*all[0].find("program_number"), Value::make_integer(5000));
  EXPECT_EQ(*all[0].find("G_FILE_NAME"), Value::make_string("OUT"));
  EXPECT_EQ(*all[0].find("rotate_used"), Value::make_logical(false));
  EXPECT_EQ(all[1].index, 1u);
  EXPECT_EQ(*all[1].find("xpos"), Value::make_numeric(-8.35));
  EXPECT_EQ(*all[1].find("arc_direction"), Value::make_enum("CW"));
  EXPECT_EQ(all[2].name, "@end_of_file");
  EXPECT_TRUE(all[2].parameters.empty());
}

TEST(TraceReader, SolidCamLayout) {
  std::ifstream f("toolpath/data/solidcam_layout.trace", std::ios::binary);
  ASSERT_TRUE(f) << "run from the tests/ folder";
  TraceReader reader(f, "solidcam_layout.trace");
  std::vector<Command> all;
  Command c;
  while (reader.next(c)) all.push_back(c);
  ASSERT_EQ(all.size(), 9u);

  const Command& start = all[0];
  EXPECT_EQ(start.depth, 1);
  EXPECT_EQ(start.parameters.size(), 5u);
  EXPECT_EQ(*start.find("home_number"), Value::make_integer(54));
  ASSERT_EQ(start.trace.size(), 2u);  // the empty `..>` line adds nothing
  EXPECT_EQ(start.trace[0], (TraceLine{TraceLine::Kind::Output, "%"}));
  EXPECT_EQ(start.trace[1], (TraceLine{TraceLine::Kind::Output, "N10 ; PART"}));

  EXPECT_EQ(all[1].name, "@usr_header");
  EXPECT_EQ(all[1].depth, 2);
  EXPECT_FALSE(all[1].is_stream_command());
  ASSERT_EQ(all[1].trace.size(), 1u);
  EXPECT_EQ(all[1].trace[0].text, "N20 G17 G90 ");  // trailing blanks are part of the NC line

  const Command& job = all[2];
  EXPECT_EQ(*job.find("xnext"), Value::make_numeric(61.55, ChangeFlag::Changed));
  EXPECT_EQ(*job.find("znext"), Value::make_numeric(33.0, ChangeFlag::Unchanged));
  EXPECT_EQ(*job.find("sWCM_MSG"), Value::make_string("Salamat Abzar Check Shavad!!"));
  EXPECT_EQ(*job.find("time"), Value::make_string("  0:00:12"));
  ASSERT_EQ(job.trace.size(), 1u);
  EXPECT_EQ(job.trace[0], (TraceLine{TraceLine::Kind::Output, "!! open file = F_contour1.SPF !!"}));

  EXPECT_EQ(all[3].name, "@tmatrix");
  EXPECT_EQ(all[3].depth, 0);
  EXPECT_TRUE(all[3].is_stream_command());
  EXPECT_EQ(all[3].parameters.size(), 2u);
  ASSERT_EQ(all[3].trace.size(), 1u);
  EXPECT_EQ(all[3].trace[0], (TraceLine{TraceLine::Kind::Note, "x = cosy*cosz*x - sinz*cosy*y + siny*z"}));

  EXPECT_EQ(all[5].name, "@usr_spindle_output");  // cut at 16 characters, continued below
  EXPECT_EQ(all[5].depth, 3);
  ASSERT_EQ(all[5].trace.size(), 1u);
  EXPECT_EQ(all[5].trace[0].text, "N290 S1910");

  EXPECT_EQ(*all[7].find("radius"), Value::make_numeric(15.0));
  EXPECT_EQ(*all[7].find("arc_plane"), Value::make_enum("XY"));

  const Command& end = all[8];
  ASSERT_EQ(end.trace.size(), 2u);
  EXPECT_EQ(end.trace[0], (TraceLine{TraceLine::Kind::Partial, "N400 M30"}));
  EXPECT_EQ(end.trace[1], (TraceLine{TraceLine::Kind::Directive, "!! close file = F_contour1.SPF !!"}));
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i].index, i);
}

// User parameters, as SolidCAM writes them at @start_of_file and @start_of_job: `name : value`
// pairs, the value unquoted, possibly empty, possibly with blanks and colons.
TEST(TraceReader, UserParameterLines) {
  struct Case {
    const char* name;
    const char* line;  // after `..>`
    std::vector<std::pair<std::string, Value>> expected;
  } cases[] = {
      {"Numbers", " iWorkOffset_Method : 0  iNumber_of_Fixtures : 0  bToolPreselect : 1  Iteration_For_M8 : 1  ",
       {{"iWorkOffset_Method", Value::make_integer(0)}, {"iNumber_of_Fixtures", Value::make_integer(0)},
        {"bToolPreselect", Value::make_integer(1)}, {"Iteration_For_M8", Value::make_integer(1)}}},
      {"Decimal", " nM8_CommitInterval : 1.000  bSPF_CM : 0  ",
       {{"nM8_CommitInterval", Value::make_numeric(1.0)}, {"bSPF_CM", Value::make_integer(0)}}},
      {"TextWithColonAndBlanks", " sWCM_MSG : Note: Ask your supervisor!  iX : 2",
       {{"sWCM_MSG", Value::make_string("Note: Ask your supervisor!")}, {"iX", Value::make_integer(2)}}},
      {"EmptyValues", " sA :   sB :  iC : 3", {{"sA", Value::make_string("")}, {"sB", Value::make_string("")},
                                               {"iC", Value::make_integer(3)}}},
      {"EmptyLast", " sA : 1  sB :", {{"sA", Value::make_integer(1)}, {"sB", Value::make_string("")}}},
      {"Word", " sMode : ROUGH", {{"sMode", Value::make_enum("ROUGH")}}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    auto all = read_all(std::string("(1)@start_of_job    ==> job_name:'F-contour1' \n") +
                        "                    ..>" + c.line + "\n");
    ASSERT_EQ(all.size(), 1u);
    ASSERT_EQ(all[0].parameters.size(), c.expected.size() + 1);
    EXPECT_TRUE(all[0].trace.empty()) << "kept as parameters, not as a note";
    for (const auto& [name, value] : c.expected) {
      ASSERT_NE(all[0].find(name), nullptr) << name;
      EXPECT_EQ(*all[0].find(name), value) << name;
    }
  }
  // SolidCAM's `no parameters` after `==>` is neither a parameter nor unfinished output.
  auto end = read_all("(1)@end_of_file     ==> no parameters\n");
  ASSERT_EQ(end.size(), 1u);
  EXPECT_TRUE(end[0].parameters.empty());
  EXPECT_TRUE(end[0].trace.empty());
  // A `..>` line of free text that is not pairs is still a note.
  auto note = read_all("(0)@tmatrix         ==> \n                    ..> around Z\n");
  ASSERT_EQ(note[0].trace.size(), 1u);
  EXPECT_EQ(note[0].trace[0], (TraceLine{TraceLine::Kind::Note, "around Z"}));
}

TEST(TraceReader, ManualExampleHas210Commands) {
  auto reader = TraceReader::open("golden/solidcam-fanuc/toolpath.trace");
  Command c;
  std::size_t n = 0;
  std::string last;
  while (reader->next(c)) {
    EXPECT_EQ(c.index, n);
    last = c.name;
    ++n;
  }
  EXPECT_EQ(n, 210u);
  EXPECT_EQ(last, "@end_of_file");
}

TEST(TraceReader, EmptyInputsGiveNoCommands) {
  EXPECT_TRUE(read_all("").empty());
  EXPECT_TRUE(read_all("\n\r\n   \n").empty());
}

TEST(TraceReader, LastLineWithoutNewlineAndCrlf) {
  auto all = read_all("@a\r\nx : 1\r\n@b\r\ny : 'q'");
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(*all[0].find("x"), Value::make_integer(1));
  EXPECT_EQ(*all[1].find("y"), Value::make_string("q"));
}

struct ErrorCase {
  const char* input;
  const char* message;
};

TEST(TraceReader, MalformedInputNamesThePosition) {
  const ErrorCase cases[] = {
      {"xpos : 1\n", "t.trace:1:1: expected a command header `(N)@name` or `@name`"},
      {"(x)@line\n", "t.trace:1:2: expected a number and `)` in the command header"},
      {"(1)@\n", "t.trace:1:5: expected a command name after `@`"},
      {"(1)@line junk\n", "t.trace:1:10: expected `==>` or the end of the line after the command name"},
      {"@line\nxpos 1\n", "t.trace:2:6: expected `:` after the parameter name `xpos`"},
      {"@line\n  ?? what\n", "t.trace:2:3: expected `name : value`, `..>` continuation, `> ` output line or a command header"},
      {"@line\nname : 'open\n", "t.trace:2:13: expected closing ' of the string"},
      {"@line\nn : 99999999999999999999\n", "t.trace:2:5: integer out of range: 99999999999999999999"},
      {"@line\nn : 1e999\n", "t.trace:2:5: number out of range: 1e999"},
      {"(1)@line ==> a:'x\n", "t.trace:1:18: expected closing ' of the string"},
      {"(1)@line ==> a:'x' junk\n", "t.trace:1:20: expected `name:value`"},
      {"(-1)@line ==> a:1\n", "t.trace:1:2: expected a depth of 0 or more"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.input);
    EXPECT_EQ(read_error(c.input), c.message);
  }
}

TEST(TraceReader, MissingFileIsAnInputError) {
  EXPECT_THROW(TraceReader::open("no/such/file.trace"), toolpath::InputError);
}

TEST(LookaheadSource, PeekShowsTheNextCommandWithoutTakingIt) {
  std::istringstream in("@a\n@b\n");
  TraceReader reader(in, "t");
  toolpath::LookaheadSource source(reader);
  Command c;
  ASSERT_NE(source.peek(), nullptr);
  EXPECT_EQ(source.peek()->name, "@a");
  ASSERT_TRUE(source.next(c));
  EXPECT_EQ(c.name, "@a");
  ASSERT_NE(source.peek(), nullptr);
  EXPECT_EQ(source.peek()->name, "@b");
  ASSERT_TRUE(source.next(c));
  EXPECT_EQ(c.name, "@b");
  EXPECT_EQ(source.peek(), nullptr);
  EXPECT_FALSE(source.next(c));
}

}  // namespace
