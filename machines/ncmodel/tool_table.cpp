#include "machines/ncmodel/tool_table.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <optional>

#include "machines/ncmodel/block_text.hpp"
#include "toolpath/bounded_read.hpp"
#include "toolpath/error.hpp"

namespace ncmodel {
namespace {

constexpr std::size_t kMaxTableBytes = 16u << 20;  // a tool table of 16 MiB is no tool table
constexpr std::int64_t kMaxTool = 99'999'999;

void read_line(std::string_view text, const std::string& file, std::size_t number, ToolTable& table) {
  auto fail = [&](std::size_t column, const std::string& message) {
    throw toolpath::InputError({file, number, column}, message);
  };
  Cursor c{text.substr(0, text.find(';'))};
  std::optional<std::int64_t> tool;
  std::size_t tool_column = 0;
  ToolOffsets offsets;
  for (c.skip(); !c.at_end(); c.skip()) {
    const std::size_t column = c.column();
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(c.text[c.i])));
    if (!std::strchr("TPXYZABCUVWDIJQ", letter))
      fail(column, fmt::format("expected a word T, P, X, Y, Z, A, B, C, U, V, W, D, I, J or Q, found `{}`",
                               toolpath::excerpt(c.text.substr(c.i), 10)));
    ++c.i;
    if (c.at_end() || c.peek() == ';') fail(c.column(), fmt::format("expected the number of {}", letter));
    double value = 0;
    try {
      value = c.number();
    } catch (const BlockError& e) {
      fail(e.column, fmt::format("{} of {}", e.message, letter));
    }
    if (letter == 'T') {
      if (value < 0 || value > kMaxTool || value != std::trunc(value))
        fail(column, fmt::format("expected a tool number 0 .. {}, found T{:g}", kMaxTool, value));
      tool = static_cast<std::int64_t>(value);
      tool_column = column;
    } else if (letter == 'Z') {
      offsets.length = value;
    } else if (letter == 'D') {
      if (value < 0) fail(column, fmt::format("expected a diameter of 0 or more, found D{:g}", value));
      offsets.diameter = value;
    }
  }
  if (c.text.find_first_not_of(" \t\r") == std::string_view::npos) return;  // blank or a comment
  if (!tool) fail(1, "expected the tool number T on the line");
  if (!table.tools.emplace(*tool, offsets).second)
    fail(tool_column, fmt::format("T{} is in the table twice", *tool));
}

}  // namespace

ToolTable parse_tool_table(std::string_view text, const std::string& file) {
  ToolTable table;
  table.file = file;
  std::size_t number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    read_line(line, file, ++number, table);
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return table;
}

ToolTable load_tool_table(const std::string& path) {
  return parse_tool_table(toolpath::read_file_bounded(path, kMaxTableBytes, "larger than 16 MiB: not a tool table?",
                                                      "cannot open the tool table"),
                          path);
}

}  // namespace ncmodel
