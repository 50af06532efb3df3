// A temporary file of commands, written once and read back from any position: lets a filter defer
// or reorder whole jobs without holding them in memory. Commands come back as written (name, index,
// depth, parameters with kinds, values and change flags, trace lines); of a value only the field of
// its kind is kept, the others come back zero or empty.
//
// Every command of a job passes through it twice, so records are compact binary and the file is
// written and read in blocks of a mebibyte: memory stays at two blocks whatever the job length, and
// the records not yet flushed are read straight from memory.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

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
  std::int64_t end() const { return flushed_ + static_cast<std::int64_t>(out_.size()); }
  std::int64_t position() const { return position_; }  // of the next read

private:
  void flush();
  const char* record_at(std::int64_t offset, std::uint32_t& size);  // payload of the record at offset

  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Close> file_;
  std::int64_t flushed_ = 0;     // bytes in the file; the records after them are in out_
  std::string out_;              // records not yet in the file
  std::string in_;               // a window of the file: bytes [in_start_, in_start_ + in_.size())
  std::int64_t in_start_ = 0;
  std::int64_t position_ = 0;    // where the next read starts
};

}  // namespace prp
