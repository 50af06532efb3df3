// Reads a program one line at a time from a stream, in large chunks, without loading the file.
// Loops and subprogram calls (G25/G125 and M99, GOTOB, M98) jump back with mark()/seek().
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

namespace ncmodel {

class LineReader {
public:
  struct Mark {
    std::uint64_t offset = 0;  // byte offset of a line start
    std::size_t line = 0;      // number of lines before it
  };

  // `file` names the input in the error for a line longer than 16 MiB.
  LineReader(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}

  // The next line without its line end (LF, CR LF or a lone CR); valid until the next call.
  bool next(std::string_view& line);
  // 1-based number of the line returned last.
  std::size_t line_number() const { return line_; }
  // Where the next line starts.
  Mark mark() const { return {buffer_start_ + pos_, line_}; }
  void seek(const Mark& where);

private:
  bool fill();  // reads another chunk; false at the end of the stream

  std::istream& in_;
  // The bytes read and not dropped yet: size_ of capacity_. Not a std::string, whose resize would
  // zero every chunk before it is read over (a 256 KiB memset a chunk).
  std::unique_ptr<char[]> buffer_;
  std::size_t size_ = 0, capacity_ = 0;
  std::string file_;
  std::uint64_t buffer_start_ = 0;  // file offset of buffer_[0]
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
  bool at_eof_ = false;
};

}  // namespace ncmodel
