// Subroutine generation on a flat toolpath: a profile job and two drill jobs over the same holes,
// under gen_procs Y and C with and without drill_proc; a structured toolpath passes unchanged.
#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <string>
#include <vector>

#include "prp/filters/procedure_generation.hpp"
#include "prp/filters/structure_check.hpp"
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

prp::MachineParameters machine(const std::string& settings) {
  return prp::load_source("@pre_processor\n" + settings + "proc_num_dflt = 7\nendp\n", "g.prp", prp::Units::Metric);
}

std::vector<std::string> run(const std::string& settings, std::vector<Command> in) {
  auto params = machine(settings);
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

// Procedures in two passes: a forecast from the skim of the job (its basic motions inside jobs
// left out, as TraceReader::skim_job_motions() reads it), then the whole job streamed against it.
// Wherever the forecast is taken, the commands must be those of one pass, field for field.

bool named(const Command& c, const char* name) { return toolpath::iequals(c.name, name); }

std::vector<Command> skim(const std::vector<Command>& in) {
  std::vector<Command> kept;
  bool in_job = false, leading = false;
  for (const Command& c : in) {
    if (in_job && !leading && (named(c, "@line") || named(c, "@arc") || named(c, "@rapid_move"))) continue;
    kept.push_back(c);
    if (named(c, "@start_of_job")) in_job = leading = true;
    else if (named(c, "@end_of_job")) in_job = leading = false;
    else if (!named(c, "@change_tool")) leading = false;
  }
  return kept;
}

std::vector<Command> one_pass(const std::string& settings, const std::vector<Command>& in) {
  auto params = machine(settings);
  ListSource source(in);
  prp::ProcedureGeneration filter(source, params);
  return drain(filter);
}

// The second pass over `in` with the forecast of `forecast_from`; nullopt when there is none.
std::optional<std::vector<Command>> two_passes(const std::string& settings, const std::vector<Command>& forecast_from,
                                               const std::vector<Command>& in) {
  auto params = machine(settings);
  ListSource skimmed(skim(forecast_from));
  auto forecast = prp::ProcedureGeneration::forecast(skimmed, params);
  if (!forecast) return std::nullopt;
  ListSource source(in);
  prp::ProcedureGeneration filter(source, params, std::move(*forecast));
  return drain(filter);
}

std::vector<Command> numbered(std::vector<Command> in) {
  for (std::size_t i = 0; i < in.size(); ++i) in[i].index = i;
  return in;
}

std::vector<Command> edited(void (*edit)(std::vector<Command>&)) {
  auto in = flat_job();
  edit(in);
  return numbered(std::move(in));
}

struct TwoPassCase {
  const char* name;
  const char* settings;
  std::vector<Command> in;
  bool forecast;  // whether the job may be done in two passes
};

std::vector<TwoPassCase> two_pass_cases() {
  return {
      {"EveryJob", "gen_procs = Y\ndrill_proc = N\n", flat_job(), true},
      {"SharedPointsNeedOnePass", "gen_procs = Y\ndrill_proc = Y\n", flat_job(), false},
      {"LeafProcedures", "gen_procs = C\ndrill_proc = N\n", flat_job(), true},
      {"InlineJobsNeedOnePass", "gen_procs = C\ndrill_proc = Y\n", flat_job(), false},
      {"ToolChangeBeforeTheJob", "gen_procs = Y\n", edited([](auto& in) {
         std::swap(in[3], in[4]);
         std::swap(in[8], in[9]);
       }), true},
      {"PointsNotShared", "gen_procs = Y\ndrill_proc = Y\n", edited([](auto& in) { in[18].set("xpos", num(21)); }), true},
      {"NoEndOfFile", "gen_procs = Y\n", edited([](auto& in) { in.pop_back(); }), true},
      {"EndsInsideAJob", "gen_procs = Y\n", edited([](auto& in) { in.resize(7); }), true},
      {"EndsRightAfterAJobsToolChange", "gen_procs = Y\n", edited([](auto& in) { in.resize(10); }), true},
      {"SomethingAfterTheEndOfFile", "gen_procs = Y\n", edited([](auto& in) { in.push_back(command("@message", {})); }),
       false},
      {"CommandsBetweenJobs", "gen_procs = Y\n", edited([](auto& in) {
         in.insert(in.begin() + 8, command("@rapid_move", {{"xpos", num(50)}}));
         in.insert(in.begin() + 8, command("@message", {{"message", text("between")}}));
       }), true},
      {"TwoToolChangesOpenAJob", "gen_procs = Y\n", edited([](auto& in) {
         in.insert(in.begin() + 5, command("@change_tool", {{"tool_number", num(3)}}));
       }), true},
      {"ToolChangeInsideABody", "gen_procs = Y\n", edited([](auto& in) {
         in.insert(in.begin() + 6, command("@change_tool", {{"tool_number", num(3)}}));
       }), true},
      {"Structured", "gen_procs = Y\n",
       numbered({command("@start_of_file", {}), command("@call_proc", {{"label", num(1)}}), command("@end_program", {}),
                 command("@proc", {{"label", num(1)}}), command("@line", {{"xpos", num(2)}}),
                 command("@end_proc", {{"label", num(1)}}), command("@end_of_file", {})}),
       false},
      {"Empty", "gen_procs = Y\n", {}, true},
  };
}

TEST(GenerationInTwoPasses, SameCommandsAsOnePass) {
  for (const TwoPassCase& c : two_pass_cases()) {
    SCOPED_TRACE(c.name);
    const auto two = two_passes(c.settings, c.in, c.in);
    ASSERT_EQ(two.has_value(), c.forecast);
    if (!two) continue;
    const auto one = one_pass(c.settings, c.in);
    std::vector<std::string> a, b;
    for (const auto& x : one) a.push_back(describe(x));
    for (const auto& x : *two) b.push_back(describe(x));
    EXPECT_EQ(b, a);
    EXPECT_TRUE(*two == one);  // every field, not only what describe() shows
  }
}

// Random flat toolpaths: jobs with and without opening tool changes, motions, drill cycles over a
// few holes (so that some cycles share their points), commands between jobs.
std::vector<Command> random_toolpath(std::mt19937& rng) {
  std::vector<Command> in{command("@start_of_file", {{"program_number", num(1)}}), command("@start_program", {})};
  const int jobs = static_cast<int>(rng() % 5);
  for (int j = 0; j < jobs; ++j) {
    if (rng() % 3 == 0) in.push_back(command("@rapid_move", {{"xpos", num(rng() % 9)}}));
    if (rng() % 4 == 0) in.push_back(command("@change_tool", {{"tool_number", num(rng() % 3)}}));
    in.push_back(command("@start_of_job", {{"job_name", text(rng() % 2 ? "A" : "B")}}));
    for (int t = static_cast<int>(rng() % 3); t > 0; --t) in.push_back(command("@change_tool", {{"tool_number", num(rng() % 3)}}));
    for (int b = static_cast<int>(rng() % 8); b > 0; --b) {
      switch (rng() % 5) {
        case 0: in.push_back(command("@line", {{"xpos", num(rng() % 9)}})); break;
        case 1: in.push_back(command("@arc", {{"xpos", num(rng() % 9)}})); break;
        case 2: in.push_back(command("@rapid_move", {{"xpos", num(rng() % 9)}})); break;
        case 3: in.push_back(command("@change_tool", {{"tool_number", num(rng() % 3)}})); break;
        default:
          in.push_back(command("@drill", {{"drill_type", word("Peck")}}));
          for (int p = 1 + static_cast<int>(rng() % 2); p > 0; --p)
            in.push_back(command("@drill_point", {{"xpos", num(rng() % 2)}}));
          if (rng() % 8) in.push_back(command("@end_drill", {}));
      }
    }
    if (rng() % 8) in.push_back(command("@end_of_job", {}));
  }
  if (rng() % 4) in.push_back(command("@end_program", {}));
  if (rng() % 4) in.push_back(command("@end_of_file", {}));
  return numbered(std::move(in));
}

TEST(GenerationInTwoPasses, RandomToolpaths) {
  const char* settings[] = {"gen_procs = Y\ndrill_proc = N\n", "gen_procs = Y\ndrill_proc = Y\n",
                            "gen_procs = C\ndrill_proc = Y\n", "gen_procs = C\ndrill_proc = N\n"};
  std::mt19937 rng(20261128);
  int forecast = 0;
  for (int round = 0; round < 3000; ++round) {
    const auto in = random_toolpath(rng);
    const char* s = settings[rng() % std::size(settings)];
    const auto two = two_passes(s, in, in);
    if (!two) continue;
    ++forecast;
    ASSERT_TRUE(*two == one_pass(s, in)) << "round " << round;
  }
  EXPECT_GT(forecast, 1000);  // most of them are done in two passes
}

// Default positions look at nothing but the command they fill, so the chain runs them before
// procedure generation (in one layer with the checks): on random flat toolpaths with @start_program
// and @end_program, with and without a position, in and between jobs, both orders give the same.
TEST(ProcedureGeneration, DefaultPositionsBeforeOrAfterGiveTheSame) {
  const char* settings[] = {"gen_procs = Y\ndrill_proc = Y\n", "gen_procs = C\ndrill_proc = Y\n"};
  std::mt19937 rng(28);
  for (int round = 0; round < 1000; ++round) {
    std::vector<Command> in;
    for (Command& c : random_toolpath(rng)) {
      in.push_back(std::move(c));
      if (rng() % 6 == 0) {
        Command program = command(rng() % 2 ? "@start_program" : "@END_PROGRAM", {});
        if (rng() % 2) program.set("zpos", num(5));
        in.push_back(std::move(program));
      }
    }
    in = numbered(std::move(in));
    auto params = machine(std::string(settings[round % 2]) + "dflt_start = 1 2 3, 0.1 0.2 0.3\ndflt_end = 4 5 6, 0.4 0.5 0.6\n");
    ListSource after_in(in), before_in(in);
    prp::ProcedureGeneration after_generation(after_in, params);
    prp::StepFilter<prp::DefaultPositions> after(after_generation, params);
    prp::StepFilter<prp::DefaultPositions> before(before_in, params);
    prp::ProcedureGeneration before_generation(before, params);
    std::string after_error, before_error;
    std::vector<Command> a, b;
    try {
      a = drain(after);
    } catch (const prp::StreamError& e) {
      after_error = e.what();
    }
    try {
      b = drain(before_generation);
    } catch (const prp::StreamError& e) {
      before_error = e.what();
    }
    ASSERT_EQ(after_error, before_error) << round;
    ASSERT_TRUE(a == b) << round;
  }
}

// A job that differs from its forecast outside the bodies stops the second pass; inside a body
// it is streamed as it comes, which is the point.
TEST(GenerationInTwoPasses, DifferencesFromTheForecast) {
  const std::string settings = "gen_procs = Y\n";
  const auto base = flat_job();
  auto mismatch = [&](void (*edit)(std::vector<Command>&)) {
    try {
      two_passes(settings, base, edited(edit));
    } catch (const prp::ForecastMismatch& e) {
      return std::string(e.what());
    }
    return std::string("no mismatch");
  };
  EXPECT_EQ(mismatch([](auto& in) { in[1].set("tool_number", num(3)); }),
            "command #1 @def_tool where the forecast has #1 @def_tool");
  EXPECT_EQ(mismatch([](auto& in) { in.resize(15); }), "the job ended before its forecast");
  EXPECT_EQ(mismatch([](auto& in) {
              const std::vector<Command> d2(in.begin() + 15, in.begin() + 21);
              in.insert(in.begin() + 21, d2.begin(), d2.end());  // D2 once more
            }),
            "command #21 @start_of_job where the forecast has #21 @end_program");
  EXPECT_EQ(mismatch([](auto& in) { in.insert(in.begin() + 5, command("@change_tool", {{"tool_number", num(1)}})); }),
            "command #5 @change_tool: more tool changes open the job than forecast");
  EXPECT_EQ(mismatch([](auto& in) { in[12].set("ypos", num(6)); }), "a drill cycle differs from the forecast");
  EXPECT_EQ(mismatch([](auto& in) { in[21] = command("@proc", {{"label", num(3)}}); }),
            "@proc in a job forecast without it");

  const auto moved = edited([](auto& in) { in[6].set("xpos", num(3)); });
  EXPECT_TRUE(*two_passes(settings, base, moved) == one_pass(settings, moved));
}

}  // namespace
