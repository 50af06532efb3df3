// Streaming reader of the `.trace` text format: the block form (`(N)@name` then `name : value`
// lines) and the SolidCAM level-5 layout (`(depth)@name ==> k:v ...`, `..>` continuations,
// `> NC line` output, wrapped long names). See docs/trace-format.md.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <limits>
#include <memory>
#include <string>
#include <string_view>

#include "toolpath/error.hpp"
#include "toolpath/parameter_shelf.hpp"
#include "toolpath/source.hpp"

namespace toolpath {

namespace trace_syntax {
struct KeyMemo;
}

// What a consumer that holds every parameter to a rule of its key (postproc::ParameterCheck) takes
// without a closer look, given to the reader as plain data (TraceReader::screen_values): the
// reader's fast path then tells, per command, whether every parameter passed, so that the
// consumer need not look at each one again.
struct ValueScreen {
  double low = -std::numeric_limits<double>::infinity();  // a Numeric value lies in [low, high]
  double high = std::numeric_limits<double>::infinity();  // (which NaN never does)
  std::uint16_t need = 0;  // bits the consumer collects per command
  std::uint8_t kinds = 0;  // the value kinds (bit 1 << ValueKind) taken as they are
  bool passes(const Value& v) const {
    if (((kinds >> static_cast<unsigned>(v.kind)) & 1u) == 0) return false;
    return v.kind != ValueKind::Numeric || (v.numeric >= low && v.numeric <= high);
  }
};

// Parses one value as it appears after `name :` (`'text'`, `12`, `1.5T`, `TRUE`, `CW`, or free text).
// Throws InputError at `where` (column advanced to the fault) when the text is malformed.
Value parse_value(std::string_view text, const SourcePosition& where);

class TraceReader final : public CommandSource {
public:
  // Reads from `in`, which must outlive the reader; `file_name` is used in error messages.
  TraceReader(std::istream& in, std::string file_name);
  ~TraceReader() override;
  // Opens a file; throws InputError when it cannot be read.
  static std::unique_ptr<TraceReader> open(const std::string& path);

  bool next(Command& out) override;

  // Bytes taken from the input so far (in chunks), for a progress bar. Safe to read from another
  // thread than the one reading.
  std::uintmax_t bytes_read() const { return bytes_read_.load(std::memory_order_relaxed); }

  // Reads every line by the general rule, without the fast path for the common lines of the
  // inline layout: tests hold that path to the rule with it.
  void read_by_general_rule() { general_only_ = true; }

  // A first pass over a job, for what only the job's outline decides (prp: procedure generation
  // in two passes): commands deeper than the stream (depth 2 on) and the basic motions (@line,
  // @arc, @rapid_move) inside a job, after the tool changes that open it, are skipped unread. They
  // still count, so indices and lines stay those of a full read; the lines of a skipped command
  // are not parsed, so what is wrong in them is found by the full read only.
  void skim_job_motions() { skim_ = true; }

  // Screens the values the fast path reads by `by_key` (indexed by ParamKey, param_key_count + 1
  // entries, copied).
  void screen_values(const ValueScreen* by_key);
  // For the command next() gave last, after screen_values(): true when the fast path read every
  // parameter and each passed its key's screen, with `need` the OR of their need bits; false when
  // the consumer has to look at the parameters itself.
  bool screened(std::uint32_t& need) const {
    need = screen_need_;
    return screening_ && screen_passed_;
  }

private:
  bool read_line();
  bool skim_to_kept_header();
  void skip_in_chunk();
  bool skipped_in_skim(std::string_view header) const;
  void follow_job(const Command& kept);
  void begin_command(Command& out);
  bool header_ahead();
  std::size_t fast_header(Command& out);
  bool fast_continuation(Command& out);
  std::size_t fast_lines(Command& out, const char* p, const char* line);
  // The number of the line after the current one, as positions keep it (saturating).
  std::uint32_t next_line32() const { return static_cast<std::uint32_t>(std::min<std::size_t>(line_number_ + 1, 0xffffffff)); }
  void count_lines(std::size_t n) {
    line_number_ += n;
    line32_ = static_cast<std::uint32_t>(std::min<std::size_t>(line_number_, 0xffffffff));
  }
  // A fast path read `n` lines of the chunk, up to `next`, where the next line starts.
  void take_lines(const char* next, std::size_t n) {
    buffer_pos_ = static_cast<std::size_t>(next - buffer_.data());
    header_ahead_ = false;
    count_lines(n);
  }
  void take_line(const char* next) { take_lines(next, 1); }
  [[noreturn]] void fail(std::size_t column, const std::string& message) const;
  bool parse_header(Command& out);
  void parse_body_line(Command& out, bool first_after_header, std::size_t first_non_blank);
  void parse_pairs(Command& out, std::string_view text, std::size_t column, TraceLine::Kind otherwise);
  void parse_other_pairs(Command& out, std::string_view text, std::size_t i, std::size_t column, TraceLine::Kind otherwise);
  void parse_user_pairs(Command& out, std::string_view text, std::size_t first, std::size_t column);

  std::unique_ptr<std::istream> owned_;
  std::istream& in_;
  std::string file_;
  std::string buffer_;           // raw bytes read from the stream
  std::size_t buffer_pos_ = 0;
  bool stream_done_ = false;
  // The current line, without its line end: in buffer_ or carry_, so the byte after it is '\n',
  // '\r' or '\0' (the pair scans rely on that).
  std::string_view line_;
  std::string carry_;            // a line cut by the end of a chunk, put together
  std::size_t line_number_ = 0;
  std::uint32_t line32_ = 0;     // line_number_ as positions keep it (saturating at 2^32 - 1)
  bool have_line_ = false;       // line_ holds a header not yet consumed
  std::size_t next_index_ = 0;
  std::size_t used_parameters_ = 0; // parameter slots of the command being read
  bool name_may_be_cut_ = false; // the header's name ran up to `==>` and may continue below
  bool general_only_ = false;    // read_by_general_rule()
  bool header_ahead_ = false;    // header_ahead() found the unread line to be a header
  // skim_job_motions(): where the stream is, as the commands kept so far tell.
  bool skim_ = false;
  bool seen_header_ = false;
  bool in_job_ = false;
  bool job_leading_ = false;     // only tool changes since the job's @start_of_job
  ParameterShelf shelf_;
  std::unique_ptr<trace_syntax::KeyMemo[]> memos_;  // the fast path's numbers and screens, one per key
  bool screening_ = false;      // screen_values()
  bool screen_passed_ = false;  // screened(), for the command being read
  std::uint32_t screen_need_ = 0;
  std::atomic<std::uintmax_t> bytes_read_{0};
};

}  // namespace toolpath
