// Procedure generation in two passes (docs/prp.md): with a way to reopen the job, the engine
// forecasts the main program from a skim of it and streams the bodies. The NC program and the
// warnings must be those of one pass; a job that is not what its skim forecast is posted again in
// one pass, its warnings said once.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "postproc/engine/engine.hpp"
#include "postproc/engine/parameter_check.hpp"
#include "prp/prp.hpp"
#include "shipped_posts.hpp"
#include "tests/support/golden_file.hpp"
#include "toolpath/trace_reader.hpp"

namespace {

namespace fs = std::filesystem;

// Three jobs as SolidCAM sends them to the shipped Fanuc post (gen_procs = Y): tool changes before
// and inside a job, a move between jobs, a deeper command, an arc over two continuation lines.
// program_number 12345 is outside prog_num_min .. prog_num_max: a warning.
const char* const kJob = R"((1)@start_of_file   ==> program_number:12345 g_file_name:'MULTI'
(1)@def_tool        ==> tool_number:4 tool_offset:5.0
(1)@def_tool        ==> tool_number:7 tool_offset:7.0
(1)@machine_plane   ==> machine_plane:XY
(1)@start_program   ==>
(1)@change_tool     ==> tool_number:4 tool_diameter:10.0 xnext:0.0 ynext:0.0 znext:50.0 spin:6000
(1)@start_of_job    ==> job_name:'F-ONE' job_type:'profile'
(1)@rapid_move      ==> xpos:40.0 ypos:0.0 zpos:5.0
(1)@line            ==> xpos:45.0 ypos:0.0 zpos:-0.5 feed:1500.0
(2)@internal        ==> a:1
(1)@arc             ==> xpos:50.0 ypos:5.0 zpos:-0.5 feed:1500.0 xcenter:45.0 ycenter:5.0 xcenter_rel:0.0
                    ..> ycenter_rel:5.0 radius:5.0 start_angle:270.0 end_angle:0.0 arc_direction:CCW arc_plane:XY
                    ..> arc_size:90.0
(1)@line            ==> xpos:50.0 ypos:45.0 zpos:-0.5 feed:1500.0
(1)@end_of_job      ==>
(1)@rapid_move      ==> xpos:50.0 ypos:45.0 zpos:50.0
(1)@start_of_job    ==> job_name:'F-TWO' job_type:'profile'
(1)@change_tool     ==> tool_number:7 tool_diameter:6.0 xnext:10.0 ynext:10.0 znext:50.0 spin:8000
(1)@rapid_move      ==> xpos:10.0 ypos:10.0 zpos:5.0
(1)@line            ==> xpos:10.0 ypos:10.0 zpos:-1.0 feed:800.0
(1)@line            ==> xpos:30.0 ypos:10.0 zpos:-1.0 feed:800.0
(1)@end_of_job      ==>
(1)@start_of_job    ==> job_name:'F-THREE' job_type:'profile'
(1)@line            ==> xpos:30.0 ypos:20.0 zpos:-1.0 feed:800.0
(1)@line            ==> xpos:10.0 ypos:20.0 zpos:-1.0 feed:800.0
(1)@end_of_job      ==>
(1)@end_program     ==>
(1)@end_of_file     ==>
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

class TwoPasses : public ::testing::Test {
protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("postproc-two-passes-" + std::to_string(::getpid()) + "-" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }

  struct Posted {
    std::string nc, warnings;
    int reopened = 0;
  };

  // Posts `job` with the shipped Fanuc post. Each reopen of the input gives the next of `reopens`
  // (the last one again when they run out); none: the engine cannot reopen it (one pass).
  Posted post(const std::string& job, const std::vector<std::string>& reopens, const std::string& machine = "fanuc") {
    std::vector<fs::path> files;
    for (std::size_t i = 0; i < reopens.size(); ++i) {
      files.push_back(dir / ("reopen" + std::to_string(i) + ".trace"));
      std::ofstream(files.back(), std::ios::binary) << reopens[i];
    }
    postproc::Engine engine(engine_test::shipped_post(machine));
    std::istringstream in(job);
    toolpath::TraceReader reader(in, "job.trace");
    postproc::OutputFiles output(dir, postproc::OutputFiles::LineEnd::LF, true);
    Posted posted;
    std::ostringstream warnings;
    postproc::RunOptions options;
    options.input_name = "job.trace";
    options.warnings = &warnings;
    if (!files.empty())
      options.reopen = [&]() -> std::unique_ptr<toolpath::CommandSource> {
        const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(posted.reopened++), files.size() - 1);
        return toolpath::TraceReader::open(files[i].string());
      };
    engine.run(reader, output, options);
    std::ostringstream nc;
    output.commit_to(nc);
    posted.nc = nc.str();
    posted.warnings = warnings.str();
    return posted;
  }

  fs::path dir;
};

TEST_F(TwoPasses, SameProgramAndWarningsAsOnePass) {
  const std::string jobs[] = {
      kJob,
      replaced(kJob, "(1)@end_of_file     ==>\n", ""),
      // SolidCAM's order: the tool change before its @start_of_job (docs/parity.md)
      replaced(replaced(kJob, "(1)@start_of_job    ==> job_name:'F-TWO' job_type:'profile'\n", ""),
               "(1)@rapid_move      ==> xpos:10.0 ypos:10.0 zpos:5.0\n",
               "(1)@start_of_job    ==> job_name:'F-TWO' job_type:'profile'\n"
               "(1)@rapid_move      ==> xpos:10.0 ypos:10.0 zpos:5.0\n"),
  };
  for (const std::string& job : jobs) {
    const Posted one = post(job, {});
    const Posted two = post(job, {job});
    EXPECT_EQ(two.reopened, 1);
    EXPECT_EQ(two.nc, one.nc);
    EXPECT_EQ(two.warnings, one.warnings);
    EXPECT_NE(one.nc.find("M98 P3 (F-THREE)"), std::string::npos) << one.nc;
    EXPECT_NE(one.warnings.find("job.trace:1:1: warning: command #0 @start_of_file: program number 12345"),
              std::string::npos)
        << one.warnings;
  }
}

// The skim the forecast came from is another job (a tool's offset differs outside the bodies): the
// run notices when it meets the difference, starts again in one pass over the job reopened, and
// writes what one pass writes, each warning once.
TEST_F(TwoPasses, RunStartsAgainWhenTheJobIsNotItsForecast) {
  const std::string other = replaced(kJob, "tool_number:7 tool_offset:7.0", "tool_number:7 tool_offset:8.0");
  const Posted one = post(kJob, {});
  const Posted again = post(kJob, {other, kJob});
  EXPECT_EQ(again.reopened, 2);  // the skim, then the job again
  EXPECT_EQ(again.nc, one.nc);
  EXPECT_EQ(again.warnings, one.warnings);
}

// A wrong value stops the run where one pass stops it: in the main program before the post has run
// any of it (the skim is checked too), in a body at the value's own position.
TEST_F(TwoPasses, WrongValuesStopTheRunAsInOnePass) {
  auto error_of = [&](const std::string& job, const std::vector<std::string>& reopens) {
    try {
      post(job, reopens);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string in_main = replaced(kJob, "tool_number:7 tool_offset:7.0", "tool_number:'seven' tool_offset:7.0");
  const std::string in_body = replaced(kJob, "xpos:30.0 ypos:10.0 zpos:-1.0", "xpos:30..0 ypos:10.0 zpos:-1.0");
  for (const std::string& job : {in_main, in_body}) {
    const std::string one = error_of(job, {});
    EXPECT_NE(one.find("job.trace:"), std::string::npos) << one;
    EXPECT_EQ(error_of(job, {job}), one);
  }
}

using test_support::slurp;

// Every example job through every shipped post whose PRP generates procedures: two passes (where
// the skim allows them) post what one pass posts, and fail where it fails.
TEST_F(TwoPasses, ShippedPostsOnTheExampleJobs) {
  int forecast = 0, posted = 0;
  for (const std::string& machine : engine_test::kShippedMachines) {
    const auto params = prp::load_file(engine_test::shipped_file(machine, "prp"), prp::Units::Metric);
    for (const std::string& path : engine_test::kExampleJobs) {
      SCOPED_TRACE(machine + " " + path);
      const std::string job = slurp(path);
      ASSERT_FALSE(job.empty());
      auto outcome = [&](const std::vector<std::string>& reopens) {
        try {
          return post(job, reopens, machine);
        } catch (const std::exception& e) {
          return Posted{"error", e.what(), 0};
        }
      };
      const Posted one = outcome({}), two = outcome({job});
      EXPECT_EQ(two.nc, one.nc);
      if (one.nc != "error") {
        ++posted;
        EXPECT_EQ(two.warnings, one.warnings);
      }
      std::istringstream in(job);
      toolpath::TraceReader skim(in, path);
      skim.skim_job_motions();
      // As the engine hands the skim to the forecast (a value the check refuses means no forecast).
      postproc::ParameterCheck checked(skim, path, {}, postproc::ParameterCheck::Deeper::Leave);
      if (prp::forecast_jobs(params, checked)) ++forecast;
    }
  }
  EXPECT_GE(posted, 40);    // of 50 (41 when written): some jobs need a machine the post is not for
  EXPECT_GE(forecast, 20);  // (21 when written) the flat jobs under the PRPs without motion-bound filters
}

}  // namespace
