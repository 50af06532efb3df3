// `min_delt_arc_rad` (spec 3.5): while cutter compensation is on, a concave arc (one the tool runs
// inside of) must have a radius of at least the tool radius plus this margin, or the controller
// cannot offset it. The consequence is not stated, so the filter warns, naming the arc, and
// changes nothing. With `comp_by_zero_tool = Y` the toolpath is already the tool-centre path and
// the controller compensates only wear, so there is nothing to check.
#pragma once

#include <optional>
#include <string>

#include "prp/filters/command_step.hpp"
#include "prp/prp.hpp"

namespace prp {

class CompensationCheck final : public CommandStep {
public:
  CompensationCheck(double margin, WarningSink warn);
  void apply(toolpath::Command& c, CommandKind& kind) override;
  static bool needed(const MachineParameters& params);

private:
  double margin_;
  WarningSink warn_;
  std::optional<double> tool_radius_;
  std::string side_;  // COMP_LEFT, COMP_RIGHT, or empty when off
};

}  // namespace prp
