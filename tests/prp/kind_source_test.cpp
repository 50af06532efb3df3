// The filters hand each command on with its kind; the kind must be command_kind() of the name the
// command leaves with, also where a filter makes commands (arc pieces and chords, procedure calls
// and brackets) and when a filter reads another filter's kinds instead of classifying names.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "prp/filters/arc_filter.hpp"
#include "prp/filters/precision_filter.hpp"
#include "prp/filters/procedure_generation.hpp"
#include "prp/filters/structure_check.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;
using toolpath::Command;
using toolpath::Value;

namespace {

// Drains `source` and checks every kind it tells; returns the names handed out.
std::vector<std::string> drain_checking_kinds(prp::KindSource& source) {
  std::vector<std::string> names;
  Command c;
  prp::CommandKind kind{};
  while (source.next_with_kind(c, kind)) {
    EXPECT_EQ(kind, prp::command_kind(c)) << c.name << " #" << c.index;
    names.push_back(c.name);
  }
  return names;
}

std::vector<Command> arcs_job() {
  return {command("@start_of_job", {{"job_name", Value::make_string("J")}}, 0),
          command("@LINE", {{"xpos", num(26)}, {"ypos", num(-4)}, {"zpos", num(-6)}, {"feed", num(33)}}, 1),
          command("@Arc",
                  {{"xpos", num(26)}, {"ypos", num(-4)}, {"zpos", num(-6)}, {"feed", num(100)},
                   {"xcenter", num(26)}, {"ycenter", num(26)}, {"xcenter_rel", num(0)}, {"ycenter_rel", num(30)},
                   {"radius", num(30)}, {"arc_direction", word("CW")}, {"arc_plane", word("XY")},
                   {"arc_size", num(360)}},
                  2),
          command("@arc_5x",
                  {{"xpos", num(56)}, {"ypos", num(26)}, {"zpos", num(-6)}, {"apos", num(30)}, {"xcenter", num(26)},
                   {"ycenter", num(26)}, {"xcenter_rel", num(0)}, {"ycenter_rel", num(30)},
                   {"arc_direction", word("CCW")}, {"arc_size", num(90)}},
                  3),
          command("@no_such_command", {}, 4),
          command("@end_of_job", {}, 5)};
}

TEST(KindSource, ArcPiecesAndChordsCarryTheirOwnKind) {
  struct Case {
    const char* what;
    void (*change)(prp::ArcSettings&);
    std::vector<std::string> names;
  };
  const Case cases[] = {
      {"unchanged", [](prp::ArcSettings&) {},
       {"@start_of_job", "@LINE", "@Arc", "@arc_5x", "@no_such_command", "@end_of_job"}},
      {"quadrants", [](prp::ArcSettings& s) { s.quadrants = true; },
       {"@start_of_job", "@LINE", "@Arc", "@Arc", "@Arc", "@Arc", "@arc_5x", "@no_such_command", "@end_of_job"}},
      {"one line each", [](prp::ArcSettings& s) { s.eps_angle = 361; },
       {"@start_of_job", "@LINE", "@line", "@line_5x", "@no_such_command", "@end_of_job"}},
      {"5-axis arcs as chords", [](prp::ArcSettings& s) { s.arc_5x = false, s.max_angle = 45; },
       {"@start_of_job", "@LINE", "@Arc", "@line_5x", "@line_5x", "@no_such_command", "@end_of_job"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    prp::ArcSettings s;
    c.change(s);
    ListSource source(arcs_job());
    prp::ArcFilter filter(source, s);
    EXPECT_EQ(drain_checking_kinds(filter), c.names);
  }
}

TEST(KindSource, KindsTravelDownAChainOfFilters) {
  auto params = prp::load_source("@pre_processor\ngen_procs = Y\nproc_num_dflt = 7\nendp\n", "k.prp",
                                 prp::Units::Metric);
  ListSource source(arcs_job());
  prp::StepFilter<prp::StructureCheck> check(source, params, prp::WarningSink{});
  prp::ProcedureGeneration procedures(check, params);
  prp::ArcSettings arcs;
  arcs.quadrants = true;
  prp::ArcFilter arc_filter(procedures, arcs);
  prp::PrecisionSettings precision;
  precision.movement_digits = 3;
  prp::PrecisionFilter rounding(arc_filter, precision);
  EXPECT_EQ(drain_checking_kinds(rounding),
            (std::vector<std::string>{"@call_proc", "@proc", "@start_of_job", "@LINE", "@Arc", "@Arc", "@Arc", "@Arc",
                                      "@arc_5x", "@no_such_command", "@end_of_job", "@end_proc"}));
}

}  // namespace
