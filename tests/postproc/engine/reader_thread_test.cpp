// The input read on the PRP filters' thread (two threads in all) or on one of its own (three):
// the same NC program, warnings and errors, for every shipped post on every example job and for
// jobs that stop on a wrong value or a broken line.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "postproc/engine/engine.hpp"
#include "shipped_posts.hpp"
#include "tests/support/golden_file.hpp"
#include "toolpath/trace_reader.hpp"

namespace {

namespace fs = std::filesystem;
using postproc::RunOptions;
using test_support::slurp;

// What a run wrote: the NC program and the warnings, or the error that stopped it.
struct Outcome {
  std::string nc, warnings, error;
};

Outcome post(const std::string& machine, const std::string& job, RunOptions::ReaderThread reader_thread) {
  const fs::path dir = fs::temp_directory_path() / ("postproc-reader-thread-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  Outcome outcome;
  try {
    postproc::Engine engine(engine_test::shipped_post(machine));
    std::istringstream in(job);
    toolpath::TraceReader reader(in, "job.trace");
    postproc::OutputFiles output(dir, postproc::OutputFiles::LineEnd::LF, true);
    std::ostringstream warnings, nc;
    RunOptions options;
    options.input_name = "job.trace";
    options.warnings = &warnings;
    options.reader_thread = reader_thread;
    engine.run(reader, output, options);
    output.commit_to(nc);
    outcome.nc = nc.str();
    outcome.warnings = warnings.str();
  } catch (const std::exception& e) {
    outcome.error = e.what();
  }
  fs::remove_all(dir);
  return outcome;
}

void expect_same_both_ways(const std::string& machine, const std::string& job) {
  const Outcome shared = post(machine, job, RunOptions::ReaderThread::Shared);
  const Outcome own = post(machine, job, RunOptions::ReaderThread::Own);
  EXPECT_EQ(own.nc, shared.nc);
  EXPECT_EQ(own.warnings, shared.warnings);
  EXPECT_EQ(own.error, shared.error);
}

TEST(ReaderThread, ShippedPostsOnTheExampleJobs) {
  for (const std::string& machine : engine_test::kShippedMachines) {
    for (const std::string& path : engine_test::kExampleJobs) {
      SCOPED_TRACE(machine + " " + path);
      const std::string job = slurp(path);
      ASSERT_FALSE(job.empty());
      expect_same_both_ways(machine, job);
    }
  }
}

// A wrong value, a broken line and a command without what it needs, early and late in the job:
// the same error (or warning) at the same place, and the lines before it.
TEST(ReaderThread, JobsThatStop) {
  const std::string job = slurp("../docs/examples/sample-job.trace");
  ASSERT_FALSE(job.empty());
  const std::size_t first_line = job.find("@line"), last_line = job.rfind("@line");
  ASSERT_NE(first_line, std::string::npos);
  ASSERT_NE(last_line, first_line);
  const std::string damages[] = {"@line xpos:'text' ", "@line xpos:1..5 ", "@line ==> ==> ", "@line\n$$$ "};
  int stopped = 0;
  for (const std::size_t at : {first_line, last_line}) {
    for (const std::string& damage : damages) {
      std::string damaged = job;
      damaged.replace(at, 5, damage);
      SCOPED_TRACE(damage);
      expect_same_both_ways("fanuc", damaged);
      stopped += !post("fanuc", damaged, RunOptions::ReaderThread::Own).error.empty();
    }
  }
  EXPECT_GT(stopped, 0);  // the damages do stop runs
}

}  // namespace
