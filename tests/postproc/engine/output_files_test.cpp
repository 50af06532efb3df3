// Output files of one run: directives, append semantics, atomic replacement, stream output.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "postproc/engine/output_files.hpp"

namespace {

namespace fs = std::filesystem;
using postproc::Directive;
using postproc::OutputFiles;
using Verb = Directive::Verb;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class OutputFilesTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("postproc-output-test-" + std::to_string(::getpid()) + "-" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  fs::path dir;
};

TEST_F(OutputFilesTest, DirectivesSwitchAppendDeleteAndCopy) {
  OutputFiles out(dir);
  out.set_main_path(dir / "MAIN.TAP");
  out.write_line("%");
  out.execute({Verb::Open, "SUB.SPF"});
  out.write_line("sub 1");
  out.execute({Verb::Close, "SUB.SPF"});
  out.write_line("main 2");
  out.execute({Verb::Open, "sub.spf"});  // the same file (names compare case-insensitively): appended to
  out.write_line("sub 2");
  out.execute({Verb::Close, "SUB.SPF"});
  out.execute({Verb::Open, "TMP.NC"});
  out.write_line("fixture");
  out.execute({Verb::Close, "TMP.NC"});
  out.execute({Verb::Copy, "TMP.NC"});
  out.execute({Verb::Copy, "TMP.NC"});
  out.execute({Verb::Delete, "TMP.NC"});
  out.execute({Verb::Delete, "NEVER.NC"});  // no error when missing
  out.write_line("%");
  EXPECT_EQ(listing().size(), 1u) << "only the private temporary folder before commit";
  auto written = out.commit();
  EXPECT_EQ(written.size(), 2u);
  // Breaks come before lines; the one before a directive stays in the file it ends, the one after
  // it goes with it (so SUB.SPF begins with its first line and TMP.NC ends with a break).
  EXPECT_EQ(slurp(dir / "MAIN.TAP"), "\n%\nmain 2\nfixture\nfixture\n%");
  EXPECT_EQ(slurp(dir / "SUB.SPF"), "sub 1\nsub 2\n");
  EXPECT_EQ(listing(), (std::vector<std::string>{"MAIN.TAP", "SUB.SPF"}));
}

TEST_F(OutputFilesTest, DeleteThenOpenStartsTheFileAgain) {
  OutputFiles out(dir);
  out.set_main_path(dir / "MAIN.TAP");
  for (const char* text : {"first", "second"}) {
    out.execute({Verb::Delete, "P.SPF"});
    out.execute({Verb::Open, "P.SPF"});
    out.write_line(text);
    out.execute({Verb::Close, "P.SPF"});
  }
  out.commit();
  EXPECT_EQ(slurp(dir / "P.SPF"), "second\n");  // the break before the close directive
}

TEST_F(OutputFilesTest, AFailedRunLeavesThePreviousFilesUntouched) {
  std::ofstream(dir / "MAIN.TAP") << "old program\n";
  {
    OutputFiles out(dir);
    out.set_main_path(dir / "MAIN.TAP");
    out.write_line("new program");
    out.execute({Verb::Open, "SUB.SPF"});
    out.write_line("sub");
  }  // destroyed without commit: an error stopped the run
  EXPECT_EQ(slurp(dir / "MAIN.TAP"), "old program\n");
  EXPECT_EQ(listing(), (std::vector<std::string>{"MAIN.TAP"}));
}

TEST_F(OutputFilesTest, ACommitThatCannotWriteOneFileWritesNone) {
  std::ofstream(dir / "MAIN.TAP") << "old program\n";
  std::ofstream(dir / "blocked") << "a file where the subprogram's folder should be\n";
  {
    OutputFiles out(dir);
    out.set_main_path(dir / "MAIN.TAP");
    out.write_line("new program");
    out.execute({Verb::Open, "blocked/SUB.SPF"});
    out.write_line("sub");
    out.execute({Verb::Close, "blocked/SUB.SPF"});
    EXPECT_THROW(out.commit(), std::runtime_error);
  }  // the run ends with the error: its temporaries go
  EXPECT_EQ(slurp(dir / "MAIN.TAP"), "old program\n");  // the main file came first and is untouched
  EXPECT_EQ(listing(), (std::vector<std::string>{"MAIN.TAP", "blocked"}));
}

TEST_F(OutputFilesTest, CommitReplacesTheOldFileAndRemovesDeletedOnes) {
  std::ofstream(dir / "MAIN.TAP") << "old program\n";
  std::ofstream(dir / "STALE.SPF") << "stale\n";
  OutputFiles out(dir, OutputFiles::LineEnd::CRLF);
  out.set_main_path(dir / "MAIN.TAP");
  out.write_line("new");
  out.execute({Verb::Delete, "STALE.SPF"});
  out.commit();
  EXPECT_EQ(slurp(dir / "MAIN.TAP"), "\r\nnew\r\n");  // the second break is the delete directive's
  EXPECT_EQ(listing(), (std::vector<std::string>{"MAIN.TAP"}));
}

TEST_F(OutputFilesTest, WindowsPathsStayInsideTheOutputFolder) {
  fs::create_directories(dir / "sub");
  OutputFiles out(dir);
  out.set_main_path(dir / "MAIN.TAP");
  out.execute({Verb::Open, "C:\\NC\\O1.SPF"});
  out.write_line("o1");
  out.execute({Verb::Open, "sub\\O2.SPF"});
  out.write_line("o2");
  out.execute({Verb::MakeDir, "made"});
  out.commit();
  EXPECT_EQ(slurp(dir / "O1.SPF"), "o1\n");
  EXPECT_EQ(slurp(dir / "sub" / "O2.SPF"), "o2\n");
  EXPECT_TRUE(fs::is_directory(dir / "made"));
}

TEST_F(OutputFilesTest, CopyOfAMissingFileIsAnError) {
  OutputFiles out(dir);
  try {
    out.execute({Verb::Copy, "NOPE.NC"});
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot copy `NOPE.NC`: no such file"), std::string::npos) << e.what();
  }
}

// `copy file` of an old file of the folder without line ends, its lines followed (test, verify):
// an error at 16 MiB instead of a line gathered without bound.
TEST_F(OutputFilesTest, CopyOfAFileWithoutLineEndsStopsAt16MiB) {
  std::ofstream(dir / "OLD.NC", std::ios::binary) << "N10\n";
  fs::resize_file(dir / "OLD.NC", std::uintmax_t{17} << 20);  // sparse: a second line of 17 MiB of zeros
  std::vector<std::string> lines;
  {
    OutputFiles out(dir);
    try {
      out.execute({Verb::Copy, "OLD.NC"}, [&](std::string_view line) { lines.emplace_back(line); });
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "cannot copy `OLD.NC`: line longer than 16 MiB: not an NC file?");
    }
  }
  EXPECT_EQ(lines, std::vector<std::string>{"N10"});
}

TEST_F(OutputFilesTest, StreamOutputNamesFilesOnlyWhenThereAreSeveral) {
  {
    OutputFiles out(dir, OutputFiles::LineEnd::LF, true);
    out.set_main_path("ONE.TAP");
    out.write_line("only");
    std::ostringstream s;
    out.commit_to(s);
    EXPECT_EQ(s.str(), "\nonly");
  }
  OutputFiles out(dir, OutputFiles::LineEnd::LF, true);
  out.set_main_path("MAIN.TAP");
  out.write_line("main");
  out.execute({Verb::Open, "O1.SPF"});
  out.write_line("sub");
  std::ostringstream s;
  out.commit_to(s);
  EXPECT_EQ(s.str(), "==> MAIN.TAP <==\n\nmain\n\n==> O1.SPF <==\nsub");
  EXPECT_TRUE(listing().empty()) << "stream output writes nothing in the output folder";
}

}  // namespace

namespace {

// Lines are buffered and written in large blocks: lines longer than the buffer, many lines across
// its end, switches between files and copies in between keep their order and bytes (CR LF too).
TEST_F(OutputFilesTest, BufferedLinesKeepTheirOrderAcrossFilesAndCopies) {
  OutputFiles out(dir, OutputFiles::LineEnd::CRLF);
  out.set_main_path(dir / "MAIN.TAP");
  std::string main_expected, sub_expected;
  const std::string long_line(200'000, 'x');
  bool break_taken = false;  // by the directive before
  auto main_line = [&](const std::string& text) {
    out.write_line(text);
    main_expected += (break_taken ? "" : "\r\n") + text;
    break_taken = false;
  };
  for (int i = 0; i < 5000; ++i) main_line("N" + std::to_string(i) + " G1 X" + std::to_string(i * 3));
  main_line(long_line);
  out.execute({Verb::Open, "SUB.SPF"});
  main_expected += "\r\n";
  for (int i = 0; i < 3000; ++i) {
    out.write_line("sub " + std::to_string(i));
    sub_expected += (i == 0 ? "" : "\r\n") + std::string("sub ") + std::to_string(i);
  }
  out.execute({Verb::Close, "SUB.SPF"});
  sub_expected += "\r\n";
  break_taken = true;
  main_line("after");
  out.execute({Verb::Copy, "SUB.SPF"});
  main_expected += "\r\n" + sub_expected;
  break_taken = true;
  main_line(long_line);
  main_line("");
  main_line("%");
  out.commit();
  EXPECT_EQ(slurp(dir / "MAIN.TAP"), main_expected);
  EXPECT_EQ(slurp(dir / "SUB.SPF"), sub_expected);
}

// Lines of every length up to 40 (each copy path and its edges) with random bytes, with and
// without the break before them, LF and CR LF: the file holds exactly them, and write_line() counts
// what break_starts_file() announced (2 for the break that begins a file, else 1).
TEST_F(OutputFilesTest, LinesOfEveryShortLengthAreCopiedWhole) {
  for (auto line_end : {OutputFiles::LineEnd::LF, OutputFiles::LineEnd::CRLF}) {
    const std::string eol = line_end == OutputFiles::LineEnd::CRLF ? "\r\n" : "\n";
    OutputFiles out(dir, line_end);
    out.set_main_path(dir / "MAIN.TAP");
    std::mt19937 random(14);
    std::string expected;
    for (int round = 0; round < 20; ++round) {
      for (std::size_t n = 0; n <= 40; ++n) {
        std::string text(n, ' ');
        for (char& c : text) c = static_cast<char>('#' + random() % 90);
        const bool after_break = (random() % 4) != 0 || expected.empty();
        const std::size_t announced = out.break_starts_file(after_break) ? 2 : 1;
        EXPECT_EQ(out.write_line(text, after_break), announced) << "length " << n;
        expected += (after_break ? eol : "") + text;
      }
    }
    out.commit();
    EXPECT_EQ(slurp(dir / "MAIN.TAP"), expected);
  }
}

}  // namespace
