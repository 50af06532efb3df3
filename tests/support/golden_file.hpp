// Golden files: a test's output compared with a file kept beside its input. POSTPROC_UPDATE_GOLDEN=1
// rewrites the files instead (review the diff before committing); an empty output removes the file.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <algorithm>
#include <string>
#include <vector>

namespace test_support {

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void expect_golden(const std::filesystem::path& file, const std::string& actual) {
  if (std::getenv("POSTPROC_UPDATE_GOLDEN")) {
    if (actual.empty()) std::filesystem::remove(file);
    else std::ofstream(file, std::ios::binary) << actual;
    return;
  }
  EXPECT_EQ(std::filesystem::exists(file) ? slurp(file) : std::string(), actual) << file;
}

// The golden folders below `root` (one test case each), sorted by name.
inline std::vector<std::string> subfolders(const std::filesystem::path& root) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(root))
    if (e.is_directory()) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace test_support
