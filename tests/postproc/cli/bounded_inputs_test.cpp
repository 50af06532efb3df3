// The inputs an audit found read without bound (a device, a sparse file of 65 MiB): each now stops
// with exit 1 and an error naming the file (and line where there is one) and what was expected,
// instead of an allocation failure, a wrong message or a silent success (docs/reliability.md).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kPost = "../machines/fanuc/fanuc.gpp";
const std::string kPrp = "../machines/fanuc/fanuc.prp";
const std::string kJob = "../docs/examples/sample-job.trace";

TEST(BoundedInputs, EveryAuditedInputIsAnError) {
  const fs::path dir = fs::temp_directory_path() / ("cli_bounded_inputs_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string big = (dir / "big.gpp").string();
  std::ofstream(big, std::ios::binary) << "@start_of_job\nendp\n";
  fs::resize_file(big, std::uintmax_t{65} << 20);  // sparse: no disk space taken
  const std::string script = "../machines/pikocnc/scripts/front.pas";
  const struct {
    const char* name;
    std::vector<std::string> args;
    std::string error;  // a line of the output
  } cases[] = {
      {"PrpDevice", {"run", "--post", kPost, "--prp", "/dev/zero", kJob},
       "/dev/zero: larger than 64 MiB: not a PRP file?"},
      {"PostTooLarge", {"check", big},
       big + ":1:1: error 426: Error while reading file '" + big + "': larger than 64 MiB: not a GPPL post?"},
      {"PostDevice", {"run", "--post", "/dev/zero", kJob},
       "/dev/zero:1:1: error 426: Error while reading file '/dev/zero': larger than 64 MiB: not a GPPL post?"},
      {"Answers", {"run", "--post", kPost, "--prp", kPrp, "--answers", "/dev/zero", kJob},
       "/dev/zero:1:1: line longer than 1 MiB: not an answers file?"},
      {"ExpectedOutput", {"test", "--post", kPost, "--prp", kPrp, "--expect", "/dev/zero", kJob},
       kJob + ":2:1: command #0 @start_of_file: /dev/zero:1:1: line longer than 16 MiB: not an NC file?"},
      {"ScriptCheck", {"script", "check", "/dev/zero"}, "/dev/zero: larger than 16 MiB: not a PikoCNC script?"},
      {"ScriptRun", {"script", "run", "/dev/zero"}, "/dev/zero: larger than 16 MiB: not a PikoCNC script?"},
      {"ScriptParams", {"script", "run", script, "--params", "/dev/zero"},
       "/dev/zero: larger than 16 MiB: not a parameters file?"},
      {"TwoAxisProgram", {"read", "--dialect", "2xaxiscnc", "/dev/zero"},
       "/dev/zero:1:1: line longer than 16 MiB: not a 2XAxisCNC program?"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const auto r = test_support::run_cli(c.args);
    EXPECT_EQ(r.code, 1) << r.err;
    // The error is printed (by `check` on stdout, by the others on stderr), and nothing long with it.
    std::string shown = r.out + r.err;
    EXPECT_NE(shown.find(c.error + "\n"), std::string::npos) << shown.substr(0, 2000);
    EXPECT_LT(shown.size(), 2000u);
  }
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}

// A bad line of an answers file is quoted shortly, with its position.
TEST(BoundedInputs, AnswersLinesAreQuotedShortly) {
  const fs::path file = fs::temp_directory_path() / ("cli_bounded_answers_" + std::to_string(::getpid()) + ".txt");
  std::ofstream(file, std::ios::binary) << "# answers\n   " << std::string(1000, 'z') << "\n";
  const auto r = test_support::run_cli({"run", "--post", kPost, "--prp", kPrp, "--answers", file.string(), kJob});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, file.string() + ":2:4: expected NAME=VALUE (or a # comment), not `" + std::string(40, 'z') + "...`\n");
  fs::remove(file);
}

}  // namespace
