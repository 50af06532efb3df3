// Drill cycles flagged N in the PRP become explicit moves (spec 3.11); those that cannot, fail.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "prp/filters/drill_expansion.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;

namespace {

const char* kPrp =
    "@pre_processor\n"
    "drill_type = Drilling Drilling N\n"
    "drill_type = F_Drill F_Drill N Delay\n"
    "drill_type = Peck Peck N\n"
    "drill_type = Boring Boring N\n"
    "drill_type = F_Boring F_Boring N P_Dwell Q\n"
    "drill_type = Tapping Tapping N\n"
    "drill_type = G81 Drilling Y\n"
    "drill_type = BadDwell F_Boring N Delay DwellToo\n"
    "drill_type = Macro None N\n"
    "endp\n";

// A drill job: two holes, levels clearance 10, upper 2, lower -5, pecks of 3.
std::vector<toolpath::Command> job(const char* type) {
  return {command("@start_of_job", {{"job_name", toolpath::Value::make_string("DR1")}}, 0),
          command("@drill", {{"xpos", num(1)}, {"ypos", num(2)}, {"zpos", num(10)}, {"drill_type", word(type)},
                             {"drill_clearance_z", num(10)}, {"drill_upper_z", num(2)}, {"drill_lower_z", num(-5)},
                             {"down_step", num(3)}, {"feed", num(75)}, {"delay", num(0.5)}, {"p_dwell", num(2)}},
                  1),
          command("@drill_point", {{"xpos", num(1)}, {"ypos", num(2)}, {"first_drill", toolpath::Value::make_logical(true)}}, 2),
          command("@drill_point", {{"xpos", num(7)}, {"ypos", num(8)}}, 3),
          command("@end_drill", {}, 4),
          command("@rapid_move", {{"zpos", num(50)}}, 5)};
}

// Compact text of the moves of the first hole: "R10 R2 F-5 ..." (R rapid, F feed, D dwell).
std::string moves(const char* type) {
  auto params = prp::load_source(kPrp, "d.prp", prp::Units::Metric);
  ListSource source(job(type));
  prp::DrillExpansion filter(source, params, {});
  std::string text;
  for (const auto& c : drain(filter)) {
    if (c.index != 2) {  // the @drill and @end_drill themselves are never sent
      EXPECT_TRUE(c.index != 1 && c.index != 4) << c.name;
      continue;
    }
    if (!text.empty() && text.back() != ' ') text += ' ';
    if (c.name == "@delay") text += fmt::format("D{}", get(c, "delay_period"));
    else text += fmt::format("{}{}", c.name == "@line" ? "F" : "R", get(c, "zpos"));
    EXPECT_TRUE(c.name == "@delay" || (get(c, "xpos") == 1 && get(c, "ypos") == 2));
    if (c.name == "@line") {
      EXPECT_EQ(get(c, "feed"), 75);
    }
  }
  return text;
}

TEST(DrillExpansion, EveryExpandableBaseType) {
  EXPECT_EQ(moves("Drilling"), "R10 R2 F-5 R2 R10");
  EXPECT_EQ(moves("F_Drill"), "R10 R2 F-5 D0.5 R2 R10");
  EXPECT_EQ(moves("Peck"), "R10 R2 F-1 R2 R-1 F-4 R2 R-4 F-5 R2 R10");
  EXPECT_EQ(moves("Boring"), "R10 R2 F-5 F2 R10");
  EXPECT_EQ(moves("F_Boring"), "R10 R2 F-5 D2 F2 R10");
}

TEST(DrillExpansion, CycleTheMachineHasPassesUnchanged) {
  auto params = prp::load_source(kPrp, "d.prp", prp::Units::Metric);
  ListSource source(job("G81"));
  prp::DrillExpansion filter(source, params, {});
  EXPECT_EQ(drain(filter), job("G81"));
}

TEST(DrillExpansion, SecondHoleAndTheCycleCommandsAreReplaced) {
  auto params = prp::load_source(kPrp, "d.prp", prp::Units::Metric);
  ListSource source(job("Drilling"));
  prp::DrillExpansion filter(source, params, {});
  auto out = drain(filter);
  ASSERT_EQ(out.size(), 12u);  // job start, 2 x 5 moves, the final rapid
  EXPECT_EQ(out[6].index, 3u);
  EXPECT_EQ(get(out[6], "xpos"), 7);
  EXPECT_EQ(out[11].name, "@rapid_move");
}

std::string expansion_error(const char* type, const char* machine = kPrp, const char* file = "d.prp") {
  auto params = prp::load_source(machine, file, prp::Units::Metric);
  ListSource source(job(type));
  prp::DrillExpansion filter(source, params, {});
  try {
    drain(filter);
  } catch (const prp::StreamError& e) {
    return e.what();
  }
  return "no error";
}

TEST(DrillExpansion, CyclesThatCannotBeExpandedAreErrors) {
  EXPECT_EQ(expansion_error("Tapping"),
            "command 1 (@drill): drill cycle `Tapping` (base TAPPING, declared at d.prp:7:14) of job `DR1` is marked "
            "N, but it needs spindle reversal or a spindle stop, which cannot be written as plain moves");
  EXPECT_EQ(expansion_error("BadDwell"),
            "command 1 (@drill): drill cycle `BadDwell` (base F_BORING, declared at d.prp:9:14) of job `DR1` needs a "
            "dwell: its record must declare exactly one parameter whose name contains `delay` or `dwell`");
  EXPECT_EQ(expansion_error("Macro"),
            "command 1 (@drill): drill cycle `Macro` (base NONE, declared at d.prp:10:14) of job `DR1` is marked N, "
            "but it has no base type (None): nothing says which moves it stands for");
}

// The error points at the cycle's definition in whichever machine file declared it: a VMID's
// <DrillCycle> is named by the line and column of its GppName, not by a PRP line it does not have.
TEST(DrillExpansion, ErrorsNameTheFileAndPositionOfTheCycle) {
  const char* vmid =
      "<Machine><MillDrilCycles>\n"
      "  <DrillCycle GppName=\"G84\" DrillType=\"3\" UseCycle=\"0\"/>\n"
      "  <DrillCycle GppName=\"G82\" DrillType=\"1\" UseCycle=\"0\"><CycleParams>\n"
      "    <Param GppName=\"dwell\" ValueType=\"3\"/><Param GppName=\"delay\" ValueType=\"3\"/>\n"
      "  </CycleParams></DrillCycle>\n"
      "  <DrillCycle GppName=\"CYCLE85\" DrillType=\"8\" UseCycle=\"0\"/>\n"
      "</MillDrilCycles></Machine>\n";
  const char* one_line = "<Machine><DrillCycle DrillType=\"5\" UseCycle=\"0\" GppName=\"G86\"/></Machine>";
  const char* spaced = "@pre_processor\n; taps\n\n  drill_type   =  Tap Tapping N\nendp\n";
  struct Case {
    const char* machine;
    const char* file;
    const char* type;
    const char* where;  // what the message says in place of the position
  } cases[] = {
      {vmid, "m.vmid", "G84", "(base TAPPING, declared at m.vmid:2:24)"},
      {vmid, "m.vmid", "G82", "(base F_DRILL, declared at m.vmid:3:24)"},
      {vmid, "m.vmid", "CYCLE85", "(base NONE, declared at m.vmid:6:24)"},
      {one_line, "machine.vmid", "G86", "(base R_BORING, declared at machine.vmid:1:58)"},
      // a VMID is recognised by content whatever its name; the position is the file's own
      {vmid, "shop.prp", "G84", "(base TAPPING, declared at shop.prp:2:24)"},
      {kPrp, "d.prp", "Tapping", "(base TAPPING, declared at d.prp:7:14)"},
      {spaced, "dir/p.prp", "Tap", "(base TAPPING, declared at dir/p.prp:4:19)"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(c.file) + " " + c.type);
    const std::string error = expansion_error(c.type, c.machine, c.file);
    EXPECT_NE(error.find(fmt::format("drill cycle `{}` {} of job `DR1`", c.type, c.where)), std::string::npos)
        << error;
    EXPECT_EQ(error.find("PRP line"), std::string::npos) << error;
  }
}

TEST(DrillExpansion, UndeclaredCycleIsAWarning) {
  auto params = prp::load_source(kPrp, "d.prp", prp::Units::Metric);
  ListSource source(job("G99"));
  std::vector<std::string> warnings;
  prp::DrillExpansion filter(source, params, [&](const toolpath::Command& c, const std::string& m) {
    warnings.push_back(c.name + ": " + m);
  });
  EXPECT_EQ(drain(filter).size(), 6u);
  EXPECT_EQ(warnings, std::vector<std::string>{"@drill: drill_type `G99` is declared by no drill_type record of the PRP"});
}

}  // namespace
