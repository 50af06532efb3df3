// Test helpers shared by the suites that drive the `postproc` command line in-process.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "postproc/cli/cli.hpp"
#include "tests/support/golden_file.hpp"

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

}  // namespace test_support
