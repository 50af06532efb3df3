// Machine files as real posts ship them: empty values, drill base `None`, keys we do not know, and
// the pre-2010 `.mac` spelling of the PRP. None of these stops loading.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "prp/prp.hpp"

using prp::Units;

namespace {

struct LenientCase {
  const char* name;
  const char* body;  // between @pre_processor and endp
  std::vector<std::string> warnings;
  std::function<void(const prp::MachineParameters&)> check;
};

class Leniency : public testing::TestWithParam<LenientCase> {};

TEST_P(Leniency, LoadsWithTheseWarnings) {
  const auto& c = GetParam();
  auto p = prp::load_source(std::string("@pre_processor\n") + c.body + "endp\n", "r.prp", Units::Metric);
  std::vector<std::string> got;
  for (const auto& w : p.warnings()) got.push_back(w.text());
  EXPECT_EQ(got, c.warnings);
  c.check(p);
}

const LenientCase kCases[] = {
    {"EmptyEnumeration", "_4th_axes_around =\n", {},
     [](const auto& p) { EXPECT_FALSE(p.has("_4th_axes_around")); }},
    {"EmptyLogicalKeepsItsDefault", "arc_3d =   ; not set\n", {},
     [](const auto& p) {
       EXPECT_FALSE(p.has("arc_3d"));
       EXPECT_TRUE(p.logical("arc_3d"));
     }},
    {"EmptyNumberKeepsItsDefault", "arc_max_chord =\n", {},
     [](const auto& p) { EXPECT_DOUBLE_EQ(p.numeric("arc_max_chord"), 30.0); }},
    {"EmptyStringIsSet", "gpp_file_ext =\n", {},
     [](const auto& p) {
       ASSERT_TRUE(p.has("gpp_file_ext"));
       EXPECT_EQ(p.text("gpp_file_ext"), "");
     }},
    {"EmptyRecord", "drill_type =\n", {}, [](const auto& p) { EXPECT_TRUE(p.records("drill_type").empty()); }},
    {"DrillBaseNone", "drill_type = G81_Macro None Y P1\n", {},
     [](const auto& p) {
       ASSERT_NE(p.drill_cycle("G81_Macro"), nullptr);
       EXPECT_EQ(p.drill_cycle("G81_Macro")->base, "NONE");
       EXPECT_EQ(p.drill_cycle("G81_Macro")->params, std::vector<std::string>{"P1"});
     }},
    {"LegacyDrillNone", "drill_type = none N\n", {},
     [](const auto& p) { EXPECT_EQ(p.drill_cycle("none")->base, "NONE"); }},
    {"UnknownKeyWarnedOnceLastValueKept", "user_flag = Y\nUSER_FLAG = N ; changed\n",
     {"r.prp:2:1: warning: unknown key `user_flag`: kept as text for the post"},
     [](const auto& p) {
       ASSERT_NE(p.unknown("user_flag"), nullptr);
       EXPECT_EQ(p.unknown("user_flag")->raw, "N");
       EXPECT_EQ(p.unknown("user_flag")->where.line, 3u);
     }},
    {"UnknownKeyEmpty", "user_text =\n", {"r.prp:2:1: warning: unknown key `user_text`: kept as text for the post"},
     [](const auto& p) {
       ASSERT_NE(p.unknown("user_text"), nullptr);
       EXPECT_EQ(p.unknown("user_text")->raw, "");
     }},
};

INSTANTIATE_TEST_SUITE_P(RealPosts, Leniency, testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(MacFile, OldStyleMachineFileLoads) {
  auto p = prp::load_file("prp/data/fanuc-old.MAC", Units::Inch);
  std::vector<std::string> got;
  for (const auto& w : p.warnings()) got.push_back(w.text());
  EXPECT_EQ(got, std::vector<std::string>{
                     "prp/data/fanuc-old.MAC:9:1: warning: unknown key `my_old_switch`: kept as text for the post"});
  EXPECT_EQ(p.text("gpp_file_ext"), "TAP");
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_chord"), 1.1811);
  EXPECT_FALSE(p.has("_4th_axes_around"));
  EXPECT_EQ(p.text("tool_table_name"), "");
  EXPECT_EQ(p.unknown("my_old_switch")->raw, "Y");
  std::vector<std::string> cycles;
  for (const auto* r : p.records("drill_type")) cycles.push_back(r->name + "/" + r->base);
  EXPECT_EQ(cycles, (std::vector<std::string>{"Drilling/DRILLING", "Peck/PECK", "Macro90/NONE"}));
}

}  // namespace
