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

class RegressionComparer {
public:
  // Opens the expected lines of a stream, or returns nullptr when there is no golden data for it.
  using Opener = std::function<std::unique_ptr<ExpectedLines>(const std::string& stream)>;

  RegressionComparer(Opener opener, CompareOptions options, std::string post_name);

  // One produced line of `stream`. A line with placeholders (start_line/end_line not known yet) is
  // compared once filled() has supplied all of them; memory holds only such lines.
  void produced(const std::string& stream, std::string_view text, const LineOrigin& origin);
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

private:
  struct Stream {
    std::unique_ptr<ExpectedLines> expected;  // null: no golden data
    std::size_t line = 0;
    bool expected_done = false;
    std::string last_origin;
  };
  struct Deferred {
    Difference d;  // expected and actual, not yet compared
    std::uint64_t order = 0;
  };
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
