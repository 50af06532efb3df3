// The PRP's rotary-axis switches on the stream (spec 3.13, 3.14). SolidCAM applies them while it
// computes a multi-axis toolpath; the engine makes a flat toolpath say what SolidCAM would send and
// checks a trace against them:
// - set_dir = Y: a @move_4x or @line_4x without a direction becomes @move4x_dir or @line4x_dir,
//   its C normalised to 0 .. 360, `dc` the signed change of C, `dir4x` CCW for a positive change
//   and CW for a negative one;
// - positive_4x_dir_only = Y: a simultaneous 4-axis cut that turns C back is a warning (SolidCAM
//   computes such jobs turning forward only);
// - angle_change_limit: a 5-axis cut whose rotary angle changes by more is a warning (SolidCAM
//   retracts out of the cut there).
#pragma once

#include <optional>
#include <set>
#include <string>

#include "prp/filters/command_step.hpp"
#include "prp/prp.hpp"

namespace prp {

class RotaryAxes final : public CommandStep {
public:
  RotaryAxes(const MachineParameters& params, WarningSink warn);
  void apply(toolpath::Command& c, CommandKind& kind) override;

private:
  void four_axis(toolpath::Command& c, CommandKind& kind);
  void five_axis(const toolpath::Command& c, CommandKind kind);
  void warn_once(const toolpath::Command& c, const std::string& key, const std::string& message);

  WarningSink warn_;
  bool set_dir_, positive_only_;
  double angle_limit_;
  std::optional<double> c_;               // the last C sent, unnormalised
  std::optional<double> a_, b_;           // the last 5-axis angles
  std::set<std::string> warned_;          // one warning per switch
};

}  // namespace prp
