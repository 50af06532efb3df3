// Internal helpers shared by the stream filters: reading and writing positions and numbers of
// commands, and following where the tool is.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "prp/command_kind.hpp"
#include "toolpath/command.hpp"

namespace prp {

bool is(const toolpath::Command& c, std::string_view name);
// Commands whose xpos/ypos/zpos is where the tool is afterwards.
bool moves_tool(const toolpath::Command& c);
bool is_feed_motion(const toolpath::Command& c);  // @line, @arc, @line_on, ...
// A command that moves the machine: 3-, 4- and 5-axis moves and arcs, and @drill (its first hole).
bool is_motion_block(const toolpath::Command& c);

std::optional<double> number(const toolpath::Command& c, std::string_view name);
void set_number(toolpath::Command& c, std::string_view name, double v);
void set_point(toolpath::Command& c, const Eigen::Vector3d& p);

// The tool position, axis by axis (an axis is unknown until a command sets it).
class ToolPosition {
public:
  void update(const toolpath::Command& c);
  void update(const toolpath::Command& c, CommandKind kind);  // kind: command_kind(c), already known
  std::optional<double> axis(int i) const { return axes_[static_cast<std::size_t>(i)]; }
  void set_axis(int i, double v) { axes_[static_cast<std::size_t>(i)] = v; }
  // All three axes, when known.
  std::optional<Eigen::Vector3d> point() const;

private:
  std::array<std::optional<double>, 3> axes_;
};

// A fresh stream command `name` with the position and (when given) the feed.
void make_motion(toolpath::Command& out, std::string_view name, const toolpath::Command& from,
                 const Eigen::Vector3d& p, std::optional<double> feed);

}  // namespace prp
