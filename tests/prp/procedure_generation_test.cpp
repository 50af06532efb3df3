// Subroutine generation on a flat toolpath: a profile job and two drill jobs over the same holes,
// under gen_procs Y and C with and without drill_proc; a structured toolpath passes unchanged.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "prp/filters/procedure_generation.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;
using toolpath::Command;
using toolpath::Value;

namespace {

Value text(const char* t) { return Value::make_string(t); }

std::vector<Command> flat_job() {
  std::vector<Command> c{
      command("@start_of_file", {{"program_number", num(5000)}}),
      command("@def_tool", {{"tool_number", num(1)}}),
      command("@start_program", {}),
      command("@start_of_job", {{"job_name", text("P1")}, {"job_type", text("profile")}}),
      command("@change_tool", {{"tool_number", num(1)}}),
      command("@rapid_move", {{"xpos", num(1)}}),
      command("@line", {{"xpos", num(2)}}),
      command("@end_of_job", {}),
      command("@start_of_job", {{"job_name", text("D1")}}),
      command("@change_tool", {{"tool_number", num(2)}}),
      command("@drill", {{"drill_type", word("Peck")}}),
      command("@drill_point", {{"xpos", num(10)}, {"ypos", num(5)}}),
      command("@drill_point", {{"xpos", num(20)}, {"ypos", num(5)}}),
      command("@end_drill", {}),
      command("@end_of_job", {}),
      command("@start_of_job", {{"job_name", text("D2")}}),
      command("@drill", {{"drill_type", word("Tapping")}}),
      command("@drill_point", {{"xpos", num(10)}, {"ypos", num(5)}}),
      command("@drill_point", {{"xpos", num(20)}, {"ypos", num(5)}}),
      command("@end_drill", {}),
      command("@end_of_job", {}),
      command("@end_program", {}),
      command("@end_of_file", {}),
  };
  for (std::size_t i = 0; i < c.size(); ++i) c[i].index = i;
  return c;
}

// One line per command: its name, index and the values that tell the structure apart.
std::string describe(const Command& c) {
  std::string s = c.name + " #" + std::to_string(c.index);
  for (const char* p : {"label", "message", "job_name", "drill_type", "xpos", "tool_number", "end_of_job",
                        "first_proc_number", "last_proc_number", "first_user_proc"}) {
    const Value* v = c.find(p);
    if (!v) continue;
    s += std::string(" ") + p + "=";
    if (v->kind == toolpath::ValueKind::Logical) s += v->logical ? "T" : "F";
    else if (v->kind == toolpath::ValueKind::String || v->kind == toolpath::ValueKind::Enum) s += v->text;
    else s += std::to_string(static_cast<long long>(v->as_number()));
  }
  return s;
}

std::vector<std::string> run(const std::string& settings, std::vector<Command> in) {
  auto params = prp::load_source("@pre_processor\n" + settings + "proc_num_dflt = 7\nendp\n", "g.prp",
                                 prp::Units::Metric);
  ListSource source(std::move(in));
  prp::ProcedureGeneration filter(source, params);
  std::vector<std::string> out;
  for (const auto& c : drain(filter)) out.push_back(describe(c));
  return out;
}

struct Case {
  const char* name;
  const char* settings;
  std::vector<std::string> expected;
};

const Case kCases[] = {
    {"EveryJobAProcedure",
     "gen_procs = Y\ndrill_proc = N\n",
     {"@start_of_file #0 first_proc_number=7 last_proc_number=9 first_user_proc=10", "@def_tool #1 tool_number=1",
      "@start_program #2", "@change_tool #4 tool_number=1", "@call_proc #3 label=7 message=P1 job_name=P1 tool_number=1",
      "@change_tool #9 tool_number=2", "@call_proc #8 label=8 message=D1 job_name=D1 tool_number=2",
      "@call_proc #15 label=9 message=D2 job_name=D2 tool_number=2", "@end_program #21",
      // bodies after the main program, in label order
      "@proc #3 label=7", "@start_of_job #3 job_name=P1 tool_number=1", "@rapid_move #5 xpos=1", "@line #6 xpos=2",
      "@end_of_job #7", "@end_proc #7 label=7 end_of_job=T", "@proc #8 label=8", "@start_of_job #8 job_name=D1 tool_number=2",
      "@drill #10 drill_type=Peck", "@drill_point #11 xpos=10", "@drill_point #12 xpos=20", "@end_drill #13",
      "@end_of_job #14", "@end_proc #14 label=8 end_of_job=T", "@proc #15 label=9", "@start_of_job #15 job_name=D2 tool_number=2", "@drill #16 drill_type=Tapping", "@drill_point #17 xpos=10", "@drill_point #18 xpos=20", "@end_drill #19",
      "@end_of_job #20", "@end_proc #20 label=9 end_of_job=T", "@end_of_file #22"}},
    {"SharedDrillPoints",
     "gen_procs = Y\ndrill_proc = Y\n",
     {"@start_of_file #0 first_proc_number=7 last_proc_number=10 first_user_proc=11", "@def_tool #1 tool_number=1",
      "@start_program #2", "@change_tool #4 tool_number=1", "@call_proc #3 label=7 message=P1 job_name=P1 tool_number=1",
      "@change_tool #9 tool_number=2", "@call_proc #8 label=8 message=D1 job_name=D1 tool_number=2",
      "@call_proc #15 label=9 message=D2 job_name=D2 tool_number=2", "@end_program #21", "@proc #3 label=7",
      "@start_of_job #3 job_name=P1 tool_number=1", "@rapid_move #5 xpos=1", "@line #6 xpos=2", "@end_of_job #7",
      "@end_proc #7 label=7 end_of_job=T", "@proc #8 label=8", "@start_of_job #8 job_name=D1 tool_number=2",
      "@drill #10 drill_type=Peck", "@call_proc #10 label=10", "@end_of_job #14", "@end_proc #14 label=8 end_of_job=T",
      "@proc #15 label=9", "@start_of_job #15 job_name=D2 tool_number=2", "@drill #16 drill_type=Tapping", "@call_proc #16 label=10",
      "@end_of_job #20", "@end_proc #20 label=9 end_of_job=T",
      // the shared point list, once, with the cycle's end
      "@proc #10 label=10", "@drill_point #11 xpos=10", "@drill_point #12 xpos=20", "@end_drill #13",
      "@end_proc #13 label=10 end_of_job=F", "@end_of_file #22"}},
    {"OnlyLeafProcedures",
     "gen_procs = C\ndrill_proc = Y\n",
     {"@start_of_file #0 first_proc_number=7 last_proc_number=8 first_user_proc=9", "@def_tool #1 tool_number=1",
      "@start_program #2", "@change_tool #4 tool_number=1", "@call_proc #3 label=7 message=P1 job_name=P1 tool_number=1",
      // the drill jobs call the point list, so they stay inline
      "@start_of_job #8 job_name=D1", "@change_tool #9 tool_number=2", "@drill #10 drill_type=Peck",
      "@call_proc #10 label=8", "@end_of_job #14", "@start_of_job #15 job_name=D2", "@drill #16 drill_type=Tapping",
      "@call_proc #16 label=8", "@end_of_job #20", "@end_program #21", "@proc #3 label=7",
      "@start_of_job #3 job_name=P1 tool_number=1", "@rapid_move #5 xpos=1", "@line #6 xpos=2", "@end_of_job #7",
      "@end_proc #7 label=7 end_of_job=T", "@proc #10 label=8", "@drill_point #11 xpos=10", "@drill_point #12 xpos=20",
      "@end_drill #13", "@end_proc #13 label=8 end_of_job=F", "@end_of_file #22"}},
};

class Generation : public ::testing::TestWithParam<Case> {};

TEST_P(Generation, ExactStream) { EXPECT_EQ(run(GetParam().settings, flat_job()), GetParam().expected); }

INSTANTIATE_TEST_SUITE_P(Cases, Generation, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// SolidCAM sends a job's tool change before its @start_of_job (docs/parity.md, "Command order"):
// the tool change stays in the main program before the call, and each body names its job's tool,
// a job without a tool change of its own the one in the spindle.
TEST(Generation, ToolChangeBeforeTheJobAsSolidCamSendsIt) {
  auto in = flat_job();
  std::swap(in[3], in[4]);  // P1: @change_tool, @start_of_job
  std::swap(in[8], in[9]);  // D1
  std::vector<std::string> calls, starts;
  for (const std::string& line : run("gen_procs = Y\n", in)) {
    if (line.rfind("@call_proc", 0) == 0 || line.rfind("@change_tool", 0) == 0) calls.push_back(line);
    if (line.rfind("@start_of_job", 0) == 0) starts.push_back(line);
  }
  EXPECT_EQ(calls, (std::vector<std::string>{"@change_tool #4 tool_number=1",
                                             "@call_proc #3 label=7 message=P1 job_name=P1 tool_number=1",
                                             "@change_tool #9 tool_number=2",
                                             "@call_proc #8 label=8 message=D1 job_name=D1 tool_number=2",
                                             "@call_proc #15 label=9 message=D2 job_name=D2 tool_number=2"}));
  EXPECT_EQ(starts, (std::vector<std::string>{"@start_of_job #3 job_name=P1 tool_number=1",
                                              "@start_of_job #8 job_name=D1 tool_number=2",
                                              "@start_of_job #15 job_name=D2 tool_number=2"}));
}

TEST(Generation, DifferentPointsAreNotShared) {
  auto in = flat_job();
  in[18].set("xpos", num(21));
  auto out = run("gen_procs = Y\ndrill_proc = Y\n", in);
  EXPECT_EQ(out, run("gen_procs = Y\ndrill_proc = N\n", in));
}

TEST(Generation, StructuredToolpathPassesUnchanged) {
  std::vector<Command> in{command("@start_of_file", {}), command("@call_proc", {{"label", num(1)}}),
                          command("@end_program", {}), command("@proc", {{"label", num(1)}}),
                          command("@start_of_job", {{"job_name", text("P1")}}), command("@line", {{"xpos", num(2)}}),
                          command("@end_proc", {{"label", num(1)}}), command("@end_of_file", {})};
  std::vector<std::string> expected;
  for (const auto& c : in) expected.push_back(describe(c));
  EXPECT_EQ(run("gen_procs = Y\n", in), expected);
  EXPECT_EQ(run("gen_procs = Y\n", {}), std::vector<std::string>{});
}

// A cycle names its turning geometry by label, in the same label space as subroutines: the jobs'
// subroutines take the numbers the stream's geometry does not use (labels 7 and 9 here).
TEST(Generation, JobsSkipTheLabelsOfTurningGeometry) {
  std::vector<Command> in{command("@start_of_file", {}),
                          command("@start_of_job", {{"job_name", text("ROUGH")}}),
                          command("@turning", {{"label", num(7)}}),
                          command("@turn_proc", {{"label", num(7)}}),
                          command("@line", {{"xpos", num(2)}}),
                          command("@turn_endproc", {{"label", num(7)}}),
                          command("@end_of_job", {}),
                          command("@start_of_job", {{"job_name", text("THREAD")}}),
                          command("@thread", {{"label", num(9)}}),
                          command("@end_of_job", {}),
                          command("@start_of_job", {{"job_name", text("FACE")}}),
                          command("@line", {{"xpos", num(3)}}),
                          command("@end_of_job", {}),
                          command("@end_program", {}),
                          command("@end_of_file", {})};
  for (std::size_t i = 0; i < in.size(); ++i) in[i].index = i;
  std::vector<std::string> calls;
  for (const auto& line : run("gen_procs = Y\n", in))
    if (line.rfind("@call_proc", 0) == 0) calls.push_back(line);
  EXPECT_EQ(calls, (std::vector<std::string>{"@call_proc #1 label=8 message=ROUGH job_name=ROUGH",
                                             "@call_proc #7 label=10 message=THREAD job_name=THREAD",
                                             "@call_proc #10 label=11 message=FACE job_name=FACE"}));
}

std::string error_of(const std::string& settings, std::vector<Command> in) {
  try {
    run(settings, std::move(in));
  } catch (const prp::StreamError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Generation, Errors) {
  EXPECT_EQ(error_of("gen_procs = Y\nproc_num_min = 1\nproc_num_max = 8\n", flat_job()),
            "command 15 (@proc): procedure label 9 is outside proc_num_min .. proc_num_max (1 .. 8)");
  auto mixed = flat_job();
  mixed[21] = command("@call_proc", {{"label", num(3)}}, 21);
  EXPECT_EQ(error_of("gen_procs = Y\n", mixed),
            "command 21 (@call_proc): the toolpath mixes inline jobs with procedures or loops, so gen_procs cannot "
            "restructure it");
}

}  // namespace
