// Structure switches checked against a structured trace, and default start/end positions.
#include <gtest/gtest.h>

#include "prp/filters/structure_check.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;

namespace {

const char* kPrp =
    "@pre_processor\n"
    "gen_procs = N\nloop_exist = N\ncomp_exist = N\nnum_homes = 2\nturning_cycle = N\ngroove_cycle = N Y\n"
    "prog_num_min = 5000\nprog_num_max = 8999\nproc_num_min = 1\nproc_num_max = 99\n"
    "dflt_start = 0 200 100, 0 7.874 3.937\n"
    "endp\n";

std::vector<std::string> warnings_for(std::vector<toolpath::Command> in) {
  auto params = prp::load_source(kPrp, "s.prp", prp::Units::Metric);
  ListSource source(std::move(in));
  std::vector<std::string> got;
  prp::StepFilter<prp::StructureCheck> check(source, params, [&](const toolpath::Command& c, const std::string& m) {
    got.push_back(c.name + ": " + m);
  });
  drain(check);
  return got;
}

std::string error_for(toolpath::Command c) {
  try {
    warnings_for({std::move(c)});
  } catch (const prp::StreamError& e) {
    return e.what();
  }
  return "no error";
}

TEST(StructureCheck, MismatchesAreWarnings) {
  EXPECT_EQ(warnings_for({command("@call_proc", {{"label", num(3)}}), command("@loop", {}),
                          command("@call_prms", {}), command("@home_number", {{"home_number", num(3)}}),
                          command("@compensation", {{"side", word("COMP_OFF")}}), command("@turning", {}),
                          command("@groove", {}), command("@turning", {})}),
            (std::vector<std::string>{"@call_proc: @call_proc although the PRP says gen_procs = N",
                                      "@loop: @loop although the PRP says loop_exist = N",
                                      "@call_prms: @call_prms although the PRP says gen_procs = N (only D calls with "
                                      "parameters)",
                                      "@home_number: home_number 3 is above num_homes 2",
                                      "@turning: @turning although the PRP says turning_cycle = N (the control has no "
                                      "turning cycle)",
                                      "@groove: @groove although the PRP says groove_cycle = N (the control has no "
                                      "grooving cycle)"}));
}

TEST(StructureCheck, AProgramNumberOutOfRangeIsPostedWithAWarning) {
  EXPECT_EQ(warnings_for({command("@start_of_file", {{"program_number", num(1000)}})}),
            (std::vector<std::string>{"@start_of_file: program number 1000 is outside prog_num_min .. prog_num_max "
                                      "(5000 .. 8999); posted as it is"}));
}

TEST(StructureCheck, AToolWithoutItsDirectionTurnsClockwise) {
  auto params = prp::load_source(kPrp, "s.prp", prp::Units::Metric);
  ListSource source({command("@change_tool", {{"tool_number", num(1)}}),
                     command("@change_tool", {{"tool_number", num(2)}, {"tool_direction", word("CCW")}}),
                     command("@start_tool", {{"spin", num(100)}})});
  prp::StepFilter<prp::StructureCheck> check(source, params, nullptr);
  std::vector<std::string> directions;
  for (const auto& c : drain(check)) directions.push_back(c.find("tool_direction") ? c.find("tool_direction")->text : "-");
  EXPECT_EQ(directions, (std::vector<std::string>{"CW", "CCW", "CW"}));
}

TEST(StructureCheck, LimitsAreErrors) {
  EXPECT_EQ(error_for(command("@proc", {{"label", num(100)}}, 7)),
            "command 7 (@proc): procedure label 100 is outside proc_num_min .. proc_num_max (1 .. 99)");
  EXPECT_EQ(error_for(command("@compensation", {{"side", word("COMP_LEFT")}})),
            "command 0 (@compensation): compensation COMP_LEFT on a machine without it (comp_exist = N)");
}

TEST(DefaultPositions, FillsOnlyWhatTheToolpathLeavesOpen) {
  for (auto units : {prp::Units::Metric, prp::Units::Inch}) {
    auto params = prp::load_source(kPrp, "s.prp", units);
    ListSource source({command("@start_program", {}), command("@start_program", {{"xpos", num(1)}}),
                       command("@end_program", {})});
    prp::StepFilter<prp::DefaultPositions> filter(source, params);
    auto out = drain(filter);
    EXPECT_EQ(get(out[0], "ypos"), units == prp::Units::Metric ? 200 : 7.874);
    EXPECT_EQ(get(out[0], "zpos"), units == prp::Units::Metric ? 100 : 3.937);
    EXPECT_EQ(out[1], command("@start_program", {{"xpos", num(1)}}));
    EXPECT_EQ(out[2], command("@end_program", {}));  // no dflt_end in this PRP
  }
}

}  // namespace
