// The toolpath side of `postproc verify`: posted commands kept in temporary files and run in machine
// order, with subroutine calls (bodies after the main program, as SolidCAM sends them), loops inside
// bodies, nested calls, redefined bodies, and bodies larger than the spool's in-memory block.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "postproc/checks/verify.hpp"
#include "prp/prp.hpp"
#include "toolpath/trace_reader.hpp"

namespace {

using postproc::verify::ExpectedMotion;
using postproc::verify::Motion;
using postproc::verify::MotionKind;

// Each rapid as "<command index>:X<x>", in the order the expansion yields them.
std::string expand(ExpectedMotion& expected, std::uint64_t max_commands = ExpectedMotion::default_max_commands) {
  auto source = expected.motion(max_commands);
  std::string out;
  Motion m;
  while (source->next(m)) {
    EXPECT_EQ(m.kind, MotionKind::Rapid);
    out += fmt::format("{}{}:X{}", out.empty() ? "" : " ", m.where, m.to.x());
  }
  return out;
}

// The motion of a job written one command a line (`@name ==> name:value ...`, the trace format's
// short form), or the error it stops with.
std::string expand(const std::string& job, std::uint64_t max_commands = ExpectedMotion::default_max_commands) {
  const prp::MachineParameters machine = prp::defaults(prp::Units::Metric);
  ExpectedMotion expected(machine);
  std::istringstream in(job);
  toolpath::TraceReader reader(in, "job.trace");
  toolpath::Command c;
  while (reader.next(c)) expected.add(c);
  try {
    return expand(expected, max_commands);
  } catch (const std::runtime_error& e) {
    return std::string("error: ") + e.what();
  }
}

struct Case {
  const char* name;
  const char* job;
  const char* motion;  // "<index>:X<x>" per rapid, or "error: ..."
};

const Case cases[] = {
    {"a body called three times, defined after the main program",
     "@rapid_move ==> xpos:1\n"                   // 0
     "@call_proc ==> label:1 proc_count:3\n"      // 1
     "@rapid_move ==> xpos:9\n"                   // 2
     "@proc ==> label:1\n"                        // 3
     "@rapid_move ==> xpos:2\n"                   // 4
     "@rapid_move ==> xpos:3\n"                   // 5
     "@end_proc ==> label:1\n",                   // 6
     "0:X1 4:X2 5:X3 4:X2 5:X3 4:X2 5:X3 2:X9"},
    {"nested calls, each repeated",
     "@call_proc ==> label:1 proc_count:2\n"      // 0
     "@proc ==> label:1\n"                        // 1
     "@rapid_move ==> xpos:1\n"                   // 2
     "@call_proc ==> label:2 proc_count:2\n"      // 3
     "@rapid_move ==> xpos:3\n"                   // 4
     "@end_proc\n"                                // 5
     "@proc ==> label:2\n"                        // 6
     "@rapid_move ==> xpos:2\n"                   // 7
     "@end_proc\n",                               // 8
     "2:X1 7:X2 7:X2 4:X3 2:X1 7:X2 7:X2 4:X3"},
    {"loops inside a body: nested, around a call, restarting on each run of the body",
     "@call_proc ==> label:1 proc_count:2\n"      // 0
     "@proc ==> label:1\n"                        // 1
     "@loop ==> loop_count:2\n"                   // 2
     "@rapid_move ==> xpos:1\n"                   // 3
     "@loop ==> loop_count:2\n"                   // 4
     "@call_proc ==> label:2\n"                   // 5
     "@end_loop\n"                                // 6
     "@end_loop\n"                                // 7
     "@end_proc\n"                                // 8
     "@proc ==> label:2\n"                        // 9
     "@rapid_move ==> xpos:2\n"                   // 10
     "@end_proc\n",                               // 11
     "3:X1 10:X2 10:X2 3:X1 10:X2 10:X2 3:X1 10:X2 10:X2 3:X1 10:X2 10:X2"},
    {"a loop in the main program around a call",
     "@loop ==> loop_count:3\n"                   // 0
     "@call_proc ==> label:5\n"                   // 1
     "@rapid_move ==> xpos:7\n"                   // 2
     "@end_loop\n"                                // 3
     "@proc ==> label:5\n"                        // 4
     "@rapid_move ==> xpos:5\n"                   // 5
     "@end_proc\n",                               // 6
     "5:X5 2:X7 5:X5 2:X7 5:X5 2:X7"},
    {"a label defined again: the later body replaces the earlier one",
     "@call_proc ==> label:1\n"                   // 0
     "@proc ==> label:1\n"                        // 1
     "@rapid_move ==> xpos:1\n"                   // 2
     "@end_proc\n"                                // 3
     "@proc ==> label:1\n"                        // 4
     "@rapid_move ==> xpos:4\n"                   // 5
     "@rapid_move ==> xpos:5\n"                   // 6
     "@end_proc\n"                                // 7
     "@call_proc ==> label:1\n",                  // 8
     "5:X4 6:X5 5:X4 6:X5"},
    {"the main program goes on between bodies; messages are not motion; count 0 runs once",
     "@rapid_move ==> xpos:1\n"                   // 0
     "@call_proc ==> label:1 proc_count:0\n"      // 1
     "@proc ==> label:1\n"                        // 2
     "@message ==> message:'body'\n"              // 3
     "@rapid_move ==> xpos:2\n"                   // 4
     "@end_proc\n"                                // 5
     "@rapid_move ==> xpos:3\n"                   // 6
     "@call_proc ==> label:2\n"                   // 7
     "@proc ==> label:2\n"                        // 8
     "@rapid_move ==> xpos:4\n"                   // 9
     "@end_proc\n",                               // 10
     "0:X1 4:X2 6:X3 9:X4"},
    {"an empty body, called",
     "@call_proc ==> label:3 proc_count:4\n@rapid_move ==> xpos:1\n@proc ==> label:3\n@end_proc\n", "1:X1"},
    {"a call to a label without a body",
     "@rapid_move ==> xpos:1\n@call_proc ==> label:7\n@proc ==> label:1\n@end_proc\n",
     "error: command #1 @call_proc: subroutine 7 has no body"},
    {"a count that is no count",
     "@call_proc ==> label:1 proc_count:1e300\n@proc ==> label:1\n@end_proc\n",
     "error: command #0 @call_proc: proc_count 1e+300 is not a count"},
    {"a body that calls itself",
     "@call_proc ==> label:1\n@proc ==> label:1\n@rapid_move ==> xpos:1\n@call_proc ==> label:1\n@end_proc\n",
     "error: command #3 @call_proc: calls nest deeper than 64"},
};

TEST(VerifyExpansion, CallsLoopsAndBodiesRunInMachineOrder) {
  for (const auto& c : cases) EXPECT_EQ(expand(c.job), c.motion) << c.name;
}

// 63 nested calls are allowed (64 frames with the main program's), 64 are not.
TEST(VerifyExpansion, CallsNestUpTo64Deep) {
  for (int depth : {63, 64}) {
    std::string job = "@call_proc ==> label:1\n";
    for (int label = 1; label <= depth; ++label) {
      job += fmt::format("@proc ==> label:{}\n", label);
      if (label < depth) job += fmt::format("@call_proc ==> label:{}\n", label + 1);
      else job += "@rapid_move ==> xpos:1\n";
      job += "@end_proc\n";
    }
    const std::string last_call = fmt::format("command #{} @call_proc", 3 * (depth - 2) + 2);  // in body 63
    EXPECT_EQ(expand(job), depth == 63 ? fmt::format("{}:X1", 3 * 63 - 1)
                                       : "error: " + last_call + ": calls nest deeper than 64")
        << depth;
  }
}

// 64 open loops in one body are allowed, the 65th is an error (an @loop never closed must not
// grow memory with the job).
TEST(VerifyExpansion, LoopsNestUpTo64Deep) {
  for (int depth : {64, 65}) {
    std::string job;
    for (int i = 0; i < depth; ++i) job += "@loop ==> loop_count:1\n";
    job += "@rapid_move ==> xpos:1\n";
    EXPECT_EQ(expand(job), depth == 64 ? "64:X1" : "error: command #64 @loop: loops nest deeper than 64") << depth;
  }
}

// Calls and loops that would run more commands than allowed stop with an error (a runaway count
// in a stream must not keep verify busy for ever); exactly the allowed number runs.
TEST(VerifyExpansion, RunawayCountsStop) {
  const std::string job = "@loop ==> loop_count:1000000000\n@rapid_move ==> xpos:1\n@end_loop\n";
  EXPECT_EQ(expand(job, 10), "error: the calls and loops run more than 10 commands: a runaway count?");
  EXPECT_EQ(expand("@loop ==> loop_count:3\n@rapid_move ==> xpos:1\n@end_loop\n", 7), "1:X1 1:X1 1:X1");
  EXPECT_EQ(expand("@loop ==> loop_count:3\n@rapid_move ==> xpos:1\n@end_loop\n", 6),
            "error: the calls and loops run more than 6 commands: a runaway count?");
}

// Bodies of many mebibytes, called alternately from a loop: the spool's reads jump between blocks
// that are on disk and the block still in memory, and every record still comes back.
TEST(VerifyExpansion, BodiesLargerThanTheSpoolBlock) {
  const prp::MachineParameters machine = prp::defaults(prp::Units::Metric);
  ExpectedMotion expected(machine);
  std::size_t index = 0;
  auto add = [&](const char* name, std::vector<std::pair<const char*, std::int64_t>> parameters) {
    toolpath::Command c;
    c.name = name;
    c.index = index++;
    for (auto& [key, value] : parameters) c.set(key, toolpath::Value::make_integer(value));
    expected.add(c);
  };
  constexpr int kBody = 40000;  // about 3 MiB of records per body
  add("@loop", {{"loop_count", 3}});
  add("@call_proc", {{"label", 1}});
  add("@call_proc", {{"label", 2}, {"proc_count", 2}});
  add("@end_loop", {});
  std::vector<std::size_t> first_of(3);
  for (std::int64_t label : {1, 2}) {
    add("@proc", {{"label", label}});
    first_of[label] = index;
    for (int i = 0; i < kBody; ++i) add("@rapid_move", {{"xpos", label * 1000000 + i}, {"ypos", 0}, {"zpos", 0}});
    add("@end_proc", {});
  }
  auto source = expected.motion();
  Motion m;
  std::size_t count = 0, wrong = 0;
  for (int run = 0; run < 3 * 3; ++run) {
    const std::int64_t label = run % 3 == 0 ? 1 : 2;
    for (int i = 0; i < kBody; ++i, ++count) {
      ASSERT_TRUE(source->next(m)) << count;
      if (m.where != first_of[label] + i || m.to.x() != static_cast<double>(label * 1000000 + i)) ++wrong;
    }
  }
  EXPECT_FALSE(source->next(m));
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(count, 9u * kBody);
}

}  // namespace
