// Every input a fuzz target once failed on (tests/fuzz/regressions/<target>/<file>) goes through
// the same entry point again, under this build's ASan+UBSan: the suite keeps the fixes without clang.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/fuzz/entries.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = "fuzz/regressions";

std::vector<std::string> kept_inputs() {
  std::vector<std::string> all;
  if (!fs::exists(kRoot)) return all;
  for (const auto& target : fs::directory_iterator(kRoot))
    if (target.is_directory())
      for (const auto& file : fs::directory_iterator(target.path()))
        if (file.is_regular_file()) all.push_back(target.path().filename().string() + "/" + file.path().filename().string());
  std::sort(all.begin(), all.end());
  return all;
}

class FuzzRegression : public testing::TestWithParam<std::string> {};

TEST_P(FuzzRegression, RunsThroughItsEntryPoint) {
  const std::string& name = GetParam();
  const fuzz::Entry entry = fuzz::entry(name.substr(0, name.find('/')));
  ASSERT_NE(entry, nullptr) << "no fuzz target named by the folder of " << name;
  std::ifstream in(kRoot / name, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  entry(bytes.str());  // a crash, sanitizer report or abort fails the test
}

// Every target has its folder, so that the list is never empty.
TEST(FuzzRegression, EveryTargetHasAFolder) {
  for (const char* target : {"trace_reader", "gppl_check", "gppl_run", "display_format", "prp_loader", "pikocnc",
                             "vmid", "twoaxis", "pikocnc_script", "sinumerik", "iso", "controllers", "lsp", "tool_table"}) {
    EXPECT_NE(fuzz::entry(target), nullptr) << target;
    EXPECT_TRUE(fs::is_directory(kRoot / target)) << target;
  }
}

INSTANTIATE_TEST_SUITE_P(Kept, FuzzRegression, testing::ValuesIn(kept_inputs()),
                         [](const testing::TestParamInfo<std::string>& i) {
                           std::string n = i.param;
                           for (char& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace
