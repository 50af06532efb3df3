// A temporary file of commands, written once and read back from any position: lets a filter defer
// or reorder whole jobs without holding them in memory. Commands come back as written (name, index,
// depth, parameters with kinds, values and change flags, trace lines); of a value only the field of
// its kind is kept, the others come back zero or empty.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "toolpath/command.hpp"

namespace prp {

class CommandSpool {
public:
  CommandSpool();  // throws std::runtime_error when no temporary file can be made
  // Appends a command at the end; returns its offset.
  std::int64_t write(const toolpath::Command& c);
  // Reads from `offset` on (subsequent reads continue from there).
  void seek(std::int64_t offset);
  // Reads the next command; false at the end of what was written.
  bool read(toolpath::Command& out);
  std::int64_t end() const { return end_; }
  std::int64_t position() const { return position_; }  // of the next read

private:
  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Close> file_;
  std::int64_t end_ = 0;        // bytes written
  std::int64_t position_ = 0;   // where the next read starts
  bool writing_ = true;         // the stream's last operation was a write
  std::string buffer_;
};

}  // namespace prp
