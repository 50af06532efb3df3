// Splitting a line into commands and naming one-command frames, as tables.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "machines/2xaxiscnc/frame.hpp"

namespace {

using twoaxis::Instruction;

TEST(TwoAxisFrame, SplitsOnRunsOfBlanks) {
  struct Case {
    const char* line;
    std::size_t count;
    std::vector<std::string> commands;
    std::vector<std::size_t> columns;
  };
  const Case cases[] = {
      {"", 0, {}, {}},
      {"   \t ", 0, {}, {}},
      {"5,5 -3", 2, {"5,5", "-3"}, {1, 5}},
      {"  2\t0  0,7\r", 3, {"2", "0", "0,7"}, {3, 5, 8}},
      {"1 2 3 4 5", 5, {"1", "2", "3", "4"}, {1, 3, 5, 7}},
      {"(Hello_World!)", 1, {"(Hello_World!)"}, {1}},
  };
  for (const Case& c : cases) {
    const auto f = twoaxis::split_frame(c.line);
    EXPECT_EQ(f.count, c.count) << c.line;
    for (std::size_t i = 0; i < c.commands.size(); ++i) {
      EXPECT_EQ(f.commands[i], c.commands[i]) << c.line;
      EXPECT_EQ(f.columns[i], c.columns[i]) << c.line;
    }
  }
}

TEST(TwoAxisFrame, ClassifiesInstructions) {
  struct Case {
    const char* command;
    Instruction kind;
    bool case_differs;
    const char* argument;
  };
  const Case cases[] = {
      {"(Test)", Instruction::Comment, false, "Test"},
      {"()", Instruction::Comment, false, ""},
      {"XHYH", Instruction::HomeXY, false, ""},
      {"X0Y0", Instruction::GotoZero, false, ""},
      {"SpEn", Instruction::SpindleToggle, false, ""},
      {"M03", Instruction::SpindleOn, false, ""},
      {"M05", Instruction::SpindleOff, false, ""},
      {"Out1", Instruction::Relay, false, "1"},
      {"Out4", Instruction::Relay, false, "4"},
      {"P2,5", Instruction::Pause, false, "2,5"},
      {"ArtCam_file_for_2XAxisCNC", Instruction::ArtCamMarker, false, ""},
      {"G90", Instruction::G90Marker, false, ""},
      {"G91", Instruction::G91Marker, false, ""},
      {"Imp_1_0,001_100", Instruction::Pulses, false, "1_0,001_100"},
      {"A-0,2455", Instruction::AMove, false, "-0,2455"},
      {"A105", Instruction::AMove, false, "105"},
      {"AH", Instruction::HomeA, false, ""},
      {"RunScript_down.script", Instruction::Script, false, "down.script"},
      {"m03", Instruction::SpindleOn, true, ""},
      {"out2", Instruction::Relay, true, "2"},
      {"x0y0", Instruction::GotoZero, true, ""},
      {"M3", Instruction::Unknown, false, ""},
      {"M5", Instruction::Unknown, false, ""},
      {"Out5", Instruction::Unknown, false, ""},
      {"Out", Instruction::Unknown, false, ""},
      {"P", Instruction::Unknown, false, ""},
      {"A", Instruction::Unknown, false, ""},
      {"(", Instruction::Unknown, false, ""},
      {"RunScript_.script", Instruction::Unknown, false, ""},
      {"RunScript_x.txt", Instruction::Unknown, false, ""},
      {"G0", Instruction::Unknown, false, ""},
  };
  for (const Case& c : cases) {
    const auto r = twoaxis::classify(c.command);
    EXPECT_EQ(r.kind, c.kind) << c.command;
    EXPECT_EQ(r.case_differs, c.case_differs) << c.command;
    EXPECT_EQ(r.argument, c.argument) << c.command;
  }
}

}  // namespace
