// The 2XAxisCNC reader stops at a line longer than 16 MiB, in the program or in a script it runs,
// as the trace and PikoCNC readers do; its messages quote at most 40 characters of the program
// (docs/reliability.md).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "machines/2xaxiscnc/reader.hpp"
#include "toolpath/error.hpp"
#include "tests/support/read_error.hpp"

namespace fs = std::filesystem;

namespace {

TEST(ReaderLimits, LinesLongerThan16MiBAreAnError) {
  const fs::path dir = fs::temp_directory_path() / ("twoaxis_reader_limits_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string program = (dir / "program.nc").string(), script = (dir / "big.script").string();  // RunScript_big.script runs it
  std::ofstream(program, std::ios::binary) << "100 0\n";
  fs::resize_file(program, std::uintmax_t{17} << 20);  // sparse: a second line of 17 MiB of zeros
  std::ofstream(script, std::ios::binary) << "0 5\n";
  fs::resize_file(script, std::uintmax_t{17} << 20);
  twoaxis::Options with_scripts;
  with_scripts.scripts_folder = dir.string();
  const struct {
    const char* name;
    std::unique_ptr<twoaxis::TwoAxisReader> reader;
    std::string expected;
  } cases[] = {
      {"Device", twoaxis::TwoAxisReader::open("/dev/zero"),
       "/dev/zero:1:1: line longer than 16 MiB: not a 2XAxisCNC program?"},
      {"SecondLine", twoaxis::TwoAxisReader::open(program),
       program + ":2:1: line longer than 16 MiB: not a 2XAxisCNC program?"},
      {"InAScript", twoaxis::TwoAxisReader::from_string("10 10\nRunScript_big.script\n", "main.nc", with_scripts),
       script + ":2:1: line longer than 16 MiB: not a 2XAxisCNC program?"},
      {"JustUnderTheLimit", twoaxis::TwoAxisReader::from_string(std::string(15 << 20, ' ') + "XHYH\n", "blanks.nc"), ""},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(test_support::read_error(*c.reader), c.expected);
  }
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}

TEST(ReaderLimits, MessagesQuoteAShortPrefix) {
  const std::string x40(40, 'x'), d40(40, '1');
  const struct {
    const char* name;
    std::string program;
    std::string message;
  } cases[] = {
      {"UnknownInstruction", std::string(2 << 20, 'x') + "\n",
       "unknown instruction `" + x40 +
           "...`: expected a (comment), XHYH, X0Y0, SpEn, M03, M05, Out1..Out4, P<seconds>, "
           "Imp_<pin>_<interval>_<count>, A<mm>, AH or RunScript_<name>.script"},
      {"MalformedNumber", "5 " + std::string(2 << 20, '1') + "x\n", "malformed number `" + d40 + "...`: expected [-]digits[,digits]"},
      {"Pause", "P" + std::string(2 << 20, '1') + "x\n", "malformed number `" + d40 + "...`: expected [-]digits[,digits]"},
      {"ShortTextWhole", "Bogus\n",
       "unknown instruction `Bogus`: expected a (comment), XHYH, X0Y0, SpEn, M03, M05, Out1..Out4, P<seconds>, "
       "Imp_<pin>_<interval>_<count>, A<mm>, AH or RunScript_<name>.script"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    auto reader = twoaxis::TwoAxisReader::from_string(c.program, "p.nc");
    EXPECT_EQ(test_support::read_error(*reader), "");
    ASSERT_EQ(reader->diagnostics().kept().size(), 1u);
    EXPECT_EQ(reader->diagnostics().kept().front().message, c.message);
  }
}

}  // namespace
