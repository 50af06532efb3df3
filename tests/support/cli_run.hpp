// Test helpers shared by the suites that drive the `postproc` command line in-process.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "postproc/cli/cli.hpp"

namespace test_support {

// What one `postproc ...` invocation returned and printed.
struct CliRun {
  int code;
  std::string out, err;
};

inline CliRun run_cli(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int code = postproc::cli::main(args, out, err);
  return {code, out.str(), err.str()};
}

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace test_support
