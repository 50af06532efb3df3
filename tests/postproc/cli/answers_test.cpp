// --answer and --answers: the answers reach the post's input statements on every subcommand that
// runs a post; the run log (stderr) names prompt, variable, value and source; a value of the
// wrong type is an error, an answer nobody reads a warning (docs/gppl-language.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace {

const auto run = test_support::run_cli;
const std::string kDir = "golden/real-syntax/";
const std::vector<std::string> kPost = {"--post", kDir + "post.gpp"};

std::vector<std::string> with(std::vector<std::string> head, const std::vector<std::string>& tail) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

TEST(Answers, LogOfEverySubcommand) {
  const std::string expected_log =
      "golden/real-syntax/post.gpp:23:3: input 'Program number?': program_nr = 12 (answer from --answer "
      "PROGRAM_NR=12)\n"
      "golden/real-syntax/post.gpp:24:3: input 'Operator': operator_name = 'nobody' (no answer: value kept)\n"
      "golden/real-syntax/post.gpp:25:3: input 'Use CYCLE832 (0/1)?': use_cycle832 = FALSE (no answer: value kept)\n"
      "golden/real-syntax/post.gpp:26:3: input 'Tolerance 0.01?': tolerance_text = '0.01' (no answer: value kept)\n"
      "golden/real-syntax/post.gpp:27:3: print: posting program 12 for nobody\n"
      "golden/real-syntax/post.gpp:75:3: print: tools: MILL;LARGE; last block 130\n";
  // With -q the input lines go and the post's own print messages stay.
  const std::string quiet_log = expected_log.substr(expected_log.find("golden/real-syntax/post.gpp:27:3"));
  for (const char* command : {"run", "explain", "test"}) {
    SCOPED_TRACE(command);
    auto r = run(with({command, kDir + "job.trace", "--answer", "PROGRAM_NR=12", "-q"}, kPost));
    EXPECT_EQ(r.err, quiet_log);
    EXPECT_EQ(run(with({command, kDir + "job.trace", "--answer", "PROGRAM_NR=12"}, kPost)).err.find(expected_log), 0u);
    if (std::string(command) == "run") {
      EXPECT_NE(r.out.find("O0012 (NOBODY)"), std::string::npos) << r.out;
      EXPECT_EQ(r.out.find("print"), std::string::npos);  // the log never reaches the NC output
    }
  }
}

TEST(Answers, FileThenCommandLine) {
  auto r = run(with({"run", kDir + "job.trace", "--answers", kDir + "answers.txt", "--answer", "program_nr=5",
                     "--answer", "use_cycle832=true"},
                    kPost));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("O0005 (ADA LOVELACE)\nN10 G21 G17 G90\nN20 CYCLE832(0.005,1)"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("program_nr = 5 (answer from --answer program_nr=5)"), std::string::npos) << r.err;
}

TEST(Answers, Problems) {
  const std::filesystem::path bad = std::filesystem::temp_directory_path() / "postproc-bad-answers.txt";
  std::ofstream(bad) << "# fine\n\nprogram_nr = 3\n  = 4\n";
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string err;
  } cases[] = {
      {{"--answer", "program_nr"}, 2, "postproc run: --answer needs NAME=VALUE, not `program_nr`"},
      {{"--answer", "=3"}, 2, "postproc run: --answer needs NAME=VALUE, not `=3`"},
      {{"--answer", "program_nr=12.5"}, 1,
       "golden/real-syntax/post.gpp:23:3: error 386: Variable is not numeric: --answer program_nr=12.5: program_nr "
       "needs an integer, not '12.5'\n"},
      {{"--answer", "use_cycle832=maybe"}, 1,
       "golden/real-syntax/post.gpp:25:3: error 420: Numeric expression is not of logical type: --answer "
       "use_cycle832=maybe: use_cycle832 needs a logical (0, 1, TRUE or FALSE), not 'maybe'\n"},
      {{"--answers", "no/such/answers.txt"}, 1, "no/such/answers.txt: cannot open the answers file\n"},
      {{"--answers", bad.string()}, 1, bad.string() + ":4:3: expected NAME=VALUE (or a # comment), not `= 4`\n"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args.back());
    auto r = run(with(with({"run", kDir + "job.trace", "-q"}, kPost), c.args));
    EXPECT_EQ(r.code, c.code) << r.err;
    if (c.code == 2)
      EXPECT_EQ(r.err.find(c.err), 0u) << r.err;
    else
      EXPECT_EQ(r.err, c.err);
  }
  std::filesystem::remove(bad);
}

TEST(Answers, UnreadAnswerWarnsOnce) {
  auto r = run(with({"run", kDir + "job.trace", "-q", "--answer", "spindle=1", "--answer", "spindle=2"}, kPost));
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.err.find("--answer spindle=2: warning: no input statement reads 'spindle'\n"), 0u) << r.err;
  EXPECT_EQ(r.err.find("spindle=1"), std::string::npos) << r.err;
}

TEST(Answers, VerifyAndHelpKnowTheOptions) {
  for (const char* command : {"run", "test", "explain", "verify"}) {
    auto help = run({command, "--help"}).out;
    EXPECT_NE(help.find("--answer VALUE"), std::string::npos) << command;
    EXPECT_NE(help.find("--answers VALUE"), std::string::npos) << command;
  }
}

}  // namespace
