// The small switches of spec 3.5, 3.6 and 3.13: coordinate-mode commands, full coordinates,
// @init_cpos before a 4-axis job, and the min_delt_arc_rad check under compensation.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "prp/filters/compensation_check.hpp"
#include "prp/filters/full_coordinates.hpp"
#include "prp/filters/init_cpos.hpp"
#include "prp/filters/mode_commands.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;
using toolpath::Command;

namespace {

prp::MachineParameters prp_with(const std::string& lines) {
  return prp::load_source("@pre_processor\n" + lines + "endp\n", "s.prp", prp::Units::Metric);
}

std::vector<std::string> names(const std::vector<Command>& commands) {
  std::vector<std::string> out;
  for (const auto& c : commands) out.push_back(c.name + " #" + std::to_string(c.index));
  return out;
}

struct Warnings {
  std::vector<std::string> got;
  prp::WarningSink sink() {
    return [this](const Command& c, const std::string& m) { got.push_back(c.name + ": " + m); };
  }
};

struct ModeCase {
  const char* settings;
  std::vector<Command> in;
  std::vector<std::string> expected, warnings;
};

std::vector<Command> flat() {
  return {command("@start_program", {}, 0), command("@start_of_job", {}, 1), command("@rapid_move", {{"xpos", num(1)}}, 2),
          command("@line", {{"xpos", num(2)}}, 3)};
}

TEST(ModeCommands, Table) {
  const std::vector<std::string> untouched{"@start_program #0", "@start_of_job #1", "@rapid_move #2", "@line #3"};
  auto own = flat();
  own.insert(own.begin() + 1, command("@absolute_mode", {}, 9));
  const std::vector<Command> structured{command("@start_program", {}, 0), command("@call_proc", {}, 1),
                                        command("@end_program", {}, 2), command("@proc", {}, 3),
                                        command("@rapid_move", {}, 4)};
  const ModeCase cases[] = {
      {"abs_coord = N\n", flat(), {"@start_program #0", "@start_of_job #1", "@absolute_mode #2", "@rapid_move #2", "@line #3"}, {}},
      {"relative_gcode = Y\n", flat(), {"@start_program #0", "@start_of_job #1", "@relative_mode #2", "@rapid_move #2", "@line #3"}, {}},
      {"abs_coord = N\n", own, {"@start_program #0", "@absolute_mode #9", "@start_of_job #1", "@rapid_move #2", "@line #3"}, {}},
      {"abs_coord = N\n",
       structured,
       {"@start_program #0", "@call_proc #1", "@end_program #2", "@proc #3", "@rapid_move #4"},
       {"@rapid_move: the PRP says abs_coord = N but the toolpath sends no @absolute_mode before its first motion"}},
  };
  for (const auto& k : cases) {
    SCOPED_TRACE(k.settings);
    auto params = prp_with(k.settings);
    ListSource source(k.in);
    Warnings w;
    prp::ModeCommands filter(source, params, w.sink());
    EXPECT_EQ(names(drain(filter)), k.expected);
    EXPECT_EQ(w.got, k.warnings);
  }
  EXPECT_EQ(prp::ModeCommands::wanted(prp_with("abs_coord = Y\n")), "");
  EXPECT_EQ(prp::ModeCommands::wanted(prp_with("")), "");
}

TEST(FullCoordinates, EveryMotionCarriesAllThreeChanged) {
  using toolpath::ChangeFlag;
  ListSource source({command("@line", {{"xpos", num(1)}, {"ypos", num(2)}, {"zpos", num(3)}}),
                     command("@line", {{"xpos", num(5)}}),
                     command("@rapid_move", {{"xpos", num(5)}, {"ypos", num(2)}, {"zpos", toolpath::Value::make_numeric(3, ChangeFlag::Unchanged)}}),
                     command("@delay", {{"delay", num(2)}})});
  prp::FullCoordinates filter(source);
  auto out = drain(filter);
  const double expected[3][3] = {{1, 2, 3}, {5, 2, 3}, {5, 2, 3}};
  for (int i = 0; i < 3; ++i) {
    for (int a = 0; a < 3; ++a) {
      const toolpath::Value* v = out[static_cast<std::size_t>(i)].find(std::string(1, "xyz"[a]) + "pos");
      ASSERT_NE(v, nullptr) << i << a;
      EXPECT_EQ(v->as_number(), expected[i][a]) << i << a;
      EXPECT_EQ(v->flag, ChangeFlag::Changed) << i << a;
    }
  }
  EXPECT_EQ(out[3], command("@delay", {{"delay", num(2)}}));
}

TEST(InitCpos, BestCposIsThePreviousAngleRenamedByWholeTurns) {
  const double cases[][3] = {{350, 10, -10}, {10, 350, 370}, {720, 5, 0}, {90, 90, 90}, {-30, 400, 330}};
  for (const auto& k : cases) EXPECT_EQ(prp::best_cpos(k[0], k[1]), k[2]) << k[0] << " " << k[1];
}

TEST(InitCpos, SentBeforeTheFirstMoveOfEach4AxisJob) {
  ListSource source({command("@start_of_job", {}, 0), command("@line_4x", {{"cpos", num(350)}}, 1),
                     command("@end_of_job", {}, 2), command("@start_of_job", {}, 3), command("@rotary_info", {}, 4),
                     command("@line_4x", {{"cpos", num(10)}}, 5), command("@line_4x", {{"cpos", num(20)}}, 6),
                     command("@start_of_job", {}, 7), command("@line", {}, 8), command("@init_cpos", {}, 9),
                     command("@line_4x", {{"cpos", num(25)}}, 10)});
  prp::InitCpos filter(source);
  auto out = drain(filter);
  EXPECT_EQ(names(out), (std::vector<std::string>{"@start_of_job #0", "@line_4x #1", "@end_of_job #2", "@start_of_job #3",
                                                  "@rotary_info #4", "@init_cpos #5", "@line_4x #5", "@line_4x #6",
                                                  "@start_of_job #7", "@line #8", "@init_cpos #9", "@line_4x #10"}));
  EXPECT_EQ(get(out[5], "prev_cpos"), 350);
  EXPECT_EQ(get(out[5], "best_cpos"), -10);
}

TEST(CompensationCheck, ConcaveArcsBelowToolRadiusPlusMargin) {
  auto arc = [](const char* dir, double r) { return command("@arc", {{"arc_direction", word(dir)}, {"radius", num(r)}}); };
  ListSource source({command("@change_tool", {{"tool_diameter", num(10)}}),
                     command("@compensation", {{"side", word("COMP_LEFT")}}), arc("CCW", 5.005), arc("CW", 2),
                     arc("CCW", 6), command("@compensation", {{"side", word("COMP_RIGHT")}}), arc("CW", 4),
                     arc("CCW", 4), command("@compensation", {{"side", word("COMP_OFF")}}), arc("CCW", 1)});
  Warnings w;
  prp::StepFilter<prp::CompensationCheck> filter(source, 0.01, w.sink());
  EXPECT_EQ(drain(filter).size(), 10u);
  EXPECT_EQ(w.got, (std::vector<std::string>{
                       "@arc: arc radius 5.005 is below tool radius 5 + min_delt_arc_rad 0.01 on the compensated side (COMP_LEFT)",
                       "@arc: arc radius 4 is below tool radius 5 + min_delt_arc_rad 0.01 on the compensated side (COMP_RIGHT)"}));
  EXPECT_TRUE(prp::CompensationCheck::needed(prp_with("min_delt_arc_rad = 0.01, 0.0004\n")));
  EXPECT_FALSE(prp::CompensationCheck::needed(prp_with("min_delt_arc_rad = 0.01\ncomp_by_zero_tool = Y\n")));
  EXPECT_FALSE(prp::CompensationCheck::needed(prp_with("")));
}

}  // namespace
