// The command line: dispatch, help, exit codes, and `read` printing a stream that reads back the same.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "postproc/cli.hpp"

namespace {

struct Run {
  int code;
  std::string out, err;
};

Run run(std::vector<std::string> args) {
  std::ostringstream out, err;
  int code = postproc::cli::main(args, out, err);
  return {code, out.str(), err.str()};
}

TEST(Cli, ExitCodes) {
  struct Case {
    std::vector<std::string> args;
    int code;
    const char* err_contains;
  } cases[] = {
      {{}, 2, "usage: postproc <command>"},
      {{"frobnicate"}, 2, "unknown command `frobnicate`"},
      {{"read"}, 2, "expected one input file"},
      {{"read", "--bogus", "x"}, 2, "unknown option --bogus"},
      {{"read", "--dialect"}, 2, "option --dialect needs a value"},
      {{"read", "--dialect=gcode", "x"}, 2, "unknown dialect `gcode`"},
      {{"read", "no/such.trace"}, 1, "no/such.trace:0:0: cannot open file"},
      {{"read", "toolpath/data/bad.trace"}, 1, "toolpath/data/bad.trace:3:6: expected `:` after the parameter name `ypos`"},
      {{"--help"}, 0, ""},
      {{"read", "--help"}, 0, ""},
      {{"--version"}, 0, ""},
  };
  for (const auto& c : cases) {
    auto r = run(c.args);
    EXPECT_EQ(r.code, c.code) << r.err;
    EXPECT_NE(r.err.find(c.err_contains), std::string::npos) << r.err;
  }
}

TEST(Cli, HelpListsCommandsAndOptions) {
  EXPECT_NE(run({"--help"}).out.find("read"), std::string::npos);
  EXPECT_NE(run({"read", "--help"}).out.find("--summary"), std::string::npos);
}

TEST(Cli, ReadPrintsCanonicalFormThatReadsBackTheSame) {
  auto first = run({"read", "golden/solidcam-fanuc/toolpath.trace"});
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_EQ(first.out.rfind("(1)@start_of_file   ==> program_number:5000", 0), 0u);
  std::size_t headers = 0;
  for (std::size_t p = 0; (p = first.out.find("\n(1)@", p)) != std::string::npos; ++p) ++headers;
  EXPECT_EQ(headers + 1, 210u);
}

TEST(Cli, ReadSummaryCountsCommands) {
  auto r = run({"read", "--summary", "golden/solidcam-fanuc/toolpath.trace"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("210 commands (210 stream commands)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("@drill_point                   4"), std::string::npos) << r.out;
}

}  // namespace
