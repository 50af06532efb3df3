// A controller's tool table, for the models that apply tool length compensation (G43 H) when they
// read a program back. The file is LinuxCNC's tool table format, which the other controls' offset
// pages map onto one line per tool:
//
//   T1 P1 Z+50.200 D6.000 ;6 mm end mill
//
// T is the tool (and offset) number, Z its length, D its diameter; P (the pocket) and the other
// axes' offsets (X Y A B C U V W, lathe I J Q) are accepted and not used. `;` starts a comment.
// Values are in the program's units. docs/iso.md, "Tool table".
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace ncmodel {

struct ToolOffsets {
  double length = 0;    // Z
  double diameter = 0;  // D
};

struct ToolTable {
  std::string file;  // for messages
  std::map<std::int64_t, ToolOffsets> tools;

  const ToolOffsets* find(std::int64_t tool) const {
    const auto it = tools.find(tool);
    return it == tools.end() ? nullptr : &it->second;
  }
};

// Throws toolpath::InputError (file:line:column, what was expected) for a malformed line, a tool
// given twice, or a file that cannot be read.
ToolTable parse_tool_table(std::string_view text, const std::string& file);
ToolTable load_tool_table(const std::string& path);

}  // namespace ncmodel
