// Parameter vectors kept by the name of the command whose parameters they last held, so that a
// reader fills a command into a vector that already holds that command's names.
//
// A reader is handed back the buffers of commands the consumer is done with. The consumer keeps
// a few commands in rotation, so on a job that alternates shapes (`@line`, `@arc`, `@line`, ...)
// the buffer handed back mostly held the other shape, and every name would be copied and looked
// up again. Before reading command `@arc` into such a buffer the reader swaps its parameter vector
// for the one last used by an `@arc` (and shelves the one it was given, under its own name); the
// name strings are swapped along, so that naming the command copies nothing either.
// Only buffers move: what is read is the same whichever vector it goes into.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "toolpath/command.hpp"
#include "toolpath/short_text.hpp"

namespace toolpath {

class ParameterShelf {
public:
  // Names `out` `name` (the command about to be read into it). `out.name` still holds the name of
  // the command its parameters last held: when that differs, out's parameter vector is exchanged
  // for the shelved one of a command named `name`, if there is one.
  void rename(Command& out, std::string_view name) {
    if (!same_short_text(out.name, name)) exchange(out, name);
  }

  // `c` was read into a fresh vector (no buffers handed back yet: the pipeline filling up). When
  // no entry has c's name, a copy of its parameters goes to an unused entry or the next one to
  // replace, so that the next fresh command of that name starts from a copy instead of naming
  // every slot again.
  void keep(const Command& c);

private:
  void exchange(Command& out, std::string_view name);

  // A command name of up to 16 bytes as two words; `size` 0 for any other (never matches).
  struct Label {
    std::uint64_t head = 0, tail = 0;
    std::size_t size = 0;
    friend bool operator==(const Label&, const Label&) = default;
  };
  static Label label_of(std::string_view name);

  struct Entry {
    Entry() { name.reserve(sizeof(std::string)); }  // on the heap: swapping names swaps pointers
    Label label;       // the command whose parameters `parameters` last held, when size > 0:
    std::string name;  // that command's name (a command takes it by a swap instead of a copy)
    std::vector<Parameter> parameters;
  };
  // A job alternates a handful of command shapes; a few entries bound the memory kept.
  std::array<Entry, 4> entries_;
  std::size_t victim_ = 0;  // the entry replaced next when no entry has the name
};

}  // namespace toolpath
