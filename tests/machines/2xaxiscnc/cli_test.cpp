// `postproc read/plot/run/verify --dialect 2xaxiscnc`.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/cli_run.hpp"

namespace {

const auto run = test_support::run_cli;
using test_support::slurp;

const std::string kPost = "../machines/2xaxiscnc/2xaxiscnc.gpp";
const std::string kPrp = "../machines/2xaxiscnc/2xaxiscnc.prp";

TEST(TwoAxisCli, ReadPrintsTheStream) {
  const auto r = run({"read", "--dialect", "2xaxiscnc", "machines/2xaxiscnc/golden/tv2_artcam_conversion/program.nc"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("@marker          ==> kind:'ArtCam' converted:true"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("@line            ==> xpos:20.0 ypos:10.0 feed:1500.0 speed_coef:0.5 coef_changed:true"), std::string::npos)
      << r.out;
}

TEST(TwoAxisCli, ReadErrorsNameLineAndColumnAndFail) {
  const auto r = run({"read", "--dialect", "2xaxiscnc", "machines/2xaxiscnc/golden/tv9_reader_errors/program.nc"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("program.nc:2:7: error: 4 commands in a frame"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("program.nc:4:5: error: speed coefficient 1,5 out of range"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("program.nc:2:7: 5 error(s) in the program"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("@end_of_file"), std::string::npos) << "the stream is printed before the failure";
}

TEST(TwoAxisCli, PlotDrawsAProgram) {
  const std::string out = (std::filesystem::temp_directory_path() / "twoaxis_plot_test.svg").string();
  const auto r = run({"plot", "--dialect", "2xaxiscnc", "machines/2xaxiscnc/golden/tv1_reader_basics/program.nc", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(slurp(out).find("<svg"), std::string::npos);
  std::filesystem::remove(out);
}

TEST(TwoAxisCli, RunPostsAProgramAgain) {
  const auto r = run({"run", "--dialect", "2xaxiscnc", "--post", kPost, "--prp", kPrp,
                      "machines/2xaxiscnc/golden/tv1_reader_basics/program.nc"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("M03\nP2,5\n5,5 -3 1\n2 0 0,7\n-7,5 3\n"), std::string::npos) << r.out;
}

// The trace `read --dialect 2xaxiscnc` writes posts like the program it came from: it names its
// dialect, so its motions are not asked for the Z and feed a 2-axis machine does not have.
TEST(TwoAxisCli, ItsTracePostsAgain) {
  const auto r = run({"run", "--post", kPost, "--prp", kPrp, "machines/2xaxiscnc/golden/tv1_reader_basics/expected.trace"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("M03\nP2,5\n5,5 -3 1\n2 0 0,7\n-7,5 3\n"), std::string::npos) << r.out;
}

TEST(TwoAxisCli, VerifyFindsAMirroredProgram) {
  const auto ok = run({"verify", "--dialect", "2xaxiscnc", "--post", kPost, "--prp", kPrp, "../docs/examples/planes-helix.trace"});
  EXPECT_EQ(ok.code, 0) << ok.out << ok.err;
  const auto bad = run({"verify", "--dialect", "2xaxiscnc", "--post", kPost, "--prp", kPrp, "--answer", "flip_y=TRUE",
                        "../docs/examples/planes-helix.trace"});
  EXPECT_EQ(bad.code, 1) << bad.out;
  EXPECT_NE(bad.out.find("end point differs in Y"), std::string::npos) << bad.out;
}

TEST(TwoAxisCli, VerifyComparesCoefficients) {
  // The post writes coefficients for 6000 mm/min while verify is told the machine makes 3000.
  const auto r = run({"verify", "--dialect", "2xaxiscnc", "--post", kPost, "--prp", kPrp, "--answer",
                      "machine_speed=6000", "machines/2xaxiscnc/post/tv4_square.trace"});
  EXPECT_EQ(r.code, 0) << r.out << r.err;  // verify reads the same answer: consistent
}

TEST(TwoAxisCli, VerifyRefusesUnknownDialects) {
  const auto r = run({"verify", "--dialect", "heidenhain", "--post", kPost, "--prp", kPrp, "../docs/examples/planes-helix.trace"});
  EXPECT_EQ(r.code, 2);
}

}  // namespace
