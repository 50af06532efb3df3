// The minimal PRP reader and the structure bookkeeping that completes @end_proc / @end_loop.
#include <gtest/gtest.h>

#include "postproc/prp_settings.hpp"
#include "postproc/structure.hpp"
#include "toolpath/error.hpp"

namespace {

TEST(PrpSettings, ReadsTheManualsFanucPrp) {
  auto prp = postproc::PrpSettings::load("golden/solidcam-fanuc/fanuc.prp");
  EXPECT_EQ(prp.file_extension(), "TAP");
  EXPECT_EQ(prp.value("proc_num_dflt"), "1");
  EXPECT_EQ(prp.value("PROC_NUM_DFLT"), "1");
  EXPECT_EQ(prp.value("dflt_start"), "0.0000 200.0000 100.0000, 0.0000 7.8740 3.9370");
  EXPECT_FALSE(prp.value("no_such_key").has_value());
  EXPECT_EQ(prp.drill_type_names(),
            (std::vector<std::string>{"Drilling", "F_Drill", "Peck", "Tapping", "Boring", "R_Boring", "F_Boring"}));
  auto cycles = prp.drill_cycle_parameters();
  ASSERT_EQ(cycles.size(), 7u);
  EXPECT_EQ(cycles[1].second, std::vector<std::string>{"Delay"});
  EXPECT_TRUE(cycles[0].second.empty());
}

TEST(PrpSettings, OldDrillFormAndErrors) {
  auto prp = postproc::PrpSettings::parse("drill_type = Peck Y Delay Q_Peck ; comment\n", "x.prp");
  auto cycles = prp.drill_cycle_parameters();
  ASSERT_EQ(cycles.size(), 1u);
  EXPECT_EQ(cycles[0].first, "Peck");
  EXPECT_EQ(cycles[0].second, (std::vector<std::string>{"Delay", "Q_Peck"}));
  try {
    postproc::PrpSettings::parse("@pre_processor\n  gen_procs Y\n", "x.prp");
    ADD_FAILURE();
  } catch (const toolpath::InputError& e) {
    EXPECT_STREQ(e.what(), "x.prp:2:3: expected `name = value`, found `gen_procs Y`");
  }
}

toolpath::Command make(const char* name, std::vector<toolpath::Parameter> parameters = {}) {
  toolpath::Command c;
  c.name = name;
  c.parameters = std::move(parameters);
  return c;
}

TEST(ProgramStructure, CompletesEndProcAndEndLoop) {
  postproc::ProgramStructure s;
  using toolpath::Value;
  auto call_job = make("@call_proc", {{"label", Value::make_integer(1)}});
  auto proc1 = make("@proc", {{"label", Value::make_integer(1)}});
  auto call_inner = make("@call_proc", {{"label", Value::make_integer(4)}});
  auto end1 = make("@end_proc");
  auto proc4 = make("@proc", {{"label", Value::make_integer(4)}});
  auto loop = make("@loop", {{"label", Value::make_integer(7)}, {"loop_count", Value::make_integer(3)}});
  auto end_loop = make("@end_loop");
  auto end4 = make("@end_proc");
  for (auto* c : {&call_job, &proc1, &call_inner, &end1, &proc4, &loop, &end_loop, &end4}) s.before(*c);
  EXPECT_EQ(*end1.find("label"), Value::make_integer(1));
  EXPECT_EQ(*end1.find("end_of_job"), Value::make_logical(true));
  EXPECT_EQ(*end4.find("label"), Value::make_integer(4));
  EXPECT_EQ(*end4.find("end_of_job"), Value::make_logical(false)) << "called from a subroutine, not a job";
  EXPECT_EQ(*loop.find("loop_level"), Value::make_integer(1));
  EXPECT_EQ(*end_loop.find("label"), Value::make_integer(7));
  EXPECT_EQ(*end_loop.find("loop_count"), Value::make_integer(3));
  EXPECT_FALSE(s.in_subroutine());
}

}  // namespace
