// `postproc test`: compares the lines a run produces with expected lines, as they are produced
// (memory stays flat), and reports where they first differ and who produced the line.
//
// Expected lines come from a golden file (the main program), a golden folder (one file per output
// file, by name), or the `>` lines of a SolidCAM trace (the lines the original post generated, in
// order, output directives included).
#pragma once

#include <cstddef>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <cstdint>
#include <vector>

#include "postproc/checks/line_compare.hpp"
#include "postproc/engine/line_origin.hpp"
#include "toolpath/trace_reader.hpp"

namespace postproc {

struct ExpectedLine {
  std::string text;
  std::string source;  // where it was expected, for the report ("trace command #21 @arc"), may be empty
};

// One stream of expected lines.
class ExpectedLines {
public:
  virtual ~ExpectedLines() = default;
  virtual bool next(ExpectedLine& out) = 0;
};

// The lines of a text file (LF or CRLF; trailing blanks kept).
std::unique_ptr<ExpectedLines> expected_from_file(const std::string& path);
// The `>` lines of a trace, in order, whatever the depth of the command they follow.
std::unique_ptr<ExpectedLines> expected_from_trace(const std::string& path);

struct Difference {
  std::string stream;     // the output file (or "trace" for trace comparison)
  std::size_t line = 0;   // 1-based line number in that stream
  std::optional<ExpectedLine> expected;  // nullopt: the run wrote more lines than expected
  std::optional<std::string> actual;     // nullopt: the run ended before this expected line
  std::string origin;     // "command #21 @arc, procedure @arc (fanuc.gpp:142)" (empty when none)
};

// How much of one stream's expected output the run reproduced: the expected lines that an output
// line matches, the two sides aligned as `diff` aligns them (a missing line costs that line, not
// every line after it).
struct StreamParity {
  std::string stream;
  std::size_t expected = 0;          // lines expected
  std::size_t produced = 0;          // lines the run wrote
  std::size_t identical = 0;         // expected lines matched, in order
  std::size_t first_difference = 0;  // 1-based line of the expected side; 0: none
  bool approximate = false;          // too different to align: lines compared place by place
  bool written = true;               // false: expected, but the run wrote no such file
};

// One `diff` hunk: expected lines [expected_first, +expected_count) replaced by produced lines
// [produced_first, +produced_count), 0-based.
struct DiffHunk {
  std::size_t expected_first = 0, expected_count = 0;
  std::size_t produced_first = 0, produced_count = 0;
};

class RegressionComparer {
public:
  // Opens the expected lines of a stream, or returns nullptr when there is no golden data for it.
  using Opener = std::function<std::unique_ptr<ExpectedLines>(const std::string& stream)>;

  RegressionComparer(Opener opener, CompareOptions options, std::string post_name);

  // One produced line of `stream`. A line with placeholders (start_line/end_line not known yet) is
  // compared once filled() has supplied all of them; memory holds only such lines.
  void produced(const std::string& stream, std::string_view text, const LineOrigin& origin);
  // Compare the lines of the files as written (golden files), not the lines as generated: an empty
  // line at the very end of a file, one no line break follows, is not a line of the file. The
  // caller then tells break_written() when a directive line wrote the break after the last line.
  void compare_file_lines() { file_lines_ = true; }
  void break_written(const std::string& stream);
  // A placeholder's final text (LineObserver::on_slot_filled).
  void filled(std::uint32_t slot, std::string_view text);
  // A stream the run deleted (`!! delete file = X !!`): no longer reported as not compared.
  void discarded(const std::string& stream);
  // Ends the comparison: lines still expected are differences.
  void finish();

  std::size_t difference_count() const { return differences_; }
  std::size_t lines_compared() const { return compared_; }
  const std::optional<Difference>& first() const { return first_; }
  // Streams produced without golden data (nothing to compare them with).
  const std::vector<std::string>& unmatched_streams() const { return unmatched_; }

  // "OUT.TAP:39: ..." with the expected and actual text and the origin.
  std::string report() const;

  // After finish(): the parity figure of every stream that had golden data, in name order. The
  // lines of those streams are kept for it (memory grows with the golden files, not the job).
  std::vector<StreamParity> parity() const;
  // An expected file the run never wrote (a golden folder's file): all of its lines are missing.
  void not_written(const std::string& stream);
  bool has_stream(const std::string& name) const;  // the run wrote it (any case)
  // With keep_origins(): after finish(), every difference of every stream as unified-diff hunks,
  // each output line followed by the command and the GPP line that wrote it.
  void keep_origins() { keep_origins_ = true; }
  std::string diff_report() const;

private:
  struct Stream {
    std::unique_ptr<ExpectedLines> expected;  // null: no golden data
    std::size_t line = 0;
    bool expected_done = false;
    bool written = true;
    std::string last_origin;
    std::vector<std::string> expected_lines;  // both sides, for the parity figure
    std::vector<std::string> produced_lines;
    std::vector<std::string> origins;         // of produced_lines, with keep_origins()
    bool held = false;                        // an empty line waiting for a break (compare_file_lines)
    std::string held_origin;
    std::uint64_t held_order = 0;
  };
  void release(const std::string& stream, Stream& s);
  void compare_line(const std::string& stream, Stream& s, std::string_view text, std::string origin,
                    std::uint64_t order);
  bool file_lines_ = false;
  struct Deferred {
    Difference d;  // expected and actual, not yet compared
    std::uint64_t order = 0;
  };
  struct Alignment {
    std::vector<DiffHunk> hunks;
    bool approximate = false;
  };
  Alignment align(const Stream& s) const;
  StreamParity figure(const std::string& name, const Stream& s) const;
  bool keep_origins_ = false;
  void record(Difference d, std::uint64_t order);
  void compare(Deferred& deferred);
  std::string describe(const LineOrigin& o) const;

  Opener opener_;
  CompareOptions options_;
  std::string post_name_;
  std::map<std::string, Stream> streams_;
  std::vector<std::string> unmatched_;
  std::optional<Difference> first_;
  std::uint64_t first_order_ = 0;  // the first difference in production order, deferred lines included
  std::uint64_t produced_ = 0;
  std::vector<Deferred> deferred_;
  std::size_t differences_ = 0;
  std::size_t compared_ = 0;
  ExpectedLine scratch_;
};

}  // namespace postproc
