// A documentation page rendered from the code's tables must equal the file in docs/: the test fails
// when they drift apart, and with POSTPROC_UPDATE_DOCS set it rewrites the page instead.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace test_support {

inline void expect_page_is_rendered(const std::string& path, const std::string& rendered, const std::string& source) {
  if (std::getenv("POSTPROC_UPDATE_DOCS")) {
    std::ofstream(path, std::ios::binary) << rendered;
    return;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream actual;
  actual << in.rdbuf();
  EXPECT_TRUE(actual.str() == rendered) << path << " differs from " << source
                                        << ": rerun this test with POSTPROC_UPDATE_DOCS=1";
}

}  // namespace test_support
