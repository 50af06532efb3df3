// A temporary file of commands, written once and read back from any position: lets a filter defer
// or reorder whole jobs without holding them in memory. Commands come back as written (name, index,
// depth, parameters with kinds, values and change flags, trace lines); of a value only the field of
// its kind is kept, the others come back zero or empty.
//
// Every command of a job passes through it twice, so records are compact binary and the file is
// written and read in blocks of a mebibyte: memory stays at two blocks whatever the job length, and
// the records not yet flushed are read straight from memory. A record also keeps the command's kind
// (command_kind.hpp), so that a filter replaying it does not classify its name again, and a read
// keeps what the destination already holds when it is the same (names, parameter slots).
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "prp/filters/command_kind.hpp"
#include "toolpath/command.hpp"

namespace prp {

class CommandSpool {
public:
  CommandSpool();  // throws std::runtime_error when no temporary file can be made
  // Appends a command at the end; returns its offset. `kind` is command_kind(c), when known.
  std::int64_t write(const toolpath::Command& c) { return write(c, command_kind(c)); }
  std::int64_t write(const toolpath::Command& c, CommandKind kind);
  // Reads from `offset` on (subsequent reads continue from there).
  void seek(std::int64_t offset);
  // Reads the next command (and its kind); false at the end of what was written.
  bool read(toolpath::Command& out) {
    CommandKind kind;
    return read(out, kind);
  }
  bool read(toolpath::Command& out, CommandKind& kind);
  std::int64_t end() const { return flushed_ + static_cast<std::int64_t>(used_); }
  std::int64_t position() const { return position_; }  // of the next read

private:
  void flush();
  const char* record_at(std::int64_t offset, std::uint32_t& size);  // payload of the record at offset
  void shape(std::vector<toolpath::Parameter>& parameters, std::size_t n);

  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Close> file_;
  std::int64_t flushed_ = 0;     // bytes in the file; the records after them are in out_
  // Records not yet in the file: the first used_ of capacity_ bytes (never zero-filled, unlike a
  // std::string or std::vector resized per record or per block).
  std::unique_ptr<char[]> out_;
  std::size_t capacity_ = 0, used_ = 0;
  std::string in_;               // a window of the file: bytes [in_start_, in_start_ + in_.size())
  std::int64_t in_start_ = 0;
  std::int64_t position_ = 0;    // where the next read starts
  // Parameter lists of earlier reads, by their length (up to 31). A read trades its destination's
  // list for a spare one of the right length instead of making or destroying parameters (short and
  // long commands alternate), and the spare's slots mostly hold the same names already. At most
  // kSpares lists per length, in fixed slots (a trade is two swaps): memory stays bounded.
  static constexpr std::size_t kSpares = 8;
  struct Spares {
    std::array<std::vector<toolpath::Parameter>, kSpares> lists;
    std::size_t count = 0;  // lists[0 .. count) are spares; the others are empty
  };
  std::array<Spares, 32> spare_;
};

}  // namespace prp
