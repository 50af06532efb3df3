// Reading a post and its includes: a file that cannot be opened is error 399; one that was opened
// but is larger than 64 MiB (a wrong file, /dev/zero) or fails while being read is error 426 with
// the reason, at the post itself or at the `inc` line (docs/reliability.md).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "gppl/gppl.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using gppl_test::first_file_error;

namespace {

TEST(ReadLimits, OpenedIsNotCannotOpen) {
  const fs::path dir = fs::temp_directory_path() / ("gppl_read_limits_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string d = dir.string();
  {
    std::ofstream(dir / "big.gpp", std::ios::binary) << "@a\nendp\n";
    fs::resize_file(dir / "big.gpp", std::uintmax_t{65} << 20);  // sparse: no disk space taken
    std::ofstream(dir / "main.gpp", std::ios::binary) << "@a\nendp\n\ninc \"big\"\n";
    std::ofstream(dir / "ok.gpp", std::ios::binary) << "@b\nendp\n";
    std::ofstream(dir / "main_ok.gpp", std::ios::binary) << "inc 'ok'\n@a\nendp\n";
  }
  const struct {
    const char* name;
    std::string path;
    std::string expected;
  } cases[] = {
      {"Missing", d + "/none.gpp", d + "/none.gpp:1:1: error 399: Can't open file '" + d + "/none.gpp'"},
      {"TooLarge", d + "/big.gpp",
       d + "/big.gpp:1:1: error 426: Error while reading file '" + d + "/big.gpp': larger than 64 MiB: not a GPPL post?"},
      {"Device", "/dev/zero",
       "/dev/zero:1:1: error 426: Error while reading file '/dev/zero': larger than 64 MiB: not a GPPL post?"},
      {"Folder", d, d + ":1:1: error 426: Error while reading file '" + d + "': read error: Is a directory"},
      {"IncludeTooLarge", d + "/main.gpp",
       d + "/main.gpp:4:1: error 426: Error while reading file '" + d + "/big.gpp': larger than 64 MiB: not a GPPL post?"},
      {"IncludeSmall", d + "/main_ok.gpp", "no error"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(first_file_error(c.path), c.expected);
  }
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}

}  // namespace
