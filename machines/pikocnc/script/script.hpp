// PikoCNC scripts: the Pascal subset PikoCNC users write to generate G-code from parameters, run
// without a user (docs/pikocnc-scripts.md). Parse with parse_script(); run with run_script().
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "toolpath/error.hpp"

namespace pikocnc::script {

struct Program;  // a parsed and resolved script (compiled.hpp)

// Parses and resolves a script: syntax, unknown identifiers, calls with the wrong number of
// arguments and static type errors all throw toolpath::InputError naming file:line:column.
// This is the entry point for a fuzz target: it never runs the script.
std::shared_ptr<const Program> parse_script(std::string_view text, const std::string& file_name);

// What a person would type into the controller, given up front (spec section 10).
struct RunInputs {
  std::map<std::string, std::string> constants;  // [constants] and --const, by name (any case)
  std::map<std::string, std::string> args;       // [args] and --arg, by number as text
  std::map<std::string, bool> answers;           // [answers]: exact MsgYesNo text -> yes/no
  std::optional<bool> default_answer;            // [answers] * = yes|no
  std::vector<bool> ordered_answers;             // --answer, consumed in order
  std::int32_t run_count = 0;                    // RUN_CNT
  bool describe_args = false;                    // ArgEdit prints the dialog as JSON and stops
  std::uint64_t max_steps = 200'000'000;         // statements and loop turns before "runaway"
  std::uint32_t max_call_depth = 1000;           // nested routine calls before "runaway recursion"
  bool crlf = false;                             // line ends of the G-code
};

// Reads a parameters file (`[constants]`, `[args]`, `[answers]`) into `inputs`; values already
// there (from the command line) win. Throws toolpath::InputError on a malformed line.
void read_parameters(std::string_view text, const std::string& file_name, RunInputs& inputs);

struct RunResult {
  bool described = false;   // --describe-args: the JSON went to the output instead of G-code
  std::uint64_t lines = 0;  // G-code lines written (the leading % included)
  std::uint64_t steps = 0;  // statements executed
};

// Runs a script, writing the G-code program to `gcode` (or the dialog JSON with describe_args)
// and MsgOk/Log/Dbg texts and warnings to `diagnostics`. Throws toolpath::InputError on any
// error in the script or its inputs; the caller discards partial output then.
RunResult run_script(const Program& program, const RunInputs& inputs, std::ostream& gcode, std::ostream& diagnostics);

// Convenience: parse_script + run_script.
RunResult run_script_text(std::string_view text, const std::string& file_name, const RunInputs& inputs,
                          std::ostream& gcode, std::ostream& diagnostics);

}  // namespace pikocnc::script

namespace pikocnc::script {
// yes/no/true/false/1/0 (any case), or nothing.
std::optional<bool> parse_answer(std::string_view text);
}  // namespace pikocnc::script
