#include "prp/filters/mode_commands.hpp"

#include <fmt/format.h>

#include "prp/filters/motion.hpp"

namespace prp {

std::string ModeCommands::wanted(const MachineParameters& params) {
  if (params.logical("relative_gcode")) return "@relative_mode";
  if (!params.logical("abs_coord")) return "@absolute_mode";
  return {};
}

ModeCommands::ModeCommands(toolpath::CommandSource& input, const MachineParameters& params, WarningSink warn)
    : input_(input), warn_(std::move(warn)), mode_(wanted(params)) {
  why_ = params.logical("relative_gcode") ? "relative_gcode = Y" : "abs_coord = N";
}

bool ModeCommands::next(toolpath::Command& out) {
  if (has_held_) {
    has_held_ = false;
    swap(out, held_);
    return true;
  }
  if (!input_.next(out)) return false;
  if (done_ || !out.is_stream_command()) return true;
  using K = CommandKind;
  const K kind = command_kind(out);
  if (kind == K::absolute_mode || kind == K::relative_mode) {
    done_ = true;  // the toolpath sets the mode itself
    return true;
  }
  if (kind == K::proc || kind == K::call_proc || kind == K::call_prms || kind == K::loop) structured_ = true;
  if (!has(kMotionBlock, kind)) return true;
  done_ = true;
  if (structured_) {
    if (warn_) warn_(out, fmt::format("the PRP says {} but the toolpath sends no {} before its first motion", why_, mode_));
    return true;
  }
  swap(held_, out);
  has_held_ = true;
  out.clear();
  out.name = mode_;
  out.index = held_.index;
  out.line = held_.line;
  return true;
}

}  // namespace prp
