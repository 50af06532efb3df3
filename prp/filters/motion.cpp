#include "prp/filters/motion.hpp"

#include "prp/prp.hpp"

#include <fmt/format.h>

namespace prp {

StreamError::StreamError(const toolpath::Command& command, const std::string& message)
    : std::runtime_error(fmt::format("command {} ({}): {}", command.index, command.name, message)),
      index_(command.index),
      line_(command.line),
      name_(command.name),
      message_(message) {}

bool is(const toolpath::Command& c, std::string_view name) { return toolpath::iequals(c.name, name); }

bool moves_tool(const toolpath::Command& c) { return c.is_stream_command() && has(kMovesTool, command_kind(c)); }

bool is_feed_motion(const toolpath::Command& c) { return c.is_stream_command() && has(kFeedMotion, command_kind(c)); }

bool is_motion_block(const toolpath::Command& c) {
  return c.is_stream_command() && has(kMotionBlock, command_kind(c));
}

std::optional<double> number(const toolpath::Command& c, std::string_view name) {
  const toolpath::Value* v = c.find(name);
  if (!v || !is_number(*v)) return std::nullopt;
  return number_of(*v);
}

void set_number(toolpath::Command& c, std::string_view name, double v) {
  // Keep an explicit change flag written in the trace.
  const toolpath::Value* old = c.find(name);
  c.set(name, toolpath::Value::make_numeric(v, old ? old->flag : toolpath::ChangeFlag::None));
}

std::optional<double> number(const toolpath::Command& c, toolpath::ParamKey key) {
  const toolpath::Value* v = c.find(key);
  if (!v || !is_number(*v)) return std::nullopt;
  return number_of(*v);
}

void set_number(toolpath::Command& c, toolpath::ParamKey key, double v) {
  const toolpath::Value* old = c.find(key);
  c.set(key, toolpath::Value::make_numeric(v, old ? old->flag : toolpath::ChangeFlag::None));
}

void set_point(toolpath::Command& c, const Eigen::Vector3d& p) {
  using toolpath::ParamKey;
  set_number(c, ParamKey::xpos, p.x());
  set_number(c, ParamKey::ypos, p.y());
  set_number(c, ParamKey::zpos, p.z());
}

namespace {

// xpos, ypos, zpos: 0, 1, 2; anything else -1.
int axis_of(toolpath::ParamKey key) {
  using toolpath::ParamKey;
  return key == ParamKey::xpos ? 0 : key == ParamKey::ypos ? 1 : key == ParamKey::zpos ? 2 : -1;
}

}  // namespace

// One pass over the parameters (it runs for every command, in several filters); the first xpos,
// ypos, zpos count, as with number().
void ToolPosition::update(const toolpath::Command& c) { update(c, command_kind(c)); }

void ToolPosition::update(const toolpath::Command& c, CommandKind kind) {
  if (!c.is_stream_command() || !has(kMovesTool, kind)) return;
  unsigned seen = 0;
  for (const toolpath::Parameter& p : c.parameters) {
    const int i = axis_of(p.key);
    if (i < 0 || (seen & (1u << i))) continue;
    seen |= 1u << i;
    if (is_number(p.value)) axes_[static_cast<std::size_t>(i)] = number_of(p.value);
    if (seen == 7) break;  // moves usually name xpos ypos zpos first
  }
}

std::optional<Eigen::Vector3d> ToolPosition::point() const {
  if (!axes_[0] || !axes_[1] || !axes_[2]) return std::nullopt;
  return Eigen::Vector3d(*axes_[0], *axes_[1], *axes_[2]);
}

void make_motion(toolpath::Command& out, std::string_view name, const toolpath::Command& from,
                 const Eigen::Vector3d& p, std::optional<double> feed) {
  out.clear();
  out.name = std::string(name);
  out.index = from.index;
  out.depth = from.depth;
  out.line = from.line;
  out.parameters.push_back({"xpos", toolpath::Value::make_numeric(p.x())});
  out.parameters.push_back({"ypos", toolpath::Value::make_numeric(p.y())});
  out.parameters.push_back({"zpos", toolpath::Value::make_numeric(p.z())});
  if (feed) out.parameters.push_back({"feed", toolpath::Value::make_numeric(*feed)});
}

}  // namespace prp
