// Wire guides (prp/filters/wire_guides.hpp): @wc_abs_rel completed from the PRP, and the upper
// guide kept within u_max / v_max of the lower one, in relative and absolute UV.
#include <gtest/gtest.h>

#include "prp/filters/wire_guides.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;

namespace {

prp::MachineParameters machine(const char* uv_abs) {
  return prp::load_source(std::string("@pre_processor\nmachine_type = WIRE_CUT\nxy_abs = Y\nuv_abs = ") + uv_abs +
                              "\nu_max = 2, 0.08\nv_max = 1, 0.04\nendp\n",
                          "w.prp", prp::Units::Metric);
}

std::string error_of(const prp::MachineParameters& m, toolpath::Command c) {
  ListSource source({std::move(c)});
  prp::WireGuides guides(source, m);
  try {
    drain(guides);
  } catch (const prp::StreamError& e) {
    return e.what();
  }
  return "no error";
}

TEST(WireGuides, AbsRelGetsThePrpValuesTheStreamLeftOut) {
  auto m = machine("N");
  ListSource source({command("@wc_abs_rel", {}), command("@wc_abs_rel", {{"uv_abs", logical(true)}})});
  prp::WireGuides guides(source, m);
  auto out = drain(guides);
  EXPECT_EQ(out[0], command("@wc_abs_rel", {{"xy_abs", logical(true)}, {"uv_abs", logical(false)}}));
  EXPECT_EQ(out[1], command("@wc_abs_rel", {{"uv_abs", logical(true)}, {"xy_abs", logical(true)}}));
}

TEST(WireGuides, TheUpperGuideStaysWithinTheLimits) {
  struct Case {
    const char* uv_abs;
    const char* name;
    double x, y, u, v;
    const char* error;  // empty: none
  } cases[] = {
      {"N", "@wc_line", 10, 5, 2, -1, ""},
      {"N", "@wc_line", 10, 5, 2.5, 0, "the upper guide is 2.5 from the lower one in U, beyond u_max = 2"},
      {"N", "@wc_arc", 10, 5, 0, -1.2, "the upper guide is 1.2 from the lower one in V, beyond v_max = 1"},
      {"N", "@wc_move", 10, 5, 0, 1.5, "beyond v_max = 1"},
      {"Y", "@wc_line", 10, 5, 11.5, 5.5, ""},  // absolute: 1.5 and 0.5 away
      {"Y", "@wc_pos_pnt", 10, 5, 13, 5, "the upper guide is 3 from the lower one in U, beyond u_max = 2"},
      {"N", "@line", 10, 5, 9, 9, ""},  // not a wire move
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(c.name) + " uv_abs " + c.uv_abs);
    const std::string got = error_of(machine(c.uv_abs), command(c.name, {{"xpos", num(c.x)}, {"ypos", num(c.y)},
                                                                         {"upos", num(c.u)}, {"vpos", num(c.v)}}));
    if (*c.error) {
      EXPECT_NE(got.find(c.error), std::string::npos) << got;
    } else {
      EXPECT_EQ(got, "no error");
    }
  }
}

}  // namespace
