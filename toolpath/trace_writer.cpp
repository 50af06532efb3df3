#include "toolpath/trace_writer.hpp"

#include <fmt/format.h>

namespace toolpath {
namespace {

constexpr std::size_t kArrowColumn = 20;  // `==>` and `..>` start in column 21, as SolidCAM writes them
constexpr std::size_t kLineWidth = 100;   // parameters wrap onto `..>` lines past this width

void append_flag(std::string& out, ChangeFlag flag) {
  if (flag == ChangeFlag::Changed) out += 'T';
  if (flag == ChangeFlag::Unchanged) out += 'F';
}

void pad_to(std::string& out, std::size_t line_start, std::size_t column) {
  const std::size_t used = out.size() - line_start;
  if (used < column) out.append(column - used, ' ');
}

}  // namespace

void append_value(std::string& out, const Value& value) {
  switch (value.kind) {
    case ValueKind::Integer:
      fmt::format_to(std::back_inserter(out), "{}", value.integer);
      append_flag(out, value.flag);
      break;
    case ValueKind::Numeric: {
      // Shortest text that reads back to the same double; always with a point or an exponent so
      // that it reads back as numeric, not integer.
      const std::size_t start = out.size();
      fmt::format_to(std::back_inserter(out), "{}", value.numeric);
      if (out.find_first_of(".eE", start) == std::string::npos) out += ".0";
      append_flag(out, value.flag);
      break;
    }
    case ValueKind::Logical: out += value.logical ? "true" : "false"; break;
    case ValueKind::Enum: out += value.text; break;
    case ValueKind::String: {
      const char q = value.text.find('\'') == std::string::npos ? '\'' : '"';
      out += q;
      out += value.text;
      out += q;
      break;
    }
  }
}

void append_command(std::string& out, const Command& command) {
  std::size_t line_start = out.size();
  fmt::format_to(std::back_inserter(out), "({}){}", command.depth, command.name);
  // Long names are written whole, followed by a blank, rather than cut as SolidCAM does: the
  // reader accepts both, and whole names are easier to grep.
  if (out.size() - line_start >= kArrowColumn) out += ' ';
  pad_to(out, line_start, kArrowColumn);
  out += "==>";

  std::size_t trace_from = 0;
  bool header_line_taken = false;
  if (!command.trace.empty() && command.trace.front().kind == TraceLine::Kind::Partial) {
    // Unfinished output shares the header line; the parameters then go on continuation lines.
    out += ' ';
    out += command.trace.front().text;
    trace_from = 1;
    header_line_taken = true;
  }
  std::size_t pairs_on_line = 0;
  for (const auto& p : command.parameters) {
    if (header_line_taken || (pairs_on_line > 0 && out.size() - line_start > kLineWidth)) {
      out += '\n';
      line_start = out.size();
      out.append(kArrowColumn, ' ');
      out += "..>";
      pairs_on_line = 0;
      header_line_taken = false;
    }
    out += ' ';
    out += p.name;
    out += ':';
    append_value(out, p.value);
    ++pairs_on_line;
  }
  out += '\n';
  for (std::size_t i = trace_from; i < command.trace.size(); ++i) {
    const TraceLine& t = command.trace[i];
    switch (t.kind) {
      case TraceLine::Kind::Output:
        out.append(kArrowColumn + 2, ' ');
        out += "> ";
        out += t.text;
        break;
      case TraceLine::Kind::Note:
        out.append(kArrowColumn, ' ');
        out += "..> ";
        out += t.text;
        break;
      case TraceLine::Kind::Directive:
        out += t.text;
        break;
      case TraceLine::Kind::Partial:  // only meaningful first; kept as an output line otherwise
        out.append(kArrowColumn + 2, ' ');
        out += "> ";
        out += t.text;
        break;
    }
    out += '\n';
  }
}

void TraceWriter::write(const Command& command) {
  append_command(buffer_, command);
  if (buffer_.size() > (1u << 16)) flush();
}

void TraceWriter::flush() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

}  // namespace toolpath
