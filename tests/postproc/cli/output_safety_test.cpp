// No half-written NC program: a run that fails half way, or whose output cannot be written (a full
// disk: /dev/full, a stream that refuses bytes), exits 1 and leaves the old file as it was.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <streambuf>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;

const std::string kJob = "../docs/examples/sample-job.trace";

// A post that writes lines for a while, then fails at the first arc (division by zero).
constexpr const char* kFailingPost =
    "@start_of_file\n  {nl, '%'}\nendp\n"
    "@rapid_move\n  {nl, 'G0 X', xpos}\nendp\n"
    "@line\n  {nl, 'G1 X', xpos}\nendp\n"
    "@arc\n  local numeric z\n  z = 0\n  z = xpos / z\n  {nl, 'G2 X', z}\nendp\n";

class OutputSafety : public testing::Test {
protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("postproc-output-safety-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "out");
    std::ofstream(dir / "fail.gpp") << kFailingPost;
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(OutputSafety, AFailedRunLeavesTheOldFileAndNoPartialFile) {
  const fs::path target = dir / "out" / "PART.NC";
  std::ofstream(target) << "OLD PROGRAM\n";
  for (const std::vector<std::string>& args : {
           std::vector<std::string>{"run", "--post", (dir / "fail.gpp").string(), kJob, "-o", target.string()},
           std::vector<std::string>{"run", "--post", (dir / "fail.gpp").string(), kJob, "-o", (dir / "out").string() + "/"},
       }) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("@arc"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(target), "OLD PROGRAM\n");
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(dir / "out")) left.push_back(e.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"PART.NC"}) << "a temporary or partial file was left";
  }
}

// A device is written through, never replaced by a regular file; a full one is an error.
TEST_F(OutputSafety, AFullDiskIsAnErrorAndTheDeviceStays) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  const auto r = run_cli({"run", "--post", "../machines/fanuc/fanuc.gpp", "--prp", "../machines/fanuc/fanuc.prp", kJob,
                          "-o", "/dev/full"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("cannot write `/dev/full`"), std::string::npos) << r.err;
  struct stat st {};
  ASSERT_EQ(::stat("/dev/full", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << "/dev/full was replaced";
}

// Standard output that takes no bytes (a full disk behind a redirection) fails the command.
TEST_F(OutputSafety, StdoutThatCannotBeWrittenIsAnError) {
  struct Full : std::streambuf {
    int overflow(int) override { return traits_type::eof(); }
    std::streamsize xsputn(const char*, std::streamsize) override { return 0; }
  } full;
  for (const std::vector<std::string>& args : {
           std::vector<std::string>{"run", "--post", "../machines/fanuc/fanuc.gpp", "--prp", "../machines/fanuc/fanuc.prp", kJob},
           std::vector<std::string>{"read", kJob},
       }) {
    std::ostream out(&full);
    std::ostringstream err;
    EXPECT_EQ(postproc::cli::main(args, out, err), 1) << args[0];
    EXPECT_NE(err.str().find("cannot write the output"), std::string::npos) << err.str();
  }
}

}  // namespace
