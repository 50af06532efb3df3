// The benchmark's synthetic job: its two shapes are the same job. Posted through the shipped
// Fanuc post and PRP (gen_procs = Y), the flat shape (restructured by prp::ProcedureGeneration)
// and the procedure shape (as SolidCAM sends it) must give the same NC program, so the benchmark
// figures of both shapes measure the same work.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "bench/synthetic_job.hpp"
#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

// The job written as a trace and read back (what the benchmark does with its file).
std::string trace_of(bench::JobShape shape, std::size_t motions) {
  std::ostringstream text;
  bench::write_job(text, motions, shape);
  return text.str();
}

// The main program `postproc run` prints for `trace` with the shipped Fanuc post.
std::string post(const std::string& trace, const std::string& prp) {
  const fs::path file = fs::temp_directory_path() / ("synthetic-job-test-" + std::to_string(::getpid()) + ".trace");
  std::ofstream(file, std::ios::binary) << trace;
  const auto run = test_support::run_cli({"run", "--quiet", "--post", "../machines/fanuc/fanuc.gpp", "--prp", prp, file.string()});
  fs::remove(file);
  EXPECT_EQ(run.code, 0) << run.err;
  return run.out;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SyntheticJob, BothShapesPostTheSameProgramWithProcedureGeneration) {
  const std::string flat = trace_of(bench::JobShape::flat, 40);
  const std::string procedures = trace_of(bench::JobShape::procedures, 40);
  ASSERT_NE(flat, procedures);
  EXPECT_EQ(count(procedures, "@call_proc"), 1u);
  EXPECT_EQ(count(procedures, "@end_proc"), 1u);
  EXPECT_EQ(count(flat, "@call_proc"), 0u);

  const std::string nc = post(procedures, "../machines/fanuc/fanuc.prp");
  EXPECT_EQ(post(flat, "../machines/fanuc/fanuc.prp"), nc);
  EXPECT_EQ(count(nc, " M98 P1 (F-BENCH)\n"), 1u);  // the main program calls the job
  EXPECT_EQ(count(nc, "\nO1\n"), 1u);               // which follows it as subroutine 1
  EXPECT_EQ(count(nc, " M99\n"), 1u);
  EXPECT_EQ(count(nc, " G1 ") + count(nc, " G3 "), 40u);  // one block per motion
}

TEST(SyntheticJob, ShapesDifferOnlyAroundTheMotions) {
  // Same motions, in the same order, in both shapes.
  auto motions = [](bench::JobShape shape) {
    bench::SyntheticJob job(100, shape);
    toolpath::Command c;
    std::string names;
    while (job.next(c))
      if (c.name == "@line" || c.name == "@arc") names += c.name;
    return names;
  };
  EXPECT_EQ(motions(bench::JobShape::flat), motions(bench::JobShape::procedures));
  EXPECT_EQ(count(motions(bench::JobShape::flat), "@"), 100u);
}

}  // namespace
