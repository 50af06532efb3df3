// The trace statement and trace output in SolidCAM's layout (spec 8; solidcam-behaviour.md 1):
//   (1)@line            ==> xpos:70.000T ypos:-45.4760057628F
//                       ..> feed:2291.831T
//                         > N300 G1 X70 Z20.14 F2292
// Level 1 writes the procedure header, level 2 adds the output lines (when they end, under the
// header written last), levels 3-5 add the parameters the host assigned for the command.
#include <fmt/format.h>

#include <cmath>

#include "gppl/run/machine.hpp"

namespace gppl {

namespace {

constexpr std::size_t kHeaderWidth = 20;  // `==>` starts in column 21
constexpr std::size_t kWrapColumn = 100;
const std::string kOutputPrefix(22, ' ');

std::string trace_value(const Value& v, bool changed) {
  switch (v.type) {
    case Type::Integer: return fmt::format("{}", v.integer);
    case Type::Logical: return v.logical ? "true" : "false";
    case Type::String: return fmt::format("'{}'", v.text);
    case Type::Numeric: break;
  }
  // 3 decimals when that is exact, else 10 (the two forms SolidCAM writes).
  std::string text = fmt::format("{:.3f}", v.numeric);
  if (std::stod(text) != v.numeric) text = fmt::format("{:.10f}", v.numeric);
  return text + (changed ? "T" : "F");
}

std::string trimmed_lower(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  std::string r(s);
  for (char& c : r)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  if (!r.empty() && r.front() != '@') r.insert(r.begin(), '@');
  return r;
}

}  // namespace

int Interpreter::State::trace_level(std::uint32_t procedure) const {
  const int level = procedure_trace_level[procedure];
  return level >= 0 ? level : default_trace_level;
}

void Interpreter::State::trace_statement(const std::string& list, std::int64_t level) {
  if (level < 0 || level > 5) fail(ErrorCode::Unrecognized, {}, fmt::format("trace level {} is not in 0..5", level));
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    const std::string name = trimmed_lower(std::string_view(list).substr(start, end - start));
    start = end + 1;
    if (name == "@all") {
      default_trace_level = int(level);
      std::fill(procedure_trace_level.begin(), procedure_trace_level.end(), -1);
      command_trace_level.clear();
    } else if (name.size() > 1) {
      if (auto it = program.procedure_index.find(name); it != program.procedure_index.end())
        procedure_trace_level[it->second] = int(level);
      else
        command_trace_level[name] = int(level);
    }
  }
}

void Interpreter::State::trace_line(std::string text) {
  if (!trace_remainder.empty()) {
    // The tail of a long procedure name goes at column 4 of the next line (over its blank prefix).
    std::string head = "   " + trace_remainder;
    trace_remainder.clear();
    if (text.size() > head.size() && text.find_first_not_of(' ') >= head.size()) text.replace(0, head.size(), head);
    else *trace << head << '\n';
  }
  *trace << text << '\n';
}

void Interpreter::State::trace_enter(std::string_view name, int depth, int level) {
  last_header_level = level;
  const bool dump = level >= 3 && depth <= 1;
  std::string header = fmt::format("({}){}", depth, name);
  std::string tail;
  if (header.size() > kHeaderWidth) {
    tail = header.substr(kHeaderWidth);
    header.resize(kHeaderWidth);
  }
  header.resize(kHeaderWidth, ' ');
  header += "==>";
  if (!trace_remainder.empty()) trace_line(std::string());
  std::string text = header;
  if (dump) {
    for (std::uint32_t id : host_assigned) {
      const Cell& c = host_cell(id);
      std::string pair = fmt::format(" {}:{}", host_name(id), trace_value(c.value, c.changed));
      if (text.size() + pair.size() > kWrapColumn && text.size() > kHeaderWidth + 3) {
        trace_line(std::move(text));
        trace_remainder = std::move(tail);
        tail.clear();
        text = std::string(kHeaderWidth, ' ') + "..>";
      }
      text += pair;
    }
  }
  trace_line(std::move(text));
  trace_remainder = std::move(tail);
  host_assigned.clear();
}

// A finished line is shown under the header written last (lines are traced when they end).
void Interpreter::State::trace_output(std::string_view text) {
  if (in_init || last_header_level < 2) return;
  trace_line(kOutputPrefix + "> " + std::string(text));
}

}  // namespace gppl
