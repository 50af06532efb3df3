// Streaming reader of the `.trace` text format: the block form (`(N)@name` then `name : value`
// lines) and the SolidCAM level-5 layout (`(depth)@name ==> k:v ...`, `..>` continuations,
// `> NC line` output, wrapped long names). See docs/trace-format.md.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <memory>
#include <string>
#include <string_view>

#include "toolpath/error.hpp"
#include "toolpath/parameter_shelf.hpp"
#include "toolpath/source.hpp"

namespace toolpath {

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

private:
  bool read_line();
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
  ParameterShelf shelf_;
  std::atomic<std::uintmax_t> bytes_read_{0};
};

}  // namespace toolpath
