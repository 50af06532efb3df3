// The benchmarks' two posts of the synthetic job, kept honest:
// - the 1M-command job (make_job 1000000, both shapes) still posts to the NC program the engine
//   wrote when the hand-written post was made (issue 25): a change in the engine, the shipped
//   Fanuc post or PRP, or the job generator that changes one byte of it fails here;
// - the hand-written post (bench/hand_post.hpp) writes the engine's bytes on smaller jobs of both
//   shapes, so that ceiling_bench cannot rot, and refuses what it does not cover.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "bench/hand_post.hpp"
#include "bench/synthetic_job.hpp"
#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

// A file in the temporary folder, removed with the object.
struct TempFile {
  fs::path path;
  explicit TempFile(const std::string& name)
      : path(fs::temp_directory_path() / ("hand-post-test-" + std::to_string(::getpid()) + "-" + name)) {}
  ~TempFile() {
    std::error_code ignored;
    fs::remove(path, ignored);
  }
};


// `postproc run -q --post machines/fanuc/fanuc.gpp --prp machines/fanuc/fanuc.prp -o NC JOB`.
void post_with_engine(const fs::path& job, const fs::path& nc) {
  const auto run = test_support::run_cli({"run", "--quiet", "--post", "../machines/fanuc/fanuc.gpp", "--prp",
                                          "../machines/fanuc/fanuc.prp", "-o", nc.string(), job.string()});
  ASSERT_EQ(run.code, 0) << run.err;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// 64-bit FNV-1a of a file, with its size and its number of line breaks.
struct Digest {
  std::uint64_t fnv1a = 14695981039346656037ull;
  std::uint64_t bytes = 0, line_breaks = 0;
};

Digest digest_of(const fs::path& path) {
  Digest d;
  std::ifstream in(path, std::ios::binary);
  std::string block(1 << 20, '\0');
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    for (std::size_t i = 0; i < n; ++i) {
      const auto byte = static_cast<unsigned char>(block[i]);
      d.fnv1a = (d.fnv1a ^ byte) * 1099511628211ull;
      d.line_breaks += byte == '\n';
    }
    d.bytes += n;
  }
  return d;
}

// Today's NC program of the 1M-command job, either shape (the same program): the engine's output
// at the commit that added this test. It starts `%`, `O1234 (BENCH)`, and ends `N1170 M99`, `%`
// with no line break after the last `%`.
constexpr std::uint64_t kMillionFnv1a = 0xfb8e09659ea407d8ull;
constexpr std::uint64_t kMillionBytes = 20142500;
constexpr std::uint64_t kMillionLineBreaks = 1000020;

void expect_todays_million_program(bench::JobShape shape) {
  const TempFile job("million.trace"), nc("million.nc");
  bench::write_job(job.path.string(), 1'000'000, shape);
  post_with_engine(job.path, nc.path);
  const Digest d = digest_of(nc.path);
  EXPECT_EQ(d.bytes, kMillionBytes);
  EXPECT_EQ(d.line_breaks, kMillionLineBreaks);
  EXPECT_EQ(d.fnv1a, kMillionFnv1a) << std::hex << "FNV-1a 0x" << d.fnv1a;
}

TEST(MillionCommandJob, ProceduresShapePostsTodaysProgram) { expect_todays_million_program(bench::JobShape::procedures); }

TEST(MillionCommandJob, FlatShapePostsTodaysProgram) { expect_todays_million_program(bench::JobShape::flat); }

// The hand-written post against the engine on a job of `motions`: from the file (read in blocks)
// and from text.
void expect_hand_post_agrees(std::size_t motions, bench::JobShape shape) {
  const TempFile job("agree.trace"), engine_nc("agree-engine.nc"), hand_nc("agree-hand.nc");
  bench::write_job(job.path.string(), motions, shape);
  post_with_engine(job.path, engine_nc.path);
  const std::string engine = read_file(engine_nc.path);
  ASSERT_FALSE(engine.empty());

  const bench::hand_post::Stats stats = bench::hand_post::post_file(job.path.string(), hand_nc.path.string());
  EXPECT_TRUE(read_file(hand_nc.path) == engine) << "the hand-written post's NC differs from the engine's";
  EXPECT_EQ(stats.bytes, engine.size());
  EXPECT_FALSE(fs::exists(hand_nc.path.string() + ".part"));
  EXPECT_TRUE(bench::hand_post::post_text(read_file(job.path)) == engine);
}

TEST(HandPost, WritesTheEnginesProgramForASmallJobOfEitherShape) {
  for (std::size_t motions : {0, 1, 2, 8, 41}) {
    SCOPED_TRACE(motions);
    expect_hand_post_agrees(motions, bench::JobShape::procedures);
    expect_hand_post_agrees(motions, bench::JobShape::flat);
  }
}

// 20 000 motions: block numbers past N99990 start again at N10 (twice), the feed and the depth
// change lap after lap, and the 3 MB trace is read in several blocks.
TEST(HandPost, WritesTheEnginesProgramForALongerJobOfEitherShape) {
  expect_hand_post_agrees(20'000, bench::JobShape::procedures);
  expect_hand_post_agrees(20'000, bench::JobShape::flat);
}

std::string job_text(std::size_t motions, bench::JobShape shape) {
  std::ostringstream text;
  bench::write_job(text, motions, shape);
  return text.str();
}

// The precision filter's rules where make_job's values (0.5-mm steps) do not reach them: the
// lines' coordinates moved by a few ten-thousandths to a few thousandths (below and above the
// 0.001 of zero_value and of "an axis that barely moved keeps its value", around zero too,
// rounding halves), written with exponents, long digits or change flags; some feeds off the tenth.
TEST(HandPost, FiltersNudgedCoordinatesAsTheEngineDoes) {
  const double deltas[] = {0,       0.0004,    -0.0004,   0.0005,     -0.0005, 0.0006, -0.0006, 0.001,  -0.001,
                           0.0015,  -0.0015,   0.0009999, -0.0009999, 0.00100001, 0.002, 0.0025, -0.0025};
  const char* feeds[] = {"1500.05", "1499.95", "1500.04999", "1200.25", "1e3", "1200.0"};
  std::uint32_t random = 12345;  // a fixed sequence (LCG)
  auto next = [&random](std::uint32_t n) {
    random = random * 1664525u + 1013904223u;
    return (random >> 8) % n;
  };
  std::istringstream in(job_text(400, bench::JobShape::procedures));
  std::string trace, line;
  while (std::getline(in, line)) {
    if (line.rfind("(1)@line", 0) == 0) {
      std::istringstream words(line);
      std::string word, changed;
      while (words >> word) {
        const auto colon = word.find(':');
        const std::string name = colon == std::string::npos ? "" : word.substr(0, colon);
        if (name == "xpos" || name == "ypos" || name == "zpos") {
          const double v = std::stod(word.substr(colon + 1)) + deltas[next(std::size(deltas))];
          char text[40];
          switch (next(5)) {
            case 0: std::snprintf(text, sizeof text, "%.6e", v); break;
            case 1: std::snprintf(text, sizeof text, "%.17f", v); break;
            case 2: std::snprintf(text, sizeof text, "%.7fT", v); break;
            case 3: std::snprintf(text, sizeof text, "%.7fF", v); break;
            default: std::snprintf(text, sizeof text, "%.4f", v); break;
          }
          word = name + ":" + text;
        } else if (name == "feed" && next(8) == 0) {
          word = std::string("feed:") + feeds[next(std::size(feeds))];
        }
        changed += (changed.empty() ? "" : " ") + word;
      }
      line = changed;
    }
    trace += line + '\n';
  }
  const TempFile job("nudged.trace"), nc("nudged.nc");
  std::ofstream(job.path, std::ios::binary) << trace;
  post_with_engine(job.path, nc.path);
  const std::string engine = read_file(nc.path);
  ASSERT_FALSE(engine.empty());
  EXPECT_TRUE(bench::hand_post::post_text(trace) == engine) << "the hand-written post's NC differs from the engine's";
  EXPECT_NE(engine.find(".001 "), std::string::npos);  // some nudges survive the filter
}

TEST(HandPost, RefusesWhatMakeJobDoesNotWrite) {
  const std::string job = job_text(8, bench::JobShape::procedures);
  auto refused = [](const std::string& trace) {
    try {
      bench::hand_post::post_text(trace);
    } catch (const bench::hand_post::OutOfScope&) {
      return true;
    }
    return false;
  };
  ASSERT_FALSE(refused(job));
  std::string rapid = job;  // a command it does not know
  rapid.replace(rapid.find("(1)@line      "), 14, "(1)@rapid_move");
  EXPECT_TRUE(refused(rapid));
  std::string depth = job;  // a nested command
  depth.replace(depth.find("(1)@line"), 3, "(2)");
  EXPECT_TRUE(refused(depth));
  std::string big_arc = job;  // an arc the PRP linearises (radius above arc_max_radius)
  big_arc.replace(big_arc.find("radius:5.0"), 10, "radius:5000.0");
  EXPECT_TRUE(refused(big_arc));
  EXPECT_TRUE(refused(job.substr(0, job.find("(1)@end_of_file"))));  // cut short
  const std::string flat = job_text(8, bench::JobShape::flat);
  ASSERT_FALSE(refused(flat));
  std::string two_jobs = flat;  // a second flat job
  two_jobs.insert(two_jobs.find("(1)@end_program"), "(1)@start_of_job    ==> job_name:'TWO'\n(1)@end_of_job      ==>\n");
  EXPECT_TRUE(refused(two_jobs));
}

}  // namespace
