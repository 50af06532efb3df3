// The temporary file of commands that procedure generation replays: every command comes back as
// written, from the start or from any offset, also when writes and reads alternate.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "prp/filters/command_spool.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;
using toolpath::ChangeFlag;
using toolpath::Command;
using toolpath::Value;

namespace {

std::vector<Command> samples() {
  Command arc = command("@arc", {{"xpos", Value::make_numeric(-45.476, ChangeFlag::Changed)},
                                 {"tool_number", Value::make_integer(-12, ChangeFlag::Unchanged)},
                                 {"arc_direction", word("CCW")},
                                 {"job_name", Value::make_string("it's a job")},
                                 {"empty", Value::make_string("")},
                                 {"flag", Value::make_logical(true)},
                                 {"off", Value::make_logical(false)}},
                        7);
  arc.depth = 2;
  arc.line = 4000000000u;  // where it was read: errors found after the replay still point there
  arc.parameters[0].line = 41;
  arc.parameters[0].column = 4000000000u;
  arc.trace = {{toolpath::TraceLine::Kind::Output, "N10 G3 X1."}, {toolpath::TraceLine::Kind::Partial, ""}};
  Command bare;
  bare.name = "@end_of_file";
  bare.index = 123456789012;
  bare.depth = 0;
  Command long_name = command(std::string(300, 'n'), {{std::string(70000, 'p').c_str(), num(1e300)}}, 8);
  // Catalogue names are stored as their key, others (and other spellings of them) as text: both
  // come back spelled as written, with their key.
  Command spelled = command("@line", {{"XPOS", num(2)}, {"Feed", num(3)}, {"ypos", num(4)}, {"not_in_catalogue", num(5)},
                                      {"zpos ", num(6)}},
                            10);
  return {arc, bare, long_name, command("@line", {{"xpos", num(0.1)}, {"ypos", num(-0.0)}}, 9), spelled};
}

TEST(CommandSpool, ReadsBackWhatWasWritten) {
  prp::CommandSpool spool;
  const auto commands = samples();
  std::vector<std::int64_t> offsets;
  for (const auto& c : commands) offsets.push_back(spool.write(c));
  spool.seek(0);
  Command c;
  for (const auto& expected : commands) {
    ASSERT_TRUE(spool.read(c));
    EXPECT_EQ(c, expected);
    EXPECT_EQ(c.line, expected.line);  // not part of ==
    for (std::size_t i = 0; i < c.parameters.size() && i < expected.parameters.size(); ++i)
      EXPECT_EQ(std::pair(c.parameters[i].line, c.parameters[i].column),
                std::pair(expected.parameters[i].line, expected.parameters[i].column));
  }
  EXPECT_FALSE(spool.read(c));
  for (std::size_t i = commands.size(); i-- > 0;) {  // from any offset, in any order
    spool.seek(offsets[i]);
    ASSERT_TRUE(spool.read(c));
    EXPECT_EQ(c, commands[i]);
  }
}

TEST(CommandSpool, WritesAndReadsAlternate) {
  prp::CommandSpool spool;
  const auto commands = samples();
  Command c;
  spool.write(commands[0]);
  spool.seek(0);
  ASSERT_TRUE(spool.read(c));
  EXPECT_EQ(c, commands[0]);
  spool.write(commands[1]);  // appends at the end, whatever was read
  spool.write(commands[2]);
  ASSERT_TRUE(spool.read(c));  // reading continues where it stopped
  EXPECT_EQ(c, commands[1]);
  ASSERT_TRUE(spool.read(c));
  EXPECT_EQ(c, commands[2]);
  EXPECT_FALSE(spool.read(c));
}

// Past a block (1 MiB) records go to the file; the rest stay in memory until flushed. Every record
// reads back from any offset: in the file, across a block boundary, in memory, larger than a block.
TEST(CommandSpool, ManyBlocksAndOneHugeRecord) {
  prp::CommandSpool spool;
  std::vector<Command> commands;
  for (int i = 0; i < 40000; ++i)
    commands.push_back(command(i % 2 ? "@line" : "@arc", {{"xpos", num(i)}, {"ypos", num(-i)}, {"zpos", num(0.5)}},
                               static_cast<std::size_t>(i)));
  commands[20000].parameters.push_back({"job_name", Value::make_string(std::string(3 << 20, 'j'))});
  std::vector<std::int64_t> offsets;
  for (const auto& c : commands) offsets.push_back(spool.write(c));
  ASSERT_GT(spool.end(), 4 << 20);
  Command c;
  spool.seek(0);
  for (const auto& expected : commands) {
    ASSERT_TRUE(spool.read(c));
    ASSERT_EQ(c, expected);
  }
  EXPECT_FALSE(spool.read(c));
  for (std::size_t i = commands.size(); i-- > 0;) {
    if (i % 997 != 0 && i != 19999 && i != 20000 && i != 20001 && i + 1 != commands.size()) continue;
    spool.seek(offsets[i]);
    ASSERT_TRUE(spool.read(c));
    EXPECT_EQ(c, commands[i]) << i;
  }
}

}  // namespace
