// The tool table file (LinuxCNC's format) the ISO models apply G43 H from: what a line gives, and
// every malformed line with its position.
#include <gtest/gtest.h>

#include <string>

#include <fmt/format.h>

#include "machines/ncmodel/tool_table.hpp"
#include "toolpath/error.hpp"

namespace {

std::string error_of(const std::string& text) {
  try {
    ncmodel::parse_tool_table(text, "tool.tbl");
  } catch (const toolpath::InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ToolTable, LinesAsLinuxCNCWritesThem) {
  const auto table = ncmodel::parse_tool_table(
      "; the mill's tools\r\n"
      "T1 P1 Z+50.200 D6.000 ;6 mm end mill\n"
      "\n"
      "t7 p3 x0 y0 z-12.5 a0 d10 i0 j0 q1\n"
      "T0 P0 Z0 ; the empty spindle\n"
      "T12 P12",
      "tool.tbl");
  std::string got;
  for (const auto& [tool, o] : table.tools) got += fmt::format("T{} L{:g} D{:g}; ", tool, o.length, o.diameter);
  EXPECT_EQ(got, "T0 L0 D0; T1 L50.2 D6; T7 L-12.5 D10; T12 L0 D0; ");
  EXPECT_EQ(table.file, "tool.tbl");
  EXPECT_EQ(table.find(5), nullptr);
  ASSERT_NE(table.find(7), nullptr);
  EXPECT_EQ(table.find(7)->length, -12.5);
}

TEST(ToolTable, MalformedLinesNameLineAndColumn) {
  struct Case {
    const char* text;
    const char* error;
  } cases[] = {
      {"T1 Z5\nP2 Z3", "tool.tbl:2:1: expected the tool number T on the line"},
      {"T1 Z5\nT1 Z6", "tool.tbl:2:1: T1 is in the table twice"},
      {"T1 H5", "tool.tbl:1:4: expected a word T, P, X, Y, Z, A, B, C, U, V, W, D, I, J or Q, found `H5`"},
      {"T1 Z", "tool.tbl:1:5: expected the number of Z"},
      {"T1 Z;5", "tool.tbl:1:5: expected the number of Z"},
      {"T1 Z1.2.3", "tool.tbl:1:5: malformed number `1.2.3` of Z"},
      {"T1.5 Z1", "tool.tbl:1:1: expected a tool number 0 .. 99999999, found T1.5"},
      {"T-1 Z1", "tool.tbl:1:1: expected a tool number 0 .. 99999999, found T-1"},
      {"T1 D-3", "tool.tbl:1:4: expected a diameter of 0 or more, found D-3"},
      {"T1 Z1e5", "tool.tbl:1:6: expected a word T, P, X, Y, Z, A, B, C, U, V, W, D, I, J or Q, found `e5`"},
  };
  for (const auto& c : cases) EXPECT_EQ(error_of(c.text), c.error) << c.text;
  EXPECT_EQ(error_of("T1 Z" + std::string(400, '9')), "tool.tbl:1:5: number out of range of Z");
}

TEST(ToolTable, AMissingFileIsAnInputError) {
  EXPECT_THROW(ncmodel::load_tool_table("no/such/tool.tbl"), toolpath::InputError);
}

}  // namespace
