// One command of the neutral toolpath stream (`@line`, `@arc`, ...), as the engine receives it.
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "toolpath/param_key.hpp"
#include "toolpath/short_text.hpp"
#include "toolpath/value.hpp"

namespace toolpath {

// A named value. `key` is the interned form of `name` (param_key.hpp), kept in step by the
// constructor and rename(): change a name only through these, never by assigning `name`.
struct Parameter {
  Parameter() = default;
  Parameter(std::string name_, Value value_) : name(std::move(name_)), value(std::move(value_)), key(param_key(name)) {}
  // A catalogue parameter, spelled as the catalogue does (no name lookup).
  Parameter(ParamKey key_, Value value_) : name(param_name(key_)), value(std::move(value_)), key(key_) {}

  // Names the parameter `to` and updates the key, reusing the name's buffer.
  void rename(std::string_view to) {
    name.assign(to);
    key = param_key(to);
  }
  // Names it as the catalogue spells `to`; a recycled parameter already so named is left as it is
  // (readers refill commands slot by slot, mostly with the names the slots held).
  void rename(ParamKey to) {
    const std::string_view spelling = param_name(to);
    if (key == to && same_short_text(name, spelling)) return;
    name.assign(spelling);
    key = to;
  }

  std::string name;
  Value value;
  ParamKey key = ParamKey::none;
  // Where the value was read (1-based; 0 when a filter or a model made it), for errors found later.
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  // The same parameter whatever its position in the source.
  friend bool operator==(const Parameter& a, const Parameter& b) {
    return a.key == b.key && a.name == b.name && a.value == b.value;
  }
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
  // The line of its header in the trace (1-based; 0 when a model or a generator made it), so that
  // errors found downstream (filters, the post) still point into the file.
  std::uint32_t line = 0;
  std::vector<Parameter> parameters;
  std::vector<TraceLine> trace;

  // Parameter lookup by name (case-insensitive, the first of that name); nullptr when absent.
  // find(ParamKey::xpos) is the same as find("xpos") without any string work: filters and the
  // engine use it on every command. find(ParamKey::none) finds nothing.
  const Value* find(std::string_view parameter) const;
  // A parameter's number (integer or numeric); nullopt when absent or not a number.
  std::optional<double> number(std::string_view parameter) const;
  const Value* find(ParamKey key) const {
    if (key == ParamKey::none) return nullptr;
    for (const Parameter& p : parameters) {
      assert(p.key == param_key(p.name) && "a Parameter's name was assigned directly: use rename()");
      if (p.key == key) return &p.value;
    }
    return nullptr;
  }
  // Sets or replaces a parameter (the first of that name); a new one goes at the end, named as
  // given (set(ParamKey) uses the catalogue spelling). set(ParamKey::none, ...) does nothing.
  void set(std::string_view parameter, Value value);
  void set(ParamKey key, Value value);
  // Empties the command but keeps its buffers, so a reader can refill it without allocating.
  void clear();

  // Depth 0 and 1 are commands of the stream; deeper ones only record what the original post did.
  bool is_stream_command() const { return depth <= 1; }

  // Exchanges member by member: sources hand commands over by swapping buffers, once per command
  // per stage, and std::swap's three moves cost several times more.
  void swap(Command& other) noexcept {
    name.swap(other.name);
    std::swap(index, other.index);
    std::swap(depth, other.depth);
    std::swap(line, other.line);
    parameters.swap(other.parameters);
    trace.swap(other.trace);
  }
  friend void swap(Command& a, Command& b) noexcept { a.swap(b); }
  // Puts the name on the heap, where it stays (assigning a name never shrinks it): a swap of two
  // such names exchanges pointers, where two names inside their strings are copied by three
  // memcpy calls. The buffers that sources swap with, command after command, are given this once.
  void keep_name_on_heap() { name.reserve(sizeof(std::string)); }

  // The same command wherever it was read (like Parameter, the position is not compared).
  friend bool operator==(const Command& a, const Command& b) {
    return a.name == b.name && a.index == b.index && a.depth == b.depth && a.parameters == b.parameters &&
           a.trace == b.trace;
  }
};

}  // namespace toolpath
