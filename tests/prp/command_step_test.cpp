// Steps (the structure check, the compensation check, the rotary axes) run in one layer must give
// what each gives as a filter of its own, chained: the same commands, kinds, warnings and errors,
// on random streams that rename commands (set_dir), warn, throw, switch compensation on and off
// (the compensation check asks for arcs only while it is on) and hold commands of the post.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "prp/filters/command_step.hpp"
#include "prp/filters/compensation_check.hpp"
#include "prp/filters/rotary_axes.hpp"
#include "prp/filters/structure_check.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;
using toolpath::Command;
using toolpath::Value;

namespace {

struct Outcome {
  std::vector<Command> commands;
  std::vector<prp::CommandKind> kinds;
  std::vector<std::string> warnings;
  std::string error;
};

Outcome drain_all(prp::KindSource& source, std::vector<std::string>& warnings) {
  Outcome o;
  Command c;
  prp::CommandKind kind{};
  try {
    while (source.next_with_kind(c, kind)) {
      o.commands.push_back(c);
      o.kinds.push_back(kind);
    }
  } catch (const prp::StreamError& e) {
    o.error = e.what();
  }
  o.warnings = warnings;
  return o;
}

Command random_command(std::mt19937_64& rng, std::size_t index) {
  auto pick = [&](auto... options) {
    const double table[] = {static_cast<double>(options)...};
    return table[rng() % sizeof...(options)];
  };
  Command c;
  switch (rng() % 12) {
    case 0: c = command("@change_tool", {{"tool_diameter", num(pick(10, 4, 20))}}); break;
    case 1: c = command("@START_TOOL", {}); break;
    case 2: c = command("@compensation", {{"side", word(rng() % 3 == 0 ? "COMP_OFF" : rng() % 2 ? "COMP_LEFT" : "COMP_RIGHT")}}); break;
    case 3:
    case 4:
      c = command("@arc", {{"arc_direction", word(rng() % 2 ? "CW" : "CCW")}, {"radius", num(pick(2, 5.005, 12))}});
      break;
    case 5: c = command(rng() % 2 ? "@move_4x" : "@line_4x", {{"cpos", num(pick(350, 10, -30, 370, 720))}}); break;
    case 6: c = command("@line_5x", {{"apos", num(pick(0, 10, 80))}, {"bpos", num(pick(0, -70))}}); break;
    case 7: c = command("@move_5x", {{"apos", num(pick(0, 45))}}); break;
    case 8: c = command(rng() % 2 ? "@loop" : "@call_proc", {{"label", num(pick(3, 500))}}); break;
    case 9: c = command("@home_number", {{"home_number", num(pick(1, 3))}}); break;
    default: c = command("@line", {{"xpos", num(pick(1, 2))}}); break;
  }
  c.index = index;
  if (rng() % 8 == 0) c.depth = 2;  // the original post's own: every step leaves it alone
  return c;
}

TEST(Steps, OneLayerGivesWhatChainedFiltersGive) {
  std::mt19937_64 rng(23);
  const char* settings[] = {
      "set_dir = Y\npositive_4x_dir_only = Y\nangle_change_limit = 30\nloop_exist = N\nnum_homes = 2\n",
      "set_dir = N\nloop_exist = Y\nproc_num_max = 99\n",
      "comp_exist = N\nset_dir = Y\n",
  };
  for (int round = 0; round < 300; ++round) {
    const std::string setting = settings[round % std::size(settings)];
    auto params = prp::load_source("@pre_processor\n" + setting + "endp\n", "s.prp", prp::Units::Metric);
    std::vector<Command> in;
    for (std::size_t i = 0; i < 40; ++i) in.push_back(random_command(rng, i));

    std::vector<std::string> fused_warnings, chained_warnings;
    auto sink = [](std::vector<std::string>& into) {
      return [&into](const Command& c, const std::string& m) { into.push_back(c.name + " #" + std::to_string(c.index) + ": " + m); };
    };
    ListSource fused_in(in), chained_in(in);
    prp::Steps fused(fused_in);
    fused.add(std::make_unique<prp::StructureCheck>(params, sink(fused_warnings)));
    fused.add(std::make_unique<prp::CompensationCheck>(0.01, sink(fused_warnings)));
    fused.add(std::make_unique<prp::RotaryAxes>(params, sink(fused_warnings)));
    prp::StepFilter<prp::StructureCheck> structure(chained_in, params, prp::WarningSink(sink(chained_warnings)));
    prp::StepFilter<prp::CompensationCheck> compensation(structure, 0.01, prp::WarningSink(sink(chained_warnings)));
    prp::StepFilter<prp::RotaryAxes> rotary(compensation, params, prp::WarningSink(sink(chained_warnings)));

    const Outcome a = drain_all(fused, fused_warnings), b = drain_all(rotary, chained_warnings);
    ASSERT_EQ(a.error, b.error) << round;
    ASSERT_EQ(a.warnings, b.warnings) << round;
    ASSERT_EQ(a.kinds, b.kinds) << round;
    ASSERT_EQ(a.commands, b.commands) << round;
    for (std::size_t i = 0; i < a.commands.size(); ++i) ASSERT_EQ(a.kinds[i], prp::command_kind(a.commands[i]));
  }
}

// The compensation check asks for arcs only while compensation is on and a tool radius is known.
TEST(Steps, CompensationCheckFollowsArcsOnlyWhileItMatters) {
  prp::CompensationCheck check(0.01, {});
  EXPECT_FALSE(prp::has(check.kinds(), prp::CommandKind::arc));
  Command tool = command("@change_tool", {{"tool_diameter", num(10)}});
  Command left = command("@compensation", {{"side", word("COMP_LEFT")}});
  Command off = command("@compensation", {{"side", word("COMP_OFF")}});
  prp::CommandKind kind = prp::CommandKind::compensation;
  check.apply(left, kind);
  EXPECT_FALSE(prp::has(check.kinds(), prp::CommandKind::arc));  // no tool radius yet
  kind = prp::CommandKind::change_tool;
  check.apply(tool, kind);
  EXPECT_TRUE(prp::has(check.kinds(), prp::CommandKind::arc));
  kind = prp::CommandKind::compensation;
  check.apply(off, kind);
  EXPECT_FALSE(prp::has(check.kinds(), prp::CommandKind::arc));
}

}  // namespace
