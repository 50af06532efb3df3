// TraceReader::skim_job_motions(), the first pass of procedure generation in two passes: it must
// give exactly the commands of a full read minus the ones its rule leaves out (deeper than the
// stream, or a basic motion inside a job after the job's opening tool changes), with the indices,
// lines, parameters and trace lines of the full read. The rule is written again here, on the
// commands of a full read, and both are compared on hand-made and random jobs.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "toolpath/trace_reader.hpp"
#include "tests/support/random_edits.hpp"

namespace {

using toolpath::Command;

std::string describe(const Command& c) {
  std::ostringstream s;
  s << c.index << ' ' << c.name << " d" << c.depth << " l" << c.line << ':';
  for (const toolpath::Parameter& p : c.parameters) s << ' ' << p.name << '@' << p.line << ':' << p.column;
  for (const toolpath::TraceLine& t : c.trace) s << " [" << static_cast<int>(t.kind) << ' ' << t.text << ']';
  return s.str();
}

// The commands of `text`, read in full or skimmed; `error` gets the reader's error, if any.
std::vector<Command> read(const std::string& text, bool skim, std::string* error = nullptr) {
  std::istringstream in(text);
  toolpath::TraceReader reader(in, "f.trace");
  if (skim) reader.skim_job_motions();
  std::vector<Command> out;
  Command c;
  try {
    while (reader.next(c)) out.push_back(c);
  } catch (const toolpath::InputError& e) {
    if (error) *error = e.what();
  }
  return out;
}

bool named(const Command& c, const char* name) { return toolpath::iequals(c.name, name); }

// The rule, on a full read of a job whose headers all have the `(depth)@name   ==>` layout.
std::vector<Command> expected_skim(const std::vector<Command>& full) {
  std::vector<Command> kept;
  bool in_job = false, leading = false;
  for (const Command& c : full) {
    if (c.depth >= 2) continue;
    const bool motion = named(c, "@line") || named(c, "@arc") || named(c, "@rapid_move");
    if (in_job && !leading && motion) continue;
    kept.push_back(c);
    if (named(c, "@start_of_job")) {
      in_job = leading = true;
    } else if (named(c, "@end_of_job")) {
      in_job = leading = false;
    } else if (!named(c, "@change_tool") && !named(c, "@turn_change_tool") && !named(c, "@chng_tool_cnext")) {
      leading = false;
    }
  }
  return kept;
}

std::vector<std::string> described(const std::vector<Command>& commands) {
  std::vector<std::string> out;
  for (const Command& c : commands) out.push_back(describe(c));
  return out;
}

// The stream commands only: a deeper command whose name may go on below is kept by the skim
// (it cannot tell at a glance) and dropped after it, as the engine drops every deeper command.
std::vector<Command> stream_only(std::vector<Command> commands) {
  std::erase_if(commands, [](const Command& c) { return !c.is_stream_command(); });
  return commands;
}

void check(const std::string& text) {
  std::string error;
  const std::vector<Command> full = read(text, false, &error);
  ASSERT_EQ(error, "") << text;
  const std::vector<Command> skimmed = stream_only(read(text, true));
  const std::vector<Command> expected = expected_skim(full);
  ASSERT_EQ(described(skimmed), described(expected)) << text.substr(0, 3000);
  for (std::size_t i = 0; i < skimmed.size(); ++i) ASSERT_TRUE(skimmed[i] == expected[i]) << describe(skimmed[i]);
}

TEST(TraceReaderSkim, LeavesOutTheMotionsOfJobsAndTheDeeperCommands) {
  const std::string job =
      "(1)@start_of_file   ==> program_number:1\n"
      "(1)@rapid_move      ==> xpos:0 ypos:0 zpos:50\n"          // outside a job: kept
      "(1)@start_of_job    ==> job_name:'A'\n"
      "(1)@change_tool     ==> tool_number:4\n"
      "(2)@set_var         ==> depth:2\n"                         // deeper: left out
      "(1)@change_tool     ==> tool_number:5\n"                   // still opening the job
      "(1)@rapid_move      ==> xpos:1 ypos:1 zpos:5\n"            // the first of the body: kept
      "(1)@line            ==> xpos:2 ypos:1 zpos:5\n"
      "   > N10 G1 X2.\n"
      "(1)@arc             ==> xpos:3 ypos:2\n"
      "                    ..> radius:1 arc_direction:CW\n"
      "(1)@change_tool     ==> tool_number:6\n"                   // a tool change in the body: kept
      "(1)@LINE            ==> xpos:4\n"                          // names are case-blind
      "\n; a comment\n"
      "(0)@rapid_move      ==> xpos:5\n"                          // depth 0 is the stream too
      "(1)@drill           ==> drill_type:Peck\n"
      "(1)@drill_point     ==> xpos:1 ypos:1\n"
      "(1)@end_drill       ==>\n"
      "(1)@end_of_job      ==>\n"
      "(1)@line            ==> xpos:9\n"                          // outside again: kept
      "(1)@end_of_file     ==>\n";
  check(job);
  EXPECT_EQ(read(job, true).size(), 13u);  // the deeper command too is left out
}

// The three motion names in any case are left out; a name one byte away from one is kept.
TEST(TraceReaderSkim, MotionNamesInAnyCaseAndTheirNeighbours) {
  std::string job = "(1)@start_of_job    ==> job_name:'A'\n(1)@change_tool     ==> tool_number:4\n(1)@line ==> xpos:0\n";
  for (const char* name : {"@arc", "@ARC", "@aRc", "@line", "@LINE", "@Line", "@rapid_move", "@RAPID_MOVE", "@Rapid_Move",
                           "@arcs", "@ar_", "@ar", "@arc1", "@lin_", "@l1ne", "@line_", "@lines", "@rapid_mov",
                           "@rapid_moves", "@rapid_m0ve", "@rapidXmove", "@rapid_movf", "@_rapid_move",
                           "@qrc", "@Arc_", "@LINE1"})
    job += std::string("(1)") + name + "              ==> xpos:1\n";
  // The usual spellings with other paddings and depths, and short lines (a name that runs into
  // `==>` is kept on purpose: KeepsWhatItCannotTellAtAGlance).
  for (const char* header : {"(1)@line ==>", "(1)@arc ==> xpos:1", "(1)@arc ==>xpos:1 ypos:2 zpos:3", "(1)@line ==>xpos:1 y:1",
                             "(1)@rapid_move ==>", "(1)@rapid_move  ==> xpos:1 ypos:2", "(1)@rapid_move\t==> xpos:1 ypos:2",
                             "(1)@line\t\t\t==> xpos:1 ypos:2", "(2)@line            ==> xpos:1", "(0)@arc             ==> xpos:1",
                             "(1)@line            ==>", "(1)@arc             ==>xpos:1 ypos:2"})
    job += std::string(header) + "\n";
  job += "(1)@end_of_job      ==>\n";
  check(job);
}

TEST(TraceReaderSkim, KeepsWhatItCannotTellAtAGlance) {
  // A name that runs into `==>` may go on below: kept, so read in full. So is the block form.
  const std::string text =
      "(1)@start_of_job    ==>\n(1)@line ==> xpos:0\n(1)@line==> xpos:1\n(1)@line\n  xpos : 2\n@arc\n  xpos : 3\n"
      "(1)@end_of_job      ==>\n";
  const std::vector<Command> skimmed = read(text, true);
  ASSERT_EQ(skimmed.size(), 6u);
  EXPECT_EQ(skimmed[1].index, 1u);  // the first motion of the body
  EXPECT_EQ(skimmed[2].index, 2u);
  EXPECT_EQ(skimmed[3].index, 3u);
  EXPECT_EQ(skimmed[4].index, 4u);
  EXPECT_EQ(skimmed[5].name, "@end_of_job");
  EXPECT_EQ(skimmed[5].index, 5u);
}

TEST(TraceReaderSkim, ErrorsBeforeTheFirstHeaderAreStillFound) {
  std::string error;
  read("xpos:1\n(1)@line ==> xpos:1\n", true, &error);
  EXPECT_NE(error.find("f.trace:1:1: expected a command header"), std::string::npos) << error;
}

// Random jobs: commands outside and inside jobs, opening tool changes, deeper commands, output and
// continuation lines, blank lines and comments, CR LF ends.
std::string random_job(std::mt19937& rng, std::size_t items) {
  const char* body[] = {"@line", "@arc", "@rapid_move", "@Line", "@change_tool", "@drill", "@drill_point",
                        "@end_drill", "@message", "@turn_change_tool"};
  const char* outside[] = {"@rapid_move", "@line", "@def_tool", "@change_tool", "@message", "@start_program"};
  std::string text = "(1)@start_of_file   ==> program_number:1\n";
  auto header = [&](int depth, const char* name) {
    text += '(' + std::to_string(depth) + ')' + name + std::string(1 + rng() % 8, ' ') + "==> xpos:" +
            std::to_string(rng() % 100) + (rng() % 2 ? " ypos:1.5" : "");
    text += rng() % 10 == 0 ? "\r\n" : "\n";
    if (rng() % 4 == 0) text += "                    ..> zpos:-0.5 feed:1500\n";
    if (rng() % 8 == 0) text += "   > N10 G1 X1.\n";
    if (rng() % 15 == 0) text += rng() % 2 ? "\n" : "; note\n";
    if (rng() % 6 == 0) text += "(2)@internal        ==> a:1\n   > N20\n";
  };
  for (std::size_t i = 0; i < items; ++i) {
    if (rng() % 3 == 0) {
      header(1, outside[rng() % std::size(outside)]);
      continue;
    }
    header(rng() % 5 == 0 ? 0 : 1, "@start_of_job");
    for (std::size_t t = rng() % 3; t > 0; --t) header(1, rng() % 4 ? "@change_tool" : "@chng_tool_cnext");
    for (std::size_t b = rng() % 12; b > 0; --b) header(rng() % 7 == 0 ? 2 : 1, body[rng() % std::size(body)]);
    if (rng() % 10) header(1, "@end_of_job");  // sometimes a job runs into the next
  }
  if (rng() % 2) header(1, "@end_of_file");
  return text;
}

TEST(TraceReaderSkim, RandomJobs) {
  std::mt19937 rng(20261128);
  for (int round = 0; round < 2000; ++round) check(random_job(rng, 1 + rng() % 10));
}

// Skipped commands may straddle the 256 KiB chunk end: the skim still sees every line.
TEST(TraceReaderSkim, JobsLongerThanAChunk) {
  std::mt19937 rng(20261129);
  for (int round = 0; round < 3; ++round) check(random_job(rng, 6000));
}

TEST(TraceReaderSkim, LayoutExample) {
  std::ifstream f("toolpath/data/solidcam_layout.trace", std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  ASSERT_FALSE(s.str().empty());
  check(s.str());
}

// Damaged jobs: the skim reads what it can and stops with an error or at the end, never worse.
TEST(TraceReaderSkim, DamagedJobsNeverCrash) {
  std::mt19937 rng(20261130);
  const char alphabet[] = "()@:'\" \t\r\n.>=!-0123456789_;abc";
  for (int round = 0; round < 2000; ++round) {
    std::string text = random_job(rng, 1 + rng() % 6);
    test_support::random_edits(text, rng, std::string_view(alphabet, sizeof alphabet - 1), 1 + static_cast<int>(rng() % 4));
    std::string error;
    const std::vector<Command> full = read(text, false, &error);
    const std::vector<Command> skimmed = read(text, true);
    if (error.empty()) {
      EXPECT_LE(skimmed.size(), full.size());
    }
  }
}

}  // namespace
