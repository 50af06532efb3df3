// The ISO reader's shortcuts held to its general paths: a word's plain number against value() (the
// same random blocks with their numbers written so that only the general path reads them), and the
// O-number index, made on the first M98 far into a program, against the lines it must come back to.
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "machines/iso/reader.hpp"
#include "tests/support/read_back.hpp"

namespace {

// The trace and the diagnostics of `program` read with `dialect`.
std::pair<std::string, std::string> read(const std::string& program, const std::string& dialect) {
  const iso::Rules* rules = iso::rules_of(dialect);
  EXPECT_NE(rules, nullptr) << dialect;
  auto reader = iso::IsoReader::from_string(program, "test.nc", *rules);
  return test_support::trace_and_diagnostics(*reader);
}

// A number as a program writes it (`12.5`, `-0.25`, `3`, `.5`, `7.`), and the same value in a form
// that Cursor::plain_number declines: a blank before it, a `+`, more than fifteen digits, brackets.
struct Number {
  std::string plain, general;
};

Number random_number(std::mt19937_64& rng, bool brackets) {
  const long long units = static_cast<long long>(rng() % 2000001) - 1000000;  // ten-thousandths, +-100
  const bool negative = units < 0;
  const unsigned long long u = static_cast<unsigned long long>(negative ? -units : units);
  std::string digits;
  switch (rng() % 5) {
    case 0: digits = fmt::format("{}", u / 10000); break;                      // whole
    case 1: digits = fmt::format("{}.", u / 10000); break;                     // a point, no decimals
    case 2: digits = fmt::format(".{:04}", u % 10000); break;                  // no whole part
    default: digits = fmt::format("{}.{:04}", u / 10000, u % 10000); break;  // the usual
  }
  Number n;
  n.plain = (negative ? "-" : "") + digits;
  switch (rng() % (brackets ? 4 : 3)) {
    case 0: n.general = " " + n.plain; break;
    case 1: n.general = negative ? "- " + digits : "+" + digits; break;
    case 2: n.general = (negative ? "-" : "") + std::string(16, '0') + digits; break;
    default: n.general = "[" + n.plain + "]"; break;
  }
  return n;
}

// Random blocks of motion, feeds, spindle and dwell words, written both ways.
std::pair<std::string, std::string> random_program(std::mt19937_64& rng, bool brackets) {
  std::string plain = "%\nG90 G17\nF500\n", general = plain;
  const char* motion[] = {"G0", "G1", "G2", "G3", "G01", "G4", "M3 S1000", "M5", "G91", "G90", "G18", "G17"};
  for (int block = 0; block < 200; ++block) {
    const std::string head = fmt::format("N{} {}", block * 10, motion[rng() % std::size(motion)]);
    plain += head;
    general += head;
    const std::size_t words = rng() % 6;
    for (std::size_t w = 0; w < words; ++w) {
      const char letter = "XYZIJKRFPSxyz"[rng() % 13];
      const Number n = random_number(rng, brackets);
      plain += fmt::format(" {}{}", letter, n.plain);
      general += fmt::format(" {}{}", letter, n.general);
    }
    plain += '\n';
    general += '\n';
  }
  plain += "M30\n%\n";
  general += "M30\n%\n";
  return {plain, general};
}

TEST(IsoReader, PlainNumbersAsTheGeneralPath) {
  std::mt19937_64 rng(25);
  for (int program = 0; program < 200; ++program) {
    const std::string dialect = program % 4 == 0 ? "fanuc" : program % 4 == 1 ? "linuxcnc" : program % 4 == 2 ? "mach3" : "grbl";
    const auto [plain, general] = random_program(rng, dialect == "fanuc");
    SCOPED_TRACE(general);
    const auto fast = read(plain, dialect), slow = read(general, dialect);
    ASSERT_EQ(fast.first, slow.first);
    ASSERT_EQ(fast.second, slow.second);
  }
}

// M98 far into a program (past the line reader's first chunks), to a program number defined after
// M30 and given twice (the first counts): the index is made then, and the reading goes on where it
// was, with the right line numbers, as if the labels had been known from the start.
TEST(IsoReader, LabelsIndexedOnTheFirstCall) {
  std::string program = "%\nO1\nG90 G0 X0 Y0 Z5\n";
  const std::size_t filler = 40000;  // about 1 MB of comments before the call
  for (std::size_t i = 0; i < filler; ++i) program += "(a comment line that makes no motion at all)\n";
  program += "M98 P100\nG7\nM98 P100\nM30\nO100\nG1 X1 Y2 F100\nM99\nO100\nG1 X9 Y9\nM99\n%\n";
  const auto [trace, diagnostics] = read(program, "fanuc");
  const std::size_t call = filler + 4;  // the line of the first M98
  EXPECT_EQ(diagnostics, fmt::format("{}: warning: G7 is not modelled: ignored\n", call + 1));
  EXPECT_EQ(trace.find("xpos:9"), std::string::npos) << "the second O100 is run";
  std::size_t lines = 0;
  for (std::size_t at = trace.find("@line"); at != std::string::npos; at = trace.find("@line", at + 1)) ++lines;
  EXPECT_EQ(lines, 2u);
  // Without the filler, the same commands.
  std::string short_program = "%\nO1\nG90 G0 X0 Y0 Z5\nM98 P100\nG7\nM98 P100\nM30\nO100\nG1 X1 Y2 F100\nM99\nO100\nG1 X9 Y9\nM99\n%\n";
  EXPECT_EQ(read(short_program, "fanuc").first, trace);
}

// LinuxCNC's o-word subs are found by the same index, on their first call.
TEST(IsoReader, SubsIndexedOnTheFirstCall) {
  const std::string program =
      "o100 sub\nG1 X#1 Y2 F100\no100 endsub\nG90 G0 X0 Y0 Z5\no100 call [3]\no100 call [4]\no200 call\nM2\n";
  const auto [trace, diagnostics] = read(program, "linuxcnc");
  EXPECT_NE(trace.find("xpos:3"), std::string::npos);
  EXPECT_NE(trace.find("xpos:4"), std::string::npos);
  EXPECT_NE(diagnostics.find("7: warning: o200 call: no o200 sub in this file"), std::string::npos) << diagnostics;
}

}  // namespace
