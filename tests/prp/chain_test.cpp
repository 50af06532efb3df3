// The whole filter chain on the shared FANUC example: its trace already conforms to fanuc.prp, so
// the chain must hand every command through, in order, without restructuring (spec 3.0).
// The arcs stay single arcs although one starts 0.002 degrees past a quadrant boundary.
#include <gtest/gtest.h>

#include "prp/prp.hpp"
#include "stream_helpers.hpp"
#include "toolpath/trace_reader.hpp"

using namespace prp_test;

namespace {

TEST(FilterChain, SolidCamFanucTracePassesThrough) {
  auto params = prp::load_file("prp/data/fanuc.prp", prp::Units::Metric);
  auto plain = toolpath::TraceReader::open("golden/solidcam-fanuc/toolpath.trace");
  auto expected = drain(*plain);
  auto reader = toolpath::TraceReader::open("golden/solidcam-fanuc/toolpath.trace");
  std::vector<std::string> warnings;
  auto chain = prp::build_filter_chain(params, *reader, [&](const toolpath::Command& c, const std::string& m) {
    warnings.push_back(c.name + ": " + m);
  });
  auto out = drain(*chain);
  ASSERT_EQ(out.size(), expected.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    EXPECT_EQ(out[i].name, expected[i].name) << i;
    EXPECT_EQ(out[i].index, expected[i].index) << i;
    for (const char* p : {"xpos", "ypos", "zpos", "arc_size", "xcenter_rel"}) {
      if (expected[i].find(p)) {  // rounded to movement_precision, or snapped below zero_value (0.001)
        EXPECT_NEAR(get(out[i], p), get(expected[i], p), 0.001) << i << " " << p;
      }
    }
  }
  // The example's post generates subroutines although its PRP says gen_procs = N, and its PRP says
  // the control starts incremental (abs_coord = N) but the trace sends no @absolute_mode: each
  // reported once, nothing restructured.
  EXPECT_EQ(warnings, (std::vector<std::string>{"@call_proc: @call_proc although the PRP says gen_procs = N",
                                                "@rapid_move: the PRP says abs_coord = N but the toolpath sends no "
                                                "@absolute_mode before its first motion"}));
}

// The compensation check follows the tool and the side in stream order, before procedure
// generation moves the jobs into bodies (gen_procs = Y in the shipped Fanuc PRP).
TEST(FilterChain, CompensationIsCheckedBeforeJobsBecomeProcedures) {
  auto params = prp::load_file("../machines/fanuc/fanuc.prp", prp::Units::Metric);
  ASSERT_EQ(params.text("gen_procs"), "Y");
  auto reader = toolpath::TraceReader::open("prp/data/tight-corners.trace");
  std::vector<std::string> warnings;
  auto chain = prp::build_filter_chain(params, *reader, [&](const toolpath::Command& c, const std::string& m) {
    warnings.push_back(std::to_string(c.line) + ": " + m);
  });
  drain(*chain);
  const std::string tight = ": arc radius 5 is below tool radius 5 + min_delt_arc_rad 0.01 on the compensated side (COMP_LEFT)";
  EXPECT_EQ(warnings, (std::vector<std::string>{"58" + tight, "78" + tight, "98" + tight, "118" + tight}));
}

TEST(FilterChain, LinearisesArcsForAMachineWithoutThem) {
  auto params = prp::load_source("@pre_processor\narc_exist = N\nendp\n", "n.prp", prp::Units::Metric);
  ListSource source({command("@line", {{"xpos", num(10)}, {"ypos", num(0)}, {"zpos", num(0)}}),
                     command("@arc", {{"xpos", num(-10)}, {"ypos", num(0)}, {"zpos", num(0)}, {"xcenter", num(0)},
                                      {"ycenter", num(0)}, {"xcenter_rel", num(-10)}, {"ycenter_rel", num(0)},
                                      {"radius", num(10)}, {"arc_direction", word("CCW")}, {"arc_size", num(180)}})});
  std::vector<std::string> warnings;
  auto chain = prp::build_filter_chain(params, source, [&](const toolpath::Command&, const std::string& m) {
    warnings.push_back(m);
  });
  auto out = drain(*chain);
  EXPECT_EQ(out.size(), 19u);  // 180 degrees in 10-degree chords (the default limits)
  EXPECT_EQ(warnings, std::vector<std::string>{"arcs are linearised but the PRP sets neither arc_max_angle nor "
                                               "arc_max_chord: using 10 degrees and 30 mm / 1.1811 inch"});
}

}  // namespace
