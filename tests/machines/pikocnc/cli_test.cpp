// `postproc read --dialect pikocnc` and `postproc plot` on G-code and traces.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "postproc/cli/cli.hpp"
#include "tests/support/cli_run.hpp"

namespace {

using Run = test_support::CliRun;
const auto run = test_support::run_cli;

using test_support::slurp;

TEST(PikoCli, ReadPrintsTheStreamAndWarnings) {
  const auto r = run({"read", "--dialect", "pikocnc", "machines/pikocnc/golden/ignored_words_and_codes/program.nc"});
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, slurp("machines/pikocnc/golden/ignored_words_and_codes/expected.trace"));
  EXPECT_NE(r.err.find("program.nc:5:1: warning: unknown code G82 ignored"), std::string::npos) << r.err;
}

TEST(PikoCli, ReadErrorNamesLineAndColumn) {
  const auto r = run({"read", "--dialect=pikocnc-2016", "machines/pikocnc/golden/error_arc_radius_too_small/program.nc"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("program.nc:3:11: arc radius 4.9 does not fit"), std::string::npos) << r.err;
}

TEST(PikoCli, ReadAttachesNcLinesOnRequest) {
  const auto r = run({"read", "--dialect", "pikocnc", "--nc-lines", "machines/pikocnc/golden/g81_drilling/program.nc"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("                      > G81 X40 Y100 Z-3.2 R1.0 F150\n"), std::string::npos) << r.out;
}

TEST(PikoCli, PlotWritesSvgAtomically) {
  const std::string out = (std::filesystem::temp_directory_path() / "pikocnc_plot_test.svg").string();
  std::filesystem::remove(out);
  const auto r = run({"plot", "machines/pikocnc/data/plot.nc", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string svg = slurp(out);
  EXPECT_FALSE(std::filesystem::exists(out + ".tmp"));
  EXPECT_NE(svg.find("stroke-dasharray=\"4 3\" vector-effect=\"non-scaling-stroke\" d=\"M0 30L50 50\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("d=\"M0 0L20 0A10 10 0 0 1 30 10A10 10 0 0 0 30 30L0 30A5 5 0 0 1 0 20A5 5 0 0 1 0 30M50 50"),
            std::string::npos) << svg;
  std::filesystem::remove(out);
}

TEST(PikoCli, PlotReadsTraces) {
  const std::string out = (std::filesystem::temp_directory_path() / "pikocnc_plot_trace.svg").string();
  const auto r = run({"plot", "golden/solidcam-fanuc/toolpath.trace", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(slurp(out).find("A15 15 0 0 0 -8.35 -24.565"), std::string::npos);
  std::filesystem::remove(out);
}

TEST(PikoCli, PlotNeedsAnOutput) {
  EXPECT_EQ(run({"plot", "machines/pikocnc/data/plot.nc"}).code, 2);
  EXPECT_EQ(run({"plot", "no/such.nc", "-o", "/tmp/x.svg"}).code, 1);
}

}  // namespace
