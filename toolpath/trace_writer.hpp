// Writes commands in the canonical `.trace` form: the SolidCAM level-5 layout, which the reader
// reads back to the same commands.
#pragma once

#include <ostream>
#include <string>

#include "toolpath/command.hpp"

namespace toolpath {

// Appends the textual form of a value (`'text'`, `12`, `1.5`, `true`, `CW`, with a `T`/`F` flag).
void append_value(std::string& out, const Value& value);

// Appends one command, with its parameters, trace notes and output lines, ending in '\n'.
void append_command(std::string& out, const Command& command);

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
};

}  // namespace toolpath
