// One command of the neutral toolpath stream (`@line`, `@arc`, ...), as the engine receives it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "toolpath/value.hpp"

namespace toolpath {

struct Parameter {
  std::string name;
  Value value;
  friend bool operator==(const Parameter&, const Parameter&) = default;
};

// Text attached to a command in a trace, kept in order. It is never a parameter.
struct TraceLine {
  enum class Kind : std::uint8_t {
    Output,     // `> text`: one NC line the original post wrote (the golden output)
    Partial,    // text after `==>` that is not name:value pairs: output not yet ended by a newline
    Directive,  // `!! open file = X !!` on a line of its own (outside a `>` line)
    Note,       // a `..>` continuation that is not name:value pairs (e.g. @tmatrix formulas)
  };
  Kind kind = Kind::Output;
  std::string text;
  friend bool operator==(const TraceLine&, const TraceLine&) = default;
};

struct Command {
  std::string name;        // with the leading '@'
  std::size_t index = 0;   // position in the stream, from 0
  int depth = 1;           // 1: handled by the post; 0: no procedure; 2+: an internal call of the post
  std::vector<Parameter> parameters;
  std::vector<TraceLine> trace;

  // Parameter lookup by name (case-insensitive); nullptr when absent.
  const Value* find(std::string_view parameter) const;
  // Sets or replaces a parameter.
  void set(std::string_view parameter, Value value);
  // Empties the command but keeps its buffers, so a reader can refill it without allocating.
  void clear();

  // Depth 0 and 1 are commands of the stream; deeper ones only record what the original post did.
  bool is_stream_command() const { return depth <= 1; }

  friend bool operator==(const Command&, const Command&) = default;
};

}  // namespace toolpath
