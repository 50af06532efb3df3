// The rotary-axis switches (prp/filters/rotary_axes.hpp): set_dir turns 4-axis moves into their
// _dir form with normalised C; positive_4x_dir_only and angle_change_limit check the stream.
#include <gtest/gtest.h>

#include "prp/filters/rotary_axes.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;

namespace {

struct Run {
  std::vector<toolpath::Command> out;
  std::vector<std::string> warnings;
};

Run run(const char* settings, std::vector<toolpath::Command> in) {
  auto params = prp::load_source(std::string("@pre_processor\n") + settings + "endp\n", "r.prp", prp::Units::Metric);
  ListSource source(std::move(in));
  Run r;
  prp::StepFilter<prp::RotaryAxes> filter(source, params, [&](const toolpath::Command& c, const std::string& m) {
    r.warnings.push_back(c.name + ": " + m);
  });
  r.out = drain(filter);
  return r;
}

TEST(RotaryAxes, SetDirNormalisesCAndGivesTheDirection) {
  const auto r = run("set_dir = Y\n", {command("@move_4x", {{"cpos", num(350)}}), command("@line_4x", {{"cpos", num(370)}}),
                                       command("@line_4x", {{"cpos", num(-30)}}),
                                       command("@line4x_dir", {{"cpos", num(10)}, {"dir4x", word("CW")}})});
  ASSERT_EQ(r.out.size(), 4u);
  EXPECT_EQ(r.out[0], command("@move4x_dir", {{"cpos", num(350)}, {"dc", num(0)}, {"dir4x", word("CCW")}}));
  EXPECT_EQ(r.out[1], command("@line4x_dir", {{"cpos", num(10)}, {"dc", num(20)}, {"dir4x", word("CCW")}}));
  EXPECT_EQ(r.out[2], command("@line4x_dir", {{"cpos", num(330)}, {"dc", num(-400)}, {"dir4x", word("CW")}}));
  // SolidCAM's own _dir commands pass as they are
  EXPECT_EQ(r.out[3], command("@line4x_dir", {{"cpos", num(10)}, {"dir4x", word("CW")}}));
  EXPECT_TRUE(r.warnings.empty());
  // Without set_dir nothing changes
  const auto plain = run("", {command("@line_4x", {{"cpos", num(370)}})});
  EXPECT_EQ(plain.out[0], command("@line_4x", {{"cpos", num(370)}}));
}

TEST(RotaryAxes, PositiveOnlyWarnsOfACutTurningBack) {
  const auto r = run("positive_4x_dir_only = Y\n",
                     {command("@move_4x", {{"cpos", num(90)}}), command("@move_4x", {{"cpos", num(0)}}),
                      command("@line_4x", {{"cpos", num(30)}}), command("@line_4x", {{"cpos", num(20)}}),
                      command("@line_4x", {{"cpos", num(10)}})});
  // positioning back is fine; the first cut back is reported once
  EXPECT_EQ(r.warnings, (std::vector<std::string>{"@line_4x: @line_4x turns C back by 10 degrees although the PRP says "
                                                  "positive_4x_dir_only = Y: SolidCAM computes such cuts turning forward "
                                                  "only"}));
  EXPECT_TRUE(run("", {command("@line_4x", {{"cpos", num(30)}}), command("@line_4x", {{"cpos", num(20)}})}).warnings.empty());
}

TEST(RotaryAxes, AngleChangeLimitWarnsOfAJumpWithinACut) {
  const auto r = run("angle_change_limit = 100\n",
                     {command("@move_5x", {{"apos", num(0)}, {"bpos", num(10)}}),
                      command("@line_5x", {{"apos", num(20)}, {"bpos", num(170)}}),
                      command("@move_5x", {{"apos", num(200)}, {"bpos", num(170)}})});
  EXPECT_EQ(r.warnings, (std::vector<std::string>{"@line_5x: @line_5x turns B by 160 degrees within a cut, more than "
                                                  "angle_change_limit = 100: SolidCAM retracts out of the cut for such a "
                                                  "change, this stream does not"}));
}

}  // namespace
