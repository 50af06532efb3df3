// The types of the command catalogue (parameter_table.hpp) held against the stream as it is read:
// a value its post variable cannot take (`xpos : 12..5`, a word where a number belongs, `TRUE`
// where a string belongs) is an InputError at the value's own position, before any post runs.
// `postproc read` and the engine both put it right behind the reader.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>

#include "postproc/engine/parameter_table.hpp"
#include "toolpath/error.hpp"
#include "toolpath/source.hpp"

namespace toolpath {
class TraceReader;
}

namespace postproc {

// What is wrong with `value` for a parameter of `kind` ("expected a number, not `12..5`"); empty
// when the post variable takes it as it is or by an exact conversion.
std::string kind_mismatch(ParameterKind kind, const toolpath::Value& value);

// Also holds each motion command read from a trace (the commands with a header line) to the
// parameters it cannot do without (`xpos ypos zpos` of `@rapid_move`, the centre of `@arc`, ...):
// one that no command of the stream has given yet is an error, since the post would invent it;
// one given before is taken over from there, with a warning (once per command and parameter).
// A stream a controller model read back from G-code (@start_of_file names its `dialect`) has the
// axes of its machine and is not held to this.
class ParameterCheck final : public toolpath::CommandSource {
public:
  using Warn = std::function<void(const toolpath::SourcePosition& where, const std::string& message)>;
  // Commands deeper than the stream (Command::is_stream_command: calls the original post made
  // itself) are passed on unchecked, as written, or with Deeper::Leave left out (the engine posts
  // the stream only, and leaves them out here rather than in a layer of its own).
  enum class Deeper : std::uint8_t { Pass, Leave };
  // `file_name` names the input in errors; `inner` must outlive the check.
  ParameterCheck(toolpath::CommandSource& inner, std::string file_name, Warn warn = {}, Deeper deeper = Deeper::Pass);
  bool next(toolpath::Command& out) override;

private:
  void check_slow(const toolpath::Command& c, const toolpath::Parameter& p);
  // Command `c`, entry `r` of the required-parameter list, lacks some of them: an error when no
  // command gave one before, else a warning (once per command and parameter).
  void report_missing(const toolpath::Command& c, int r, std::uint32_t present);

  // The catalogue kind of a parameter without an interned key (keyed ones are one table index),
  // or -1 when it is not in the catalogue.
  int unkeyed_kind(const toolpath::Parameter& p);

  toolpath::CommandSource& inner_;
  const toolpath::TraceReader* screening_ = nullptr;  // inner_, when a trace reader screens the values
  std::string file_;
  std::unordered_map<std::string, int> unkeyed_;  // names outside the key list, looked up once
  // The last names looked up in unkeyed_, by a hash of their length and first bytes (`kind` -2:
  // empty): a job repeats the same few names outside the key list command after command.
  struct RecentName {
    std::string name;
    int kind = -2;
  };
  std::array<RecentName, 64> recent_unkeyed_;
  Warn warn_;
  std::uint32_t given_ = 0;   // the required parameters some command has carried (bits of Need)
  std::uint64_t warned_ = 0;  // (command, parameter) pairs already warned about
  bool read_back_ = false;    // the stream is G-code read back by a controller model
  bool leave_deeper_ = false;
};

}  // namespace postproc
