// Checks a structured toolpath (a SolidCAM trace already carries procedures, loops and
// transformations) against the PRP's structure switches (spec 3.0, 3.5, 3.7, 3.9, 3.10). It never
// restructures: mismatches and a program number outside the PRP's range are warnings; procedure
// labels outside the PRP's limits and controller compensation on a machine without it are errors. A
// tool change or spindle start without `tool_direction` gets CW (what SolidCAM sends for a usual tool).
#pragma once

#include <set>
#include <string>

#include "prp/filters/command_step.hpp"
#include "prp/filters/kind_source.hpp"
#include "prp/prp.hpp"

namespace prp {

class StructureCheck final : public CommandStep {
public:
  StructureCheck(const MachineParameters& params, WarningSink warn);
  void apply(toolpath::Command& c, CommandKind& kind) override;

private:
  void check(const toolpath::Command& c, CommandKind kind);

  WarningSink warn_;
  std::string gen_procs_;
  bool procs_off_, calls_with_parameters_;  // gen_procs N, D
  bool loop_exist_, rotate_, mirror_, software_transform_, comp_exist_, wire_cut_, turning_cycle_, groove_cycle_;
  NumberRange programs_, procedures_;
  std::optional<std::int64_t> num_homes_;
  std::set<std::string> warned_;  // command names already reported
};

// Fills the program's start and end positions from dflt_start / dflt_end (spec 3.8) when the
// toolpath does not give them: @start_program and @end_program without xpos, ypos and zpos. It
// looks at nothing but the command, so it may run before procedure generation moves commands.
class DefaultPositions final : public CommandStep {
public:
  explicit DefaultPositions(const MachineParameters& params);
  void apply(toolpath::Command& c, CommandKind& kind) override;

private:
  std::optional<Eigen::Vector3d> start_, end_;
};

}  // namespace prp
