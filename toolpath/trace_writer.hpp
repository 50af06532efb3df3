// Writes commands in the canonical `.trace` form: the SolidCAM level-5 layout, which the reader
// reads back to the same commands.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

#include "toolpath/command.hpp"
#include "toolpath/source.hpp"

namespace toolpath {

// Appends the textual form of a value (`'text'`, `12`, `1.5`, `true`, `CW`, with a `T`/`F` flag).
void append_value(std::string& out, const Value& value);

// Appends one command, with its parameters, trace notes and output lines, ending in '\n'.
void append_command(std::string& out, const Command& command);

// The text of the numbers written last, by their bits: a trace repeats many values (a feed, a
// depth, a zero on every motion), and a copy costs less than the digits. Direct-mapped.
struct NumberCache {
  struct Entry {
    std::uint64_t bits = 0;
    std::uint32_t length = 0;  // 0: empty
    char text[20];
  };
  Entry entries[64];
};

class TraceWriter {
public:
  explicit TraceWriter(std::ostream& out) : out_(out) {}
  ~TraceWriter() { flush(); }
  void write(const Command& command);
  void flush();

private:
  std::ostream& out_;
  std::string buffer_;    // text to write, then room for more (its size is not the text's)
  std::size_t used_ = 0;  // bytes of text at the start of buffer_
  NumberCache numbers_;
};

// Writes every command of `source` to `out` in the canonical form, as `postproc read` prints them,
// and returns their number; what the source throws goes up after the commands before it are
// written. One thread: reading on a second one (PrefetchSource) was measured slower on the shared
// 2-core machine (the commands' buffers cross between cores; docs/performance.md).
std::size_t write_trace(CommandSource& source, std::ostream& out);

}  // namespace toolpath
