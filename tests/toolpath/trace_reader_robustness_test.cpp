// Mutated inputs never crash the reader: each one either reads or fails with a positioned message.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>

#include "toolpath/trace_reader.hpp"
#include "tests/support/random_edits.hpp"
#include "tests/support/read_error.hpp"

namespace {

std::string slurp(const char* path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// Reads everything; returns "" on success or the error text.
std::string try_read(const std::string& text) {
  std::istringstream in(text);
  toolpath::TraceReader reader(in, "m.trace");
  return test_support::read_error(reader);
}

TEST(TraceReaderRobustness, MutationsReadOrFailWithAPosition) {
  const std::string seeds[] = {slurp("toolpath/data/solidcam_layout.trace"),
                               slurp("golden/solidcam-fanuc/toolpath.trace").substr(0, 4000)};
  const char alphabet[] = "()@:'\" \t\r\n.>=!TF-+eE0123456789abcXYZ_;";
  const std::regex positioned(R"(^m\.trace:\d+:\d+: .+)");
  std::mt19937 rng(20261121);  // fixed seed: a failure reproduces
  int failures = 0;
  for (const std::string& seed : seeds) {
    ASSERT_FALSE(seed.empty());
    for (int round = 0; round < 1500; ++round) {
      std::string text = seed;
      test_support::random_edits(text, rng, std::string_view(alphabet, sizeof alphabet - 1), 1 + static_cast<int>(rng() % 4));
      const std::string error = try_read(text);
      if (!error.empty()) {
        ++failures;
        EXPECT_TRUE(std::regex_match(error, positioned)) << error;
      }
    }
  }
  EXPECT_GT(failures, 0);  // the mutations do reach the error paths
}

}  // namespace

namespace {

// A line without end (a binary file, a runaway generator) stops at 16 MiB instead of taking memory
// without bound; one just under the limit still reads.
TEST(TraceReaderRobustness, LinesLongerThanTheLimitAreAnError) {
  const std::string head = "@start_of_file\nmsg : '";
  EXPECT_EQ(try_read(head + std::string((16 << 20) - 100, 'a') + "'\n"), "");
  EXPECT_EQ(try_read(head + std::string(17 << 20, 'a')), "m.trace:2:1: line longer than 16 MiB: not a trace file?");
}

}  // namespace
