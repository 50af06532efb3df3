// The Sinumerik reader's shortcuts held to its general paths: an address word's plain number
// against number() and the assignment form (the same random blocks, their numbers written so that
// only the general paths read them), labels after block numbers, and a block's words forgotten
// before the next block (Block::clear).
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "machines/sinumerik/reader.hpp"
#include "tests/support/read_back.hpp"

namespace {

// The trace and the diagnostics of `program`.
std::pair<std::string, std::string> read(const std::string& program) {
  auto reader = sinumerik::SinumerikReader::from_string(program, "MAIN.MPF");
  return test_support::trace_and_diagnostics(*reader);
}

// A word (`X12.5`, `Y-0.25`, `F300`, `Z.5`, `I7.`) as a program writes it, and the same value in a
// form that Cursor::plain_number declines: `X=12.5`, `X=(12.5)`, `X+12.5`, more than fifteen digits.
std::pair<std::string, std::string> random_word(std::mt19937_64& rng) {
  const char letter = "XYZIJKFSxy"[rng() % 10];
  const long long units = static_cast<long long>(rng() % 2000001) - 1000000;  // ten-thousandths, +-100
  const bool negative = units < 0;
  const unsigned long long u = static_cast<unsigned long long>(negative ? -units : units);
  std::string digits;
  switch (rng() % 5) {
    case 0: digits = fmt::format("{}", u / 10000); break;
    case 1: digits = fmt::format("{}.", u / 10000); break;
    case 2: digits = fmt::format(".{:04}", u % 10000); break;
    default: digits = fmt::format("{}.{:04}", u / 10000, u % 10000); break;
  }
  const std::string sign = negative ? "-" : "";
  const std::string plain = fmt::format("{}{}{}", letter, sign, digits);
  switch (rng() % 4) {
    case 0: return {plain, fmt::format("{}{}{}{}", letter, negative ? "-" : "+", std::string(16, '0'), digits)};
    case 1: return {plain, fmt::format("{}{}{}", letter, negative ? "-" : "+", digits)};
    case 2: return {plain, fmt::format("{}={}{}", letter, sign, digits)};
    default: return {plain, fmt::format("{}=({}{})", letter, sign, digits)};
  }
}

TEST(SinumerikReader, PlainNumbersAsTheGeneralPaths) {
  std::mt19937_64 rng(25);
  const char* heads[] = {"G0", "G1", "G2", "G3", "G01", "G4", "M3 S1000", "M5", "G91", "G90", "G18", "G17", "MARK1:", ""};
  for (int program = 0; program < 300; ++program) {
    std::string plain = "G90 G17\nF500\n", general = plain;
    for (int block = 0; block < 100; ++block) {
      const std::string head = fmt::format("{}{}", rng() % 2 ? fmt::format("N{} ", block * 10) : "", heads[rng() % std::size(heads)]);
      plain += head;
      general += head;
      for (std::size_t w = rng() % 5; w > 0; --w) {
        const auto [p, g] = random_word(rng);
        plain += " " + p;
        general += " " + g;
      }
      plain += '\n';
      general += '\n';
    }
    plain += "M30\n";
    general += "M30\n";
    SCOPED_TRACE(general);
    const auto fast = read(plain), slow = read(general);
    ASSERT_EQ(fast.first, slow.first);
    ASSERT_EQ(fast.second, slow.second);
  }
}

// A label after the block number is registered for GOTOB, and its block's words are executed.
TEST(SinumerikReader, LabelsAfterBlockNumbers) {
  const auto [trace, diagnostics] =
      read("N10 G90 G0 X0 Y0 Z5\nR1=0\nN20 LOOP1: G1 X=R1 F100\nN30 R1=R1+1\nN40 IF R1<3 GOTOB LOOP1\n  n50   DONE: G0 Z9\nM30\n");
  EXPECT_EQ(diagnostics, "");
  EXPECT_NE(trace.find("xpos:2.0 "), std::string::npos);
  std::size_t lines = 0;
  for (std::size_t at = trace.find("@line"); at != std::string::npos; at = trace.find("@line", at + 1)) ++lines;
  EXPECT_EQ(lines, 3u);
  EXPECT_NE(trace.find("zpos:9"), std::string::npos);
}

// What one block gives (a message, a tool name, a call's repeats, a cycle) is gone in the next.
TEST(SinumerikReader, BlocksStartEmpty) {
  const auto [trace, diagnostics] = read(
      "G90 G0 X0 Y0 Z5\nMSG(\"one\")\nG1 X1 F100\nT=\"DRILL\"\nM6\nT3\nM6\nM6\nCYCLE81(10,0,2,-5)\nG0 X5\nS2000\nM30\n");
  EXPECT_EQ(diagnostics, "");
  std::size_t messages = 0, changes = 0, named = 0, drills = 0;
  for (std::size_t at = trace.find("@message"); at != std::string::npos; at = trace.find("@message", at + 1)) ++messages;
  for (std::size_t at = trace.find("@change_tool"); at != std::string::npos; at = trace.find("@change_tool", at + 1)) ++changes;
  for (std::size_t at = trace.find("tool_name:"); at != std::string::npos; at = trace.find("tool_name:", at + 1)) ++named;
  for (std::size_t at = trace.find("zpos:-5"); at != std::string::npos; at = trace.find("zpos:-5", at + 1)) ++drills;
  EXPECT_EQ(messages, 1u);
  EXPECT_EQ(changes, 3u);
  EXPECT_EQ(named, 1u);  // the second and third changes are of tool 3
  EXPECT_EQ(drills, 1u);  // CYCLE81 without MCALL drills once, not again at X5
}

}  // namespace
