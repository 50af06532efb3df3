// Coordinate-mode commands the PRP asks for (spec 3.6): a controller that starts in incremental
// mode (`abs_coord = N`) gets @absolute_mode, and `relative_gcode = Y` gets @relative_mode, once,
// before the first motion of the program. Like the other structural additions this is done on a
// flat toolpath only: a toolpath that already has procedures (a SolidCAM trace) is checked, and a
// missing mode command there is a warning.
#pragma once

#include <string>

#include "prp/prp.hpp"

namespace prp {

class ModeCommands final : public toolpath::CommandSource {
public:
  ModeCommands(toolpath::CommandSource& input, const MachineParameters& params, WarningSink warn);
  bool next(toolpath::Command& out) override;
  // The mode command the parameters ask for ("@absolute_mode", "@relative_mode"), or empty.
  static std::string wanted(const MachineParameters& params);

private:
  toolpath::CommandSource& input_;
  WarningSink warn_;
  std::string mode_;  // the command to send
  std::string why_;   // the PRP setting that asks for it
  bool done_ = false;
  bool structured_ = false;
  toolpath::Command held_;
  bool has_held_ = false;
};

}  // namespace prp
