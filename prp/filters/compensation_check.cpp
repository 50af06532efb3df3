#include "prp/filters/compensation_check.hpp"

#include <fmt/format.h>

#include "prp/filters/motion.hpp"

namespace prp {

bool CompensationCheck::needed(const MachineParameters& params) {
  return params.has("min_delt_arc_rad") && params.logical("comp_exist") && !params.logical("comp_by_zero_tool");
}

namespace {

constexpr KindSet kFollowed =
    bit(CommandKind::change_tool) | bit(CommandKind::turn_change_tool) | bit(CommandKind::compensation);

}  // namespace

// Arcs only while there is something to check them against.
CompensationCheck::CompensationCheck(double margin, WarningSink warn)
    : CommandStep(kFollowed), margin_(margin), warn_(std::move(warn)) {}

void CompensationCheck::apply(toolpath::Command& out, CommandKind& kind) {
  if (kind == CommandKind::change_tool || kind == CommandKind::turn_change_tool) {
    if (auto d = number(out, "tool_diameter")) tool_radius_ = *d / 2;
    else if (auto r = number(out, "tool_radius")) tool_radius_ = *r;
  } else if (kind == CommandKind::compensation) {
    const toolpath::Value* side = out.find("side");
    side_ = side && !toolpath::iequals(side->text, "COMP_OFF") ? side->text : std::string();
  } else if (kind == CommandKind::arc && !side_.empty() && tool_radius_) {
    const toolpath::Value* dir = out.find(toolpath::ParamKey::arc_direction);
    auto radius = number(out, toolpath::ParamKey::radius);
    // The tool runs inside the arc when it is on the side of the centre: left of a CCW arc,
    // right of a CW one.
    const bool concave = dir && toolpath::iequals(dir->text, "CCW") == toolpath::iequals(side_, "COMP_LEFT");
    if (concave && radius && *radius < *tool_radius_ + margin_ && warn_)
      warn_(out, fmt::format("arc radius {:g} is below tool radius {:g} + min_delt_arc_rad {:g} on the compensated "
                             "side ({})",
                             *radius, *tool_radius_, margin_, side_));
  }
  kinds_ = !side_.empty() && tool_radius_ ? kFollowed | bit(CommandKind::arc) : kFollowed;
}

}  // namespace prp
