// `full_gcode = Y` (spec 3.6): coordinates are not modal on the controller, so every motion block
// must print X, Y and Z. The filter marks xpos, ypos and zpos as changed on every motion command
// (a modal group such as [' X'xpos] then always prints) and fills an axis a 3-axis move leaves out
// from the tool position. No command is added.
#pragma once

#include "prp/filters/kind_source.hpp"
#include "prp/filters/motion.hpp"
#include "prp/prp.hpp"

namespace prp {

class FullCoordinates final : public KindSource {
public:
  explicit FullCoordinates(toolpath::CommandSource& input) : input_(input) {}
  bool next_with_kind(toolpath::Command& out, CommandKind& kind) override;

private:
  KindedInput input_;
  ToolPosition position_;
};

}  // namespace prp
