// Line comparison options and the streaming regression comparer.
#include <gtest/gtest.h>
#include <unistd.h>

#include <deque>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "postproc/checks/line_compare.hpp"
#include "postproc/checks/regression.hpp"

namespace {

using postproc::CompareOptions;
using postproc::lines_match;

TEST(LineCompare, OptionsTable) {
  CompareOptions none;
  CompareOptions blocks;
  blocks.ignore_block_numbers = true;
  CompareOptions trailing;
  trailing.ignore_trailing_blanks = true;
  CompareOptions leading;
  leading.ignore_leading_blanks = true;
  CompareOptions dates;
  dates.ignore_datetime = true;
  CompareOptions tolerance;
  tolerance.numeric_tolerance = 0.001;
  struct Case {
    const char* expected;
    const char* actual;
    const CompareOptions* options;
    bool match;
  } cases[] = {
      {"G1 X1.", "G1 X1.", &none, true},
      {"G1 X1.", "G1 X1. ", &none, false},
      {"G1 X1.", "G1 X1.  ", &trailing, true},
      {"N10 G1 X1.", "N20 G1 X1.", &none, false},
      {"N10 G1 X1.", "N20 G1 X1.", &blocks, true},
      {"N10 G1 X1.", "G1 X1.", &blocks, true},
      {"N10 G1 X1.", "N10 G1 X2.", &blocks, false},
      {"NOSE", "NOSE", &blocks, true},
      {"   Z2.", "  Z2.", &none, false},
      {"   Z2.", "  Z2.", &leading, true},
      {"(DATE 21.11.2025 TIME 12:05)", "(DATE 01.02.2026 TIME 9:41:07)", &dates, true},
      {"(DATE 21-NOV-2025)", "(DATE 3-DEC-2026)", &dates, true},
      {"; Date : JUL-12-2026", "; Date : AUG-13-2026", &dates, true},
      {"; Date : JUL-12-2026", "; Date : JUL- 9-2026", &dates, true},
      {"(JUL-12)", "(JUL-13)", &dates, false},
      {"; posted 2025/11/21", "; posted 2026/01/02", &dates, true},
      {"G1 X12.05 (12:05)", "G1 X12.06 (12:06)", &dates, false},
      {"(DIA 12.7)", "(DIA 12.8)", &dates, false},
      // SolidCAM's Siemens posts: the day blank-padded, the hour not padded.
      {"N30 ; Date \t\t: JUL-12-2026-3:43:33PM", "N30 ; Date \t\t: JUL- 9-2026-11:04:10PM", &dates, true},
      {"N30 ; Date \t\t: JUL-12-2026-3:43:33PM", "N40 ; Date \t\t: JUL- 9-2026-11:04:10PM", &dates, false},
      {"N30 ; Date \t\t: JUL-12-2026-3:43:33PM ", "N30 ; Date \t\t: NOV-28-2026-12:42:26AM ", &dates, true},
      {"(TIME 3:43 PM)", "(TIME 9:05 am)", &dates, true},
      {"(AT 3:43 PMX)", "(AT 3:43 AMX)", &dates, false},
      {"N30 ; Date : JUL-12-2026-3:43:33PM", "N30 ; Time : JUL- 9-2026-11:04:10PM", &dates, false},
      {"G1 X-16.35 Y2.", "G1 X-16.3504 Y2.0009", &tolerance, true},
      {"G1 X-16.35 Y2.", "G1 X-16.352 Y2.", &tolerance, false},
      {"G1 X-16.35", "G1 Y-16.35", &tolerance, false},
      {"G1 X1.", "G1 X1. F2", &tolerance, false},
  };
  for (const auto& c : cases)
    EXPECT_EQ(lines_match(c.expected, c.actual, *c.options), c.match) << c.expected << " | " << c.actual;
}

class Lines final : public postproc::ExpectedLines {
public:
  explicit Lines(std::deque<std::string> lines) : lines_(std::move(lines)) {}
  bool next(postproc::ExpectedLine& out) override {
    if (lines_.empty()) return false;
    out.text = lines_.front();
    out.source.clear();
    lines_.pop_front();
    return true;
  }

private:
  std::deque<std::string> lines_;
};

postproc::RegressionComparer comparer_for(std::deque<std::string> main_lines) {
  return postproc::RegressionComparer(
      [main_lines](const std::string& stream) -> std::unique_ptr<postproc::ExpectedLines> {
        if (stream != "OUT.TAP") return nullptr;
        return std::make_unique<Lines>(main_lines);
      },
      {}, "fanuc.gpp");
}

TEST(RegressionComparer, ReportsTheFirstDifferenceWithItsOrigin) {
  auto c = comparer_for({"%", "G0 X1.", "G2 X2. R1.", "M30"});
  postproc::LineOrigin origin{21, "@arc", "@line", 120, {}};
  c.produced("OUT.TAP", "%", origin);
  c.produced("OUT.TAP", "G0 X1.", origin);
  c.produced("OUT.TAP", "   Y2.G2 X2. R1.", origin);
  c.produced("OUT.TAP", "M30", origin);
  c.produced("O1.SPF", "sub", origin);
  c.finish();
  EXPECT_EQ(c.difference_count(), 1u);
  EXPECT_EQ(c.lines_compared(), 4u);
  EXPECT_EQ(c.unmatched_streams(), std::vector<std::string>{"O1.SPF"});
  EXPECT_EQ(c.report(),
            "OUT.TAP:3: the output differs from the expected line\n"
            "  expected: `G2 X2. R1.`\n"
            "  actual:   `   Y2.G2 X2. R1.`\n"
            "  produced by command #21 @arc, procedure @line (fanuc.gpp:120)\n");
}

TEST(RegressionComparer, MissingAndExtraLinesAreDifferences) {
  auto shorter = comparer_for({"%", "M30", "%"});
  shorter.produced("OUT.TAP", "%", {});
  shorter.finish();
  EXPECT_EQ(shorter.difference_count(), 2u);
  EXPECT_EQ(shorter.report(),
            "OUT.TAP:2: the output ended before the expected line\n"
            "  expected: `M30`\n"
            "2 differing lines in all\n");

  auto longer = comparer_for({"%"});
  longer.produced("OUT.TAP", "%", {});
  longer.produced("OUT.TAP", "M30", {3, "@end_program", "@end_program", 40, {}});
  longer.finish();
  EXPECT_EQ(longer.report(),
            "OUT.TAP:2: the output has more lines than expected\n"
            "  actual:   `M30`\n"
            "  produced by command #3 @end_program, procedure @end_program (fanuc.gpp:40)\n");
}

// The parity figure aligns the two sides as diff does: one missing line costs that line only.
TEST(RegressionComparer, ParityFigureAlignsTheLines) {
  struct Case {
    const char* name;
    std::deque<std::string> expected;
    std::vector<std::string> produced;
    std::size_t identical, first_difference;
  } cases[] = {
      {"Same", {"%", "G0 X1.", "M30"}, {"%", "G0 X1.", "M30"}, 3, 0},
      {"OneMissing", {"%", "M8", "G0 X1.", "G1 X2.", "M30"}, {"%", "G0 X1.", "G1 X2.", "M30"}, 4, 2},
      {"OneExtra", {"%", "G0 X1.", "M30"}, {"%", "G00", "G0 X1.", "M30"}, 3, 2},
      {"OneChanged", {"%", "G0 X1.", "M30"}, {"%", "G0 X2.", "M30"}, 2, 2},
      {"NothingWritten", {"%", "M30"}, {}, 0, 1},
      {"DateValueOnly", {"; Date : JUL-12-2026", "M30"}, {"; Date : JUL- 9-2026", "M30"}, 2, 0},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    CompareOptions options;
    options.ignore_datetime = true;
    postproc::RegressionComparer r(
        [&](const std::string&) -> std::unique_ptr<postproc::ExpectedLines> { return std::make_unique<Lines>(c.expected); },
        options, "p.gpp");
    for (const auto& line : c.produced) r.produced("OUT.NC", line, {});
    if (c.produced.empty()) {
      r.not_written("OUT.NC");
      r.keep_origins();
    }
    r.finish();
    auto figures = r.parity();
    ASSERT_EQ(figures.size(), 1u);
    EXPECT_EQ(figures[0].expected, c.expected.size());
    EXPECT_EQ(figures[0].identical, c.identical);
    EXPECT_EQ(figures[0].first_difference, c.first_difference);
    EXPECT_EQ(figures[0].written, !c.produced.empty());
    if (c.produced.empty()) {
      EXPECT_EQ(r.diff_report(), "@@ OUT.NC: the run wrote no such file (2 lines expected) @@\n");
    }
  }
}

// Against golden files the lines are the file's: an empty line no break follows (the end of a file
// after `{nb, 'M2 ', nl}`) is not one; the break before a directive makes it one.
TEST(RegressionComparer, FileLinesEndWithTheLastBreak) {
  for (bool directive_after : {false, true}) {
    SCOPED_TRACE(directive_after);
    auto c = comparer_for(directive_after ? std::deque<std::string>{"", "M2 ", ""} : std::deque<std::string>{"", "M2 "});
    c.compare_file_lines();
    for (const char* line : {"", "M2 ", ""}) c.produced("OUT.TAP", line, {});
    if (directive_after) c.break_written("OUT.TAP");
    c.finish();
    EXPECT_EQ(c.difference_count(), 0u) << c.report();
    EXPECT_EQ(c.lines_compared(), directive_after ? 3u : 2u);
  }
}

TEST(RegressionComparer, DiffNamesTheProcedureOfEachLineOfOurs) {
  auto c = comparer_for({"%", "M8", "G0 X1.", "M30"});
  c.keep_origins();
  const postproc::LineOrigin origin{4, "@rapid_move", "@rapid_move", 33, {}};
  // A line an include file's statement wrote names that file, not the post.
  const postproc::LineOrigin included{4, "@rapid_move", "@rapid_move", 7, "lib/moves.inc"};
  for (const char* line : {"%", "G0 X1."}) c.produced("OUT.TAP", line, origin);
  c.produced("OUT.TAP", "G0 X1.", included);
  c.produced("OUT.TAP", "M30", origin);
  c.finish();
  EXPECT_EQ(c.diff_report(),
            "@@ OUT.TAP expected line 2, output line 2 @@\n"
            "- M8\n"
            "@@ OUT.TAP expected line 4, output line 3 @@\n"
            "+ G0 X1.    <- command #4 @rapid_move, procedure @rapid_move (lib/moves.inc:7)\n");
}

TEST(RegressionComparer, ExpectedLinesOfATraceAreItsOutputLinesInOrder) {
  auto lines = postproc::expected_from_trace("toolpath/data/solidcam_layout.trace");
  postproc::ExpectedLine l;
  std::vector<std::string> texts;
  while (lines->next(l)) texts.push_back(l.text);
  EXPECT_EQ(texts, (std::vector<std::string>{"%", "N10 ; PART", "N20 G17 G90 ", "!! open file = F_contour1.SPF !!",
                                             "N290 S1910", "N300 G1 X70 Z20.14 F2292", "N400 M30"}));
}

}  // namespace

namespace {

// The expected NC file is read a line at a time up to 16 MiB a line: /dev/zero or a binary file is
// an error naming the file and line, not memory taken without bound (docs/reliability.md).
TEST(Regression, ExpectedLinesLongerThan16MiBAreAnError) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("regression_test_" + std::to_string(::getpid()) + ".nc");
  std::ofstream(file, std::ios::binary) << "N10 G0 X0\r\nN20 M30\n";
  std::filesystem::resize_file(file, std::uintmax_t{17} << 20);  // a sparse third line of 17 MiB of zeros
  const struct {
    const char* name;
    std::string path;
    std::vector<std::string> lines;  // read before the error
    std::string error;
  } cases[] = {
      {"Device", "/dev/zero", {}, "/dev/zero:1:1: line longer than 16 MiB: not an NC file?"},
      {"ThirdLine", file.string(), {"N10 G0 X0", "N20 M30"}, file.string() + ":3:1: line longer than 16 MiB: not an NC file?"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    auto expected = postproc::expected_from_file(c.path);
    std::vector<std::string> lines;
    std::string error = "no error";
    try {
      for (postproc::ExpectedLine line; expected->next(line);) lines.push_back(line.text);
    } catch (const std::runtime_error& e) {
      error = e.what();
    }
    EXPECT_EQ(lines, c.lines);
    EXPECT_EQ(error, c.error);
  }
  std::filesystem::remove(file);
}

}  // namespace
