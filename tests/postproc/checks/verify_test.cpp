// `postproc verify`: normalisation and comparison of motion events, a post that gets arcs wrong
// caught at the right command and NC line, and `run --dialect pikocnc` posting G-code again.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "postproc/cli/cli.hpp"
#include "tests/support/cli_run.hpp"
#include "postproc/checks/verify.hpp"

namespace {

using postproc::verify::Motion;
using postproc::verify::MotionKind;

class VectorSource final : public postproc::verify::MotionSource {
public:
  explicit VectorSource(std::vector<Motion> m) : motions_(std::move(m)) {}
  bool next(Motion& out) override {
    if (at_ == motions_.size()) return false;
    out = motions_[at_++];
    return true;
  }

private:
  std::vector<Motion> motions_;
  std::size_t at_ = 0;
};

Motion move(MotionKind kind, Eigen::Vector3d from, Eigen::Vector3d to, double feed = 0.0, std::size_t where = 0) {
  Motion m;
  m.kind = kind;
  m.from = from;
  m.to = to;
  m.from_known = true;
  m.feed = feed;
  m.where = where;
  return m;
}

Motion spindle(int state, double speed) {
  Motion m;
  m.kind = MotionKind::Spindle;
  m.spindle = state;
  m.speed = speed;
  return m;
}

std::vector<std::string> normalise(std::vector<Motion> in) {
  VectorSource source(std::move(in));
  auto n = postproc::verify::normalised(source, {});
  std::vector<std::string> out;
  Motion m;
  while (n->next(m)) out.push_back(postproc::verify::describe(m));
  return out;
}

TEST(VerifyNormalise, JoinsCollinearMovesDropsTinyOnesAndRepeatedSpindleStates) {
  const Eigen::Vector3d o(0, 0, 10), a(0, 0, 2), b(0, 0, 1), c(0, 0, 1.0004), d(5, 0, 1);
  auto out = normalise({
      spindle(1, 3000), spindle(1, 3000),                  // the second changes nothing
      move(MotionKind::Rapid, o, a), move(MotionKind::Rapid, a, b),  // one rapid down to Z1
      move(MotionKind::Feed, b, c, 100),                   // 0.0004 mm: dropped
      move(MotionKind::Feed, c, d, 100), move(MotionKind::Feed, d, {9, 0, 1}, 200),  // feeds differ
      spindle(0, 0),
  });
  EXPECT_EQ(out, (std::vector<std::string>{"spindle CW S3000", "rapid to X0.0000 Y0.0000 Z1.0000",
                                           "feed to X5.0000 Y0.0000 Z1.0000 F100", "feed to X9.0000 Y0.0000 Z1.0000 F200",
                                           "spindle off"}));
}

TEST(VerifyCompare, ReportsTheFirstDifferenceOfEachKind) {
  namespace geo = toolpath::geometry;
  const Eigen::Vector3d s(10, 0, 0), e(0, 10, 0), centre(0, 0, 0);
  auto arc = [&](geo::Direction dir, Eigen::Vector3d c) {
    Motion m = move(MotionKind::Arc, s, e, 100);
    m.arc = geo::make_arc(s, e, c, geo::Plane::XY, dir, std::nullopt);
    return m;
  };
  Motion tool;
  tool.kind = MotionKind::Tool;
  tool.tool = 3;
  Motion other_tool = tool;
  other_tool.tool = 4;
  struct Case {
    Motion expected, actual;
    const char* what;  // empty: equal
  } cases[] = {
      {move(MotionKind::Rapid, s, e), move(MotionKind::Rapid, s, e), ""},
      {move(MotionKind::Rapid, s, e), move(MotionKind::Rapid, s, {0, 10.001, 0}), ""},  // within 0.001
      {move(MotionKind::Rapid, s, e), move(MotionKind::Rapid, s, {0, 10.002, 0}), "end point differs in Y by 0.0020 mm"},
      {move(MotionKind::Rapid, s, e), move(MotionKind::Feed, s, e, 100), "expected a rapid, the NC program makes a feed"},
      {move(MotionKind::Feed, s, e, 100), move(MotionKind::Feed, s, e, 120), "feed 120 instead of 100"},
      {arc(geo::Direction::CCW, centre), arc(geo::Direction::CCW, centre), ""},
      {arc(geo::Direction::CCW, centre), arc(geo::Direction::CW, centre), "arc turns the other way"},
      {arc(geo::Direction::CCW, centre), arc(geo::Direction::CCW, {0.1, 0.1, 0}), "arc centre differs by 0.1414 mm"},
      {tool, other_tool, "tool 4 instead of 3"},
      {spindle(1, 3000), spindle(-1, 3000), "spindle spindle CCW S3000 instead of spindle CW S3000"},
  };
  for (const auto& c : cases) {
    VectorSource expected({move(MotionKind::Rapid, {0, 0, 0}, s), c.expected});
    VectorSource actual({move(MotionKind::Rapid, {0, 0, 0}, s), c.actual});
    auto r = postproc::verify::compare(expected, actual, {});
    if (std::string(c.what).empty()) {
      EXPECT_FALSE(r.divergence) << r.divergence->what;
      EXPECT_EQ(r.compared, 2u);
    } else {
      ASSERT_TRUE(r.divergence) << c.what;
      EXPECT_EQ(r.divergence->what, c.what);
      EXPECT_EQ(r.divergence->ordinal, 2u);
    }
  }
}

TEST(VerifyCompare, OneSideEndingEarlyIsADivergence) {
  VectorSource expected({move(MotionKind::Rapid, {0, 0, 0}, {1, 0, 0})});
  VectorSource actual({});
  auto r = postproc::verify::compare(expected, actual, {});
  ASSERT_TRUE(r.divergence);
  EXPECT_EQ(r.divergence->what, "the NC program ends here; the toolpath goes on");
}

// What compare() says of a toolpath and a program: the divergence, or "" when they match.
std::string divergence(const std::vector<Motion>& toolpath, const std::vector<Motion>& program) {
  VectorSource expected(toolpath), actual(program);
  auto r = postproc::verify::compare(expected, actual, {});
  return r.divergence ? r.divergence->what : "";
}

// The end position (@end_program) is optional: a post may home the machine instead (G28, G53).
TEST(VerifyCompare, TheEndMoveMayBeMadeInPartOrInOneBlockOrLeftOut) {
  auto optional = [](Motion m) {
    m.optional = true;
    return m;
  };
  const std::vector<Motion> toolpath = {move(MotionKind::Feed, {0, 0, 0}, {0, 0, -2}, 100),
                                        move(MotionKind::Rapid, {0, 0, -2}, {0, 0, 10}),
                                        optional(move(MotionKind::Rapid, {0, 0, 10}, {0, 0, 60})),
                                        optional(move(MotionKind::Rapid, {0, 0, 60}, {30, 15, 60}))};
  const Motion cut = move(MotionKind::Feed, {0, 0, 0}, {0, 0, -2}, 100);
  struct Case {
    const char* name;
    std::vector<Motion> program;
    const char* divergence;  // "" none
  } cases[] = {
      {"left out (G91 G28 Z0.)", {cut, move(MotionKind::Rapid, {0, 0, -2}, {0, 0, 10})}, ""},
      {"made, block by block",
       {cut, move(MotionKind::Rapid, {0, 0, -2}, {0, 0, 10}), move(MotionKind::Rapid, {0, 0, 10}, {0, 0, 60}),
        move(MotionKind::Rapid, {0, 0, 60}, {30, 15, 60})},
       ""},
      {"retract and end height in one block",
       {cut, move(MotionKind::Rapid, {0, 0, -2}, {0, 0, 60}), move(MotionKind::Rapid, {0, 0, 60}, {30, 15, 60})}, ""},
      {"only the end height", {cut, move(MotionKind::Rapid, {0, 0, -2}, {0, 0, 10}), move(MotionKind::Rapid, {0, 0, 10}, {0, 0, 60})}, ""},
      {"somewhere else",
       {cut, move(MotionKind::Rapid, {0, 0, -2}, {0, 0, 10}), move(MotionKind::Rapid, {0, 0, 10}, {5, 5, 10})},
       "the NC program goes on after the toolpath ends"},
      {"no retract", {cut}, "the NC program ends here; the toolpath goes on"},
  };
  for (const auto& c : cases) EXPECT_EQ(divergence(toolpath, c.program), c.divergence) << c.name;
}

// What a program may add or join without a divergence (docs/pikocnc.md, "verify").
TEST(VerifyCompare, WhatAProgramMayAddOrJoin) {
  auto tool = [](std::int64_t t) {
    Motion m;
    m.kind = MotionKind::Tool;
    m.tool = t;
    return m;
  };
  auto dwell = [](double s) {
    Motion m;
    m.kind = MotionKind::Dwell;
    m.seconds = s;
    return m;
  };
  auto approach = [](Motion m, bool first) {
    m.optional = true;
    m.approach = first;
    return m;
  };
  Motion xy = move(MotionKind::Rapid, {0, 0, 10}, {20, 5, 10});
  xy.known = {true, true, false};
  const std::vector<Motion> toolpath = {tool(1), spindle(1, 1000), approach(xy, true),
                                        approach(move(MotionKind::Rapid, {20, 5, 10}, {20, 5, 30}), false),
                                        move(MotionKind::Feed, {20, 5, 30}, {20, 5, 0}, 100)};
  struct Case {
    const char* name;
    std::vector<Motion> program;
    const char* divergence;
  } cases[] = {
      {"a retract up before the tool change, a dwell after M3, the approach in one block",
       {move(MotionKind::Rapid, {0, 0, 0}, {0, 0, 50}), tool(1), spindle(1, 1000), dwell(1),
        move(MotionKind::Rapid, {0, 0, 50}, {20, 5, 30}), move(MotionKind::Feed, {20, 5, 30}, {20, 5, 0}, 100)},
       ""},
      {"no approach: the next move is compared where it ends",
       {tool(1), spindle(1, 1000), move(MotionKind::Feed, {0, 0, 0}, {20, 5, 0}, 100)}, ""},
      {"an approach elsewhere", {tool(1), spindle(1, 1000), move(MotionKind::Rapid, {0, 0, 0}, {25, 5, 30})},
       "expected a feed, the NC program makes a rapid"},
      {"a move down before the tool change is one",
       {move(MotionKind::Rapid, {0, 0, 10}, {0, 0, 5}), tool(1)}, "expected a tool change, the NC program makes a rapid"},
  };
  for (const auto& c : cases) EXPECT_EQ(divergence(toolpath, c.program), c.divergence) << c.name;
}

// Machine-state checks: what no machine should do, whatever the toolpath says.
TEST(VerifyStateChecks, FindWhatMakesScrapOrIsSuspect) {
  auto cmd = [](const char* name, std::vector<std::pair<const char*, double>> numbers = {}) {
    toolpath::Command c;
    c.name = name;
    for (const auto& [k, v] : numbers) c.set(k, toolpath::Value::make_numeric(v));
    return c;
  };
  auto rapid = [&](double x, double y, double z) { return cmd("@rapid_move", {{"xpos", x}, {"ypos", y}, {"zpos", z}}); };
  auto line = [&](double x, double y, double z, double f) {
    return cmd("@line", {{"xpos", x}, {"ypos", y}, {"zpos", z}, {"feed", f}});
  };
  struct Case {
    const char* name;
    std::vector<toolpath::Command> program;
    std::vector<std::string> findings;  // "line: severity: what (count)"
  } cases[] = {
      {"a clean cut", {cmd("@start_tool"), rapid(0, 0, 10), rapid(0, 0, 2), line(0, 0, -2, 100), line(5, 0, -2, 100),
                       rapid(5, 0, 10), rapid(9, 9, 10), cmd("@change_tool")}, {}},
      {"a feed with the spindle stopped, at feed 0", {line(0, 0, -1, 100), cmd("@start_tool"), line(1, 0, -1, 0)},
       {"1: error: a feed move with the spindle stopped (1)", "3: error: a feed move at feed 0: no F was given (1)"}},
      {"a rapid across at depth, a tool change down there",
       {cmd("@start_tool"), rapid(0, 0, 2), line(0, 0, -2, 100), rapid(5, 0, -2), cmd("@change_tool")},
       {"4: warning: a rapid across X Y at Z-2.000, below Z2.000 where the last plunge started (1)",
        "5: warning: a tool change with the tool at Z-2.000, below Z2.000 where its last plunge started: no retract (1)"}},
      {"homed before the tool change", {cmd("@start_tool"), rapid(0, 0, 2), line(0, 0, -2, 100), cmd("@machine_move"),
                                       cmd("@change_tool")}, {}},
      {"compensation switched on an arc",
       {cmd("@start_tool"), cmd("@compensation"),
        cmd("@arc", {{"xpos", 1}, {"ypos", 1}, {"zpos", 0}, {"feed", 100}})},
       {"3: warning: cutter compensation switched on or off on an arc (controls want a line for it: Fanuc alarm "
        "PS0034) (1)"}},
      {"A beyond its travel (the machine's A turns -120 .. 30), B not limited",
       {cmd("@start_tool"), cmd("@rapid_move", {{"apos", 30}, {"bpos", 500}}), cmd("@line", {{"apos", -121}, {"feed", 100}}),
        cmd("@rapid_move", {{"apos", 45}}), cmd("@rapid_move", {{"apos", 90}})},
       {"3: error: A turned past its lower limit -120 (travel -120 .. 30 in the machine file): an overtravel alarm (1)",
        "4: error: A turned past its upper limit 30 (travel -120 .. 30 in the machine file): an overtravel alarm (2)"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    postproc::verify::StateChecks checks(machines::VerifyProfile{}, {prp::RotaryLimits{'A', -120, 30, {}}});
    for (std::size_t i = 0; i < c.program.size(); ++i) checks.command(c.program[i], i + 1);
    std::vector<std::string> got;
    for (const auto& f : checks.findings())
      got.push_back(fmt::format("{}: {}: {} ({})", f.line, f.severity == toolpath::Severity::Error ? "error" : "warning",
                                f.what, f.count));
    EXPECT_EQ(got, c.findings);
  }
}

using Run = test_support::CliRun;
const auto run = test_support::run_cli;

using test_support::slurp;

TEST(VerifyCli, ShippedSampleMatches) {
  auto r = run({"verify", "--post", "../machines/pikocnc/pikocnc.gpp", "--prp", "../machines/pikocnc/pikocnc.prp",
                "../docs/examples/sample-job.trace"});
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_EQ(r.out, "../docs/examples/sample-job.trace: ok, 50 motion events match; NC read by the PikoCNC model "
                   "(--dialect pikocnc)\n  cycle time 44 s (T3 25 s, T7 19 s)\n");
}

// The cycle time verify prints: in all, then per tool in the order the tools run.
TEST(VerifyCycleTime, Describe) {
  using T = postproc::verify::CycleTime;
  struct Case {
    T time;
    const char* text;
  } cases[] = {
      {T{44.4, {{0, 0}, {3, 25.2}, {7, 19.2}}, false}, "44 s (T3 25 s, T7 19 s)"},
      {T{55, {{0, 55}}, false}, "55 s"},  // no tool change: no breakdown
      {T{130, {{0, 10}, {12, 120}}, false}, "2 min 10 s (before the first tool 10 s, T12 2 min 0 s)"},
      {T{3725, {{0, 0}, {1, 3725}}, true}, "1 h 2 min 5 s (T1 1 h 2 min 5 s); rapids not timed: the machine file has no rapid_feed"},
  };
  for (const auto& c : cases) EXPECT_EQ(postproc::verify::describe(c.time), c.text);
}

// A copy of the PikoCNC post that writes G2 for counter-clockwise arcs and G3 for clockwise ones.
// A tool change that approaches X0 Y0, where the controller models start: the NC's `G0 X0. Y0.` is no
// move for the model, and the expected side drops the same first move (issue 21).
TEST(VerifyCli, ApproachToTheOriginIsNoDivergence) {
  for (const std::vector<std::string>& target :
       {std::vector<std::string>{"--post", "../machines/pikocnc/pikocnc.gpp", "--prp", "../machines/pikocnc/pikocnc.prp"},
        std::vector<std::string>{"--dialect", "2xaxiscnc", "--post", "../machines/2xaxiscnc/2xaxiscnc.gpp", "--prp",
                                 "../machines/2xaxiscnc/2xaxiscnc.prp", "--answer", "drill_action=RunScript_drill.script"}}) {
    std::vector<std::string> args{"verify"};
    args.insert(args.end(), target.begin(), target.end());
    args.push_back("postproc/checks/data/origin-job.trace");
    auto r = run(args);
    EXPECT_EQ(r.code, 0) << r.out << r.err;
  }
}

TEST(VerifyCli, PostThatTurnsArcsTheWrongWayIsCaughtAtTheFirstArc) {
  std::string post = slurp("../machines/pikocnc/pikocnc.gpp");
  const std::string right = "  if arc_direction eq CCW\n    gcode = 3\n  else\n    gcode = 2\n";
  const std::string wrong = "  if arc_direction eq CCW\n    gcode = 2\n  else\n    gcode = 3\n";
  auto at = post.find(right);
  ASSERT_NE(at, std::string::npos);
  post.replace(at, right.size(), wrong);
  const auto dir = std::filesystem::temp_directory_path() / "postproc-verify-test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "wrong-arcs.gpp", std::ios::binary) << post;

  auto r = run({"verify", "--post", (dir / "wrong-arcs.gpp").string(), "--prp", "../machines/pikocnc/pikocnc.prp",
                "../docs/examples/sample-job.trace"});
  std::filesystem::remove_all(dir);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(r.out,
            "../docs/examples/sample-job.trace: divergence at motion event 9: arc turns the other way\n"
            "  toolpath: command #13 @arc\n"
            "  NC:       SAMPLE.NC:19: G2 X40. Y5. I0. J5.\n"
            "  expected arc CCW XY to X40.0000 Y5.0000 Z-2.0000 centre X35.0000 Y5.0000 Z-2.0000 R5.0000 sweep 90.0000 F400\n"
            "  actual   arc CW XY to X40.0000 Y5.0000 Z-2.0000 centre X35.0000 Y5.0000 Z-2.0000 R5.0000 sweep 270.0000 F400\n"
            "  NC read by the PikoCNC model (--dialect pikocnc)\n");
}

// With the control's tool table the Fanuc model applies G43 H: a post whose H is not the tool's
// puts the tip where the toolpath does not, and verify says where.
TEST(VerifyCli, ToolTableCatchesTheWrongLengthOffset) {
  const std::vector<std::string> common{"--prp", "../machines/fanuc/fanuc.prp", "--dialect", "fanuc", "--tool-table",
                                        "postproc/checks/data/sample-tools.tbl", "../docs/examples/sample-job.trace"};
  std::vector<std::string> args{"verify", "--post", "../machines/fanuc/fanuc.gpp"};
  args.insert(args.end(), common.begin(), common.end());
  auto r = run(args);
  EXPECT_EQ(r.code, 0) << r.out << r.err;

  std::string post = slurp("../machines/fanuc/fanuc.gpp");
  const std::string right = "' H', tool_number}", wrong = "' H3'}";
  const auto at = post.find(right);
  ASSERT_NE(at, std::string::npos);
  post.replace(at, right.size(), wrong);
  const auto dir = std::filesystem::temp_directory_path() / "postproc-verify-tool-table";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "fanuc.gpp", std::ios::binary) << post;
  args = {"verify", "--post", (dir / "fanuc.gpp").string()};
  args.insert(args.end(), common.begin(), common.end());
  r = run(args);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("NC:       SAMPLE.NC:20: N180 G43 Z50. H3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("actual   rapid to X10.0000 Y15.0000 Z65.2500"), std::string::npos) << r.out;
}

// Closing the loop the other way: PikoCNC G-code read back and posted through the Fanuc post.
TEST(RunDialect, PikoCncProgramPostedAgainThroughTheFanucPost) {
  auto r = run({"run", "--dialect", "pikocnc", "golden/pikocnc/sample-job/SAMPLE.NC", "--post",
                "../machines/fanuc/fanuc.gpp", "--prp", "../machines/fanuc/fanuc.prp"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, slurp("golden/pikocnc/fanuc-from-nc/SAMPLE.NC"));
}

}  // namespace
