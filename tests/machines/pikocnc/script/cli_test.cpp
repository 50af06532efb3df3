// `postproc script run|check`: the parametric example of machines/pikocnc/scripts/ (golden G-code,
// read back through `postproc read`), the options of spec section 10, errors and exit codes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
const auto run = test_support::run_cli;
using test_support::slurp;

const std::string kFront = "../machines/pikocnc/scripts/front.pas";

fs::path temp(const char* name) { return fs::temp_directory_path() / name; }

TEST(ScriptCli, FrontExampleGolden) {
  const auto r = run({"script", "run", kFront, "--arg", "6=yes"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, slurp("machines/pikocnc/script/front/rounded.nc"));
}

TEST(ScriptCli, FrontExampleWithTheIssuesCommandLineWritesAFileThePikoReaderReads) {
  const std::string out = temp("script_cli_front.nc").string();
  const auto r = run({"script", "run", kFront, "--arg", "0=150", "--arg", "4=Prosta", "--const", "MAT_SIZE_X=600",
                      "--answer", "yes", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(out), slurp("machines/pikocnc/script/front/straight.nc"));
  EXPECT_FALSE(fs::exists(out + ".tmp"));
  const auto back = run({"read", "--dialect", "pikocnc", out});
  EXPECT_EQ(back.code, 0) << back.err;
  EXPECT_NE(back.out.find("@line            ==> xpos:150.0 ypos:0.0 zpos:-6.0"), std::string::npos) << back.out;
  fs::remove(out);
}

TEST(ScriptCli, DescribeArgsPrintsJsonAndNoGcode) {
  const auto r = run({"script", "run", kFront, "--describe-args"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.substr(0, 2), "{\n");
  EXPECT_NE(r.out.find("{\"arg\": 4, \"label\": \"Górna linia\", \"kind\": \"combo\", \"items\": [\"Łuk\", \"Prosta\"], \"value\": 0}"),
            std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('%'), std::string::npos);
}

TEST(ScriptCli, ParamsFile) {
  const auto params = temp("script_cli_params.ini");
  std::ofstream(params) << "[args]\n0 = 150\n4 = Prosta\n[constants]\nMAT_SIZE_X = 600\n";
  const auto r = run({"script", "run", kFront, "--params", params.string()});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, slurp("machines/pikocnc/script/front/straight.nc"));
  fs::remove(params);
}

TEST(ScriptCli, ErrorsNameTheFileAndLeaveNoOutput) {
  const std::string out = temp("script_cli_bad.nc").string();
  fs::remove(out);
  auto r = run({"script", "run", kFront, "--arg", "5=1800.5", "-o", out});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("front.pas:46:3: argument 5 (`Szybkość obróbki w osi XY (mm/min)`) is an integer field"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  const auto bad = temp("script_cli_bad.pas");
  std::ofstream(bad) << "var x: Integer;\nbegin\n  x := 1 div 0;\nend.\n";
  r = run({"script", "check", bad.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("script_cli_bad.pas:3:10: division by zero"), std::string::npos) << r.err;
  fs::remove(bad);
  r = run({"script", "run", kFront, "--answer", "maybe"});
  EXPECT_EQ(r.code, 2);
  r = run({"script", "frobnicate", kFront});
  EXPECT_EQ(r.code, 2);
  r = run({"script", "check", kFront});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("front.pas: ok"), std::string::npos);
}

}  // namespace
