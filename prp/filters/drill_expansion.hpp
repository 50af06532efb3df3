// Drill cycles the machine does not have (a `drill_type` record with flag N, spec 3.11) become
// explicit moves, hole by hole; cycles that need spindle reversal or a stop (TAPPING, R_BORING)
// cannot be expanded and stop the run with an error naming the cycle and the job.
#pragma once

#include <deque>
#include <string>

#include "prp/filters/motion.hpp"
#include "prp/prp.hpp"

namespace prp {

class DrillExpansion final : public toolpath::CommandSource {
public:
  DrillExpansion(toolpath::CommandSource& input, const MachineParameters& params, WarningSink warn)
      : input_(input), params_(params), warn_(std::move(warn)) {}
  bool next(toolpath::Command& out) override;

  // True when some drill record has flag N (otherwise the filter is not needed).
  static bool needed(const MachineParameters& params);

private:
  void start_cycle(const toolpath::Command& drill);
  void expand_hole(const toolpath::Command& point);

  toolpath::CommandSource& input_;
  const MachineParameters& params_;
  WarningSink warn_;
  std::string job_;  // name of the current job, for messages
  bool expanding_ = false;
  toolpath::Command drill_;          // the @drill being expanded
  std::string base_;                 // its record's base type
  std::optional<double> dwell_;      // F_DRILL, F_BORING
  std::deque<toolpath::Command> pending_;  // the moves of one hole
};

}  // namespace prp
