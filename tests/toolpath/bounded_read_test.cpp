// The bounded readers of toolpath/bounded_read.hpp: whole files up to a size, lines up to a length,
// and excerpts of input text in messages (docs/reliability.md, "Bad inputs tried").
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "toolpath/bounded_read.hpp"
#include "toolpath/error.hpp"
#include "toolpath/trace_reader.hpp"
#include "tests/support/read_error.hpp"

namespace fs = std::filesystem;

namespace {

// A folder of its own, removed at the end of the test.
struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("bounded_read_test_" + std::to_string(::getpid()) + "_" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Scratch() { fs::create_directories(dir); }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
  // A file of `size` bytes that takes no disk space (a sparse file of zeros).
  std::string sparse(const std::string& name, std::uintmax_t size) const {
    const fs::path p = dir / name;
    std::ofstream(p, std::ios::binary).put('x');
    fs::resize_file(p, size);
    return p.string();
  }
};

// Every line of `text` as read_line gives it, with "!" for a line that was too long (reading stops).
std::vector<std::string> lines_of(const std::string& text, std::size_t limit) {
  std::istringstream in(text);
  std::vector<std::string> lines;
  std::string line;
  for (;;) {
    const toolpath::LineRead r = toolpath::read_line(in, line, limit);
    if (r == toolpath::LineRead::End) break;
    if (r == toolpath::LineRead::TooLong) {
      lines.push_back("!");
      break;
    }
    lines.push_back(line);
  }
  return lines;
}

struct LineCase {
  const char* name;
  std::string text;
  std::size_t limit;
  std::vector<std::string> lines;
};

TEST(BoundedRead, ReadLineIsGetlineWithABound) {
  const std::string long_line(10000, 'a');  // longer than read_line's own chunk
  const LineCase cases[] = {
      {"Empty", "", 100, {}},
      {"OneLine", "abc\n", 100, {"abc"}},
      {"NoLastLineEnd", "abc\ndef", 100, {"abc", "def"}},
      {"EmptyLines", "\n\nx\n", 100, {"", "", "x"}},
      {"CarriageReturnKept", "a\r\nb\r\n", 100, {"a\r", "b\r"}},
      {"NulBytesKept", std::string("a\0b\n", 4), 100, {std::string("a\0b", 3)}},
      {"LongLineAcrossChunks", long_line + "\nz\n", 20000, {long_line, "z"}},
      {"LongLastLineWithoutEnd", "z\n" + long_line, 20000, {"z", long_line}},
      {"ExactlyTheLimit", "abcd\nabcde\n", 4, {"abcd", "!"}},
      {"TooLongWithoutLineEnd", "ok\n" + long_line, 5000, {"ok", "!"}},
      {"TooLongFirstLine", long_line + "\n", 9999, {"!"}},
  };
  for (const LineCase& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(lines_of(c.text, c.limit), c.lines);
  }
}

// /dev/zero is one endless line: read_line stops at the limit instead of taking memory.
TEST(BoundedRead, ReadLineStopsOnAnEndlessLine) {
  std::ifstream zero("/dev/zero", std::ios::binary);
  ASSERT_TRUE(zero);
  std::string line;
  EXPECT_EQ(toolpath::read_line(zero, line, 1 << 20), toolpath::LineRead::TooLong);
  EXPECT_LE(line.size(), (1u << 20) + (1u << 12));
}

std::string read_error(const std::string& path, std::size_t limit) {
  try {
    const std::string text = toolpath::read_file_bounded(path, limit, "too large: not a test file?");
    return "read " + std::to_string(text.size()) + " bytes";
  } catch (const toolpath::InputError& e) {
    return e.what();
  }
}

TEST(BoundedRead, WholeFilesStopPastTheLimit) {
  Scratch s;
  const std::string small = s.sparse("small.txt", 1000);
  const std::string big = s.sparse("big.txt", 3 << 20);  // sparse: no disk space, read in chunks
  const struct {
    const char* name;
    std::string path;
    std::size_t limit;
    std::string expected;
  } cases[] = {
      {"UnderTheLimit", small, 1000, "read 1000 bytes"},
      {"OverTheLimit", small, 999, small + ": too large: not a test file?"},
      {"SparseFile", big, 1 << 20, big + ": too large: not a test file?"},
      {"DeviceWithoutSize", "/dev/zero", 1 << 20, "/dev/zero: too large: not a test file?"},
      {"Missing", (s.dir / "none.txt").string(), 1000, (s.dir / "none.txt").string() + ": cannot open file"},
      {"Folder", s.dir.string(), 1000, s.dir.string() + ": read error: Is a directory"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(read_error(c.path, c.limit), c.expected);
  }
}

TEST(BoundedRead, Excerpt) {
  EXPECT_EQ(toolpath::excerpt(""), "");
  EXPECT_EQ(toolpath::excerpt(std::string(40, 'a')), std::string(40, 'a'));
  EXPECT_EQ(toolpath::excerpt(std::string(41, 'a')), std::string(40, 'a') + "...");
  EXPECT_EQ(toolpath::excerpt("abcdef", 3), "abc...");
}

// The trace reader's messages that quote input text quote at most 40 characters of it.
TEST(BoundedRead, TraceMessagesQuoteAShortPrefix) {
  const auto error_of = [](const std::string& text) -> std::string {
    std::istringstream in(text);
    toolpath::TraceReader reader(in, "m.trace");
    const std::string error = test_support::read_error(reader);
    return error.empty() ? "no error" : error;
  };
  const std::string name(2 << 20, 'n'), digits(2 << 20, '9');
  EXPECT_EQ(error_of("@start_of_file\n" + name + " x\n"),
            "m.trace:2:" + std::to_string(name.size() + 2) + ": expected `:` after the parameter name `" +
                std::string(40, 'n') + "...`");
  EXPECT_EQ(error_of("@start_of_file\nprogram_number : " + digits + "\n"),
            "m.trace:2:18: integer out of range: " + std::string(40, '9') + "...");
  EXPECT_EQ(error_of("@start_of_file\nxpos : " + digits + ".5\n"),
            "m.trace:2:8: number out of range: " + std::string(40, '9') + "...");
}

}  // namespace
