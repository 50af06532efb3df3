#include "prp/mode_commands.hpp"

#include <fmt/format.h>

#include "prp/motion.hpp"

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
    std::swap(out, held_);
    return true;
  }
  if (!input_.next(out)) return false;
  if (done_ || !out.is_stream_command()) return true;
  if (is(out, "@absolute_mode") || is(out, "@relative_mode")) {
    done_ = true;  // the toolpath sets the mode itself
    return true;
  }
  if (is(out, "@proc") || is(out, "@call_proc") || is(out, "@call_prms") || is(out, "@loop")) structured_ = true;
  if (!is_motion_block(out)) return true;
  done_ = true;
  if (structured_) {
    if (warn_) warn_(out, fmt::format("the PRP says {} but the toolpath sends no {} before its first motion", why_, mode_));
    return true;
  }
  std::swap(held_, out);
  has_held_ = true;
  out.clear();
  out.name = mode_;
  out.index = held_.index;
  return true;
}

}  // namespace prp
