// The temporary file of commands that procedure generation replays: every command comes back as
// written, from the start or from any offset, also when writes and reads alternate.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
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

// The kind written with a command comes back with it (procedure generation replays bodies without
// classifying their names again); write(c) stores command_kind(c).
TEST(CommandSpool, KeepsTheKind) {
  prp::CommandSpool spool;
  spool.write(command("@line", {{"xpos", num(1)}}), prp::CommandKind::line);
  spool.write(command("@ARC", {}));
  spool.write(command("\x01job", {}), prp::CommandKind::other);
  spool.seek(0);
  Command c;
  prp::CommandKind kind{};
  ASSERT_TRUE(spool.read(c, kind));
  EXPECT_EQ(kind, prp::CommandKind::line);
  ASSERT_TRUE(spool.read(c, kind));
  EXPECT_EQ(kind, prp::CommandKind::arc);
  ASSERT_TRUE(spool.read(c, kind));
  EXPECT_EQ(kind, prp::CommandKind::other);
}

// A read into a command that already holds something (another command's names, values, texts and
// lengths, as a filter chain hands back) gives what a read into a fresh command gives, whatever
// the destination held: the spare parameter lists and the names kept in place are invisible.
TEST(CommandSpool, ReusedDestinationsReadLikeFreshOnes) {
  std::mt19937 random(25);
  const char* names[] = {"xpos", "XPOS", "ypos", "feed", "arc_direction", "job_name", "not_in_catalogue", "Zpos",
                         "radius", "a_name_longer_than_sixteen_bytes"};
  auto value = [&](int i) {
    switch (i % 5) {
      case 0: return Value::make_integer(static_cast<std::int64_t>(random()) - (1 << 30), ChangeFlag::Changed);
      case 1: return num(std::ldexp(static_cast<double>(random()), -20));
      case 2: return Value::make_logical(random() % 2 == 0);
      case 3: return Value::make_string(std::string(random() % 20, 's'));
      default: return word(random() % 2 ? "CW" : "CCW");
    }
  };
  std::vector<Command> commands;
  for (int i = 0; i < 3000; ++i) {
    Command c;
    c.name = random() % 3 == 0 ? "@arc" : random() % 2 ? "@line" : "@a_command_name_longer_than_16";
    c.index = static_cast<std::size_t>(i);
    c.depth = static_cast<int>(random() % 3);
    c.line = static_cast<std::uint32_t>(random());
    const int n = random() % 4 == 0 ? static_cast<int>(random() % 40) : static_cast<int>(random() % 15);
    for (int k = 0; k < n; ++k) {
      c.parameters.push_back({names[random() % std::size(names)], value(static_cast<int>(random()))});
      c.parameters.back().line = static_cast<std::uint32_t>(random());
      c.parameters.back().column = static_cast<std::uint32_t>(random());
    }
    if (random() % 10 == 0) c.trace = {{toolpath::TraceLine::Kind::Output, "N10 G1 X1."}};
    commands.push_back(std::move(c));
  }
  prp::CommandSpool spool;
  for (const auto& c : commands) spool.write(c);
  spool.seek(0);
  std::vector<Command> reused(7);  // destinations handed back in turn, as a ring of buffers does
  for (std::size_t i = 0; i < commands.size(); ++i) {
    Command& c = reused[random() % reused.size()];
    ASSERT_TRUE(spool.read(c));
    ASSERT_EQ(c, commands[i]) << i;
    ASSERT_EQ(c.line, commands[i].line);
    for (std::size_t k = 0; k < c.parameters.size(); ++k) {
      const toolpath::Parameter &p = c.parameters[k], &q = commands[i].parameters[k];
      ASSERT_EQ(p.key, q.key) << i << " " << k;
      ASSERT_EQ(std::pair(p.line, p.column), std::pair(q.line, q.column));
      ASSERT_EQ(p.value.integer, q.value.integer);  // the fields of other kinds come back zero
      ASSERT_EQ(p.value.numeric, q.value.numeric);
      ASSERT_EQ(p.value.logical, q.value.logical);
      ASSERT_EQ(p.value.text, q.value.text);
    }
    if (random() % 3 == 0) c.parameters.emplace_back("added_downstream", num(1));  // changed by a filter
    if (random() % 5 == 0 && !c.parameters.empty()) c.parameters.front().rename("Renamed");
  }
  EXPECT_FALSE(spool.read(reused[0]));
}
