// Internal helpers shared by the stream filters: reading and writing positions and numbers of
// commands, and following where the tool is.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include <Eigen/Core>

#include "prp/filters/command_kind.hpp"
#include "toolpath/command.hpp"

namespace prp {

bool is(const toolpath::Command& c, std::string_view name);
// Commands whose xpos/ypos/zpos is where the tool is afterwards.
bool moves_tool(const toolpath::Command& c);
bool is_feed_motion(const toolpath::Command& c);  // @line, @arc, @line_on, ...
// A command that moves the machine: 3-, 4- and 5-axis moves and arcs, and @drill (its first hole).
bool is_motion_block(const toolpath::Command& c);

std::optional<double> number(const toolpath::Command& c, std::string_view name);
// Value::as_number() for a value already known to be Integer or Numeric, inline.
inline double number_of(const toolpath::Value& v) {
  return v.kind == toolpath::ValueKind::Integer ? static_cast<double>(v.integer) : v.numeric;
}
inline bool is_number(const toolpath::Value& v) {
  return v.kind == toolpath::ValueKind::Integer || v.kind == toolpath::ValueKind::Numeric;
}
void set_number(toolpath::Command& c, std::string_view name, double v);
// The same by interned key (one integer compare per parameter): the filters' per-command paths.
std::optional<double> number(const toolpath::Command& c, toolpath::ParamKey key);
void set_number(toolpath::Command& c, toolpath::ParamKey key, double v);

// A table from every ParamKey (none included) to a small code, filled by the compiler: a filter
// classifies a parameter with one load instead of comparing its name. Every name such a table
// lists must be in the catalogue (toolpath/param_names.inc), so ParamKey::none maps to `fill`.
template <class T>
using KeyTable = std::array<T, toolpath::param_key_count + 1>;
template <class T>
constexpr const T& at(const KeyTable<T>& table, toolpath::ParamKey key) {
  return table[static_cast<std::size_t>(key)];
}
template <class T>
constexpr T& at(KeyTable<T>& table, toolpath::ParamKey key) {
  return table[static_cast<std::size_t>(key)];
}
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
