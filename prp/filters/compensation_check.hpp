// `min_delt_arc_rad` (spec 3.5): while cutter compensation is on, a concave arc (one the tool runs
// inside of) must have a radius of at least the tool radius plus this margin, or the controller
// cannot offset it. The consequence is not stated, so the filter warns, naming the arc, and
// changes nothing. With `comp_by_zero_tool = Y` the toolpath is already the tool-centre path and
// the controller compensates only wear, so there is nothing to check.
#pragma once

#include <optional>
#include <string>

#include "prp/filters/kind_source.hpp"
#include "prp/prp.hpp"

namespace prp {

class CompensationCheck final : public KindSource {
public:
  CompensationCheck(toolpath::CommandSource& input, double margin, WarningSink warn)
      : input_(input), margin_(margin), warn_(std::move(warn)) {}
  bool next_with_kind(toolpath::Command& out, CommandKind& kind) override;
  static bool needed(const MachineParameters& params);

private:
  KindedInput input_;
  double margin_;
  WarningSink warn_;
  std::optional<double> tool_radius_;
  std::string side_;  // COMP_LEFT, COMP_RIGHT, or empty when off
};

}  // namespace prp
