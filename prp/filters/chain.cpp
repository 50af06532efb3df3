// The stream filters, wired in the order of spec 3.0: structure (checks, drill expansion, default
// positions), then geometry (short lines, arcs, zero snapping and precision).
#include <vector>

#include "prp/filters/arc_filter.hpp"
#include "prp/filters/command_step.hpp"
#include "prp/filters/compensation_check.hpp"
#include "prp/filters/drill_expansion.hpp"
#include "prp/filters/full_coordinates.hpp"
#include "prp/filters/init_cpos.hpp"
#include "prp/filters/mode_commands.hpp"
#include "prp/filters/precision_filter.hpp"
#include "prp/filters/procedure_generation.hpp"
#include "prp/prp.hpp"
#include "prp/filters/rotary_axes.hpp"
#include "prp/filters/short_line_filter.hpp"
#include "prp/filters/structure_check.hpp"
#include "prp/filters/wire_guides.hpp"

namespace prp {
namespace {

// Owns the filters; pulls from the last one.
class Chain final : public toolpath::CommandSource {
public:
  explicit Chain(toolpath::CommandSource& input) : last_(&input) {}
  template <class Filter, class... Args>
  void add(Args&&... args) {
    auto filter = std::make_unique<Filter>(*last_, std::forward<Args>(args)...);
    last_ = filter.get();
    filters_.push_back(std::move(filter));
    steps_ = nullptr;
  }
  // A step joins the steps added just before it in one layer.
  template <class Step, class... Args>
  void add_step(Args&&... args) {
    if (!steps_) {
      add<Steps>();
      steps_ = static_cast<Steps*>(last_);
    }
    steps_->add(std::make_unique<Step>(std::forward<Args>(args)...));
  }
  bool next(toolpath::Command& out) override { return last_->next(out); }

private:
  toolpath::CommandSource* last_;
  std::vector<std::unique_ptr<toolpath::CommandSource>> filters_;
  Steps* steps_ = nullptr;  // the last layer, when it is one of steps
};

// The filters before procedure generation: checks, drill expansion, mode commands, rotary axes,
// default positions.
void add_structure_filters(Chain& chain, const MachineParameters& params, const WarningSink& warn) {
  chain.add_step<StructureCheck>(params, warn);
  // Before procedure generation reorders the jobs: it follows the tool and the side in stream order.
  if (CompensationCheck::needed(params)) chain.add_step<CompensationCheck>(params.numeric("min_delt_arc_rad"), warn);
  if (DrillExpansion::needed(params)) chain.add<DrillExpansion>(params, warn);
  if (!ModeCommands::wanted(params).empty()) chain.add<ModeCommands>(params, warn);
  chain.add_step<RotaryAxes>(params, warn);
  if (params.logical("init_cpos")) chain.add<InitCpos>();
  if (WireGuides::needed(params)) chain.add<WireGuides>(params);
  // Of the command alone (spec 3.8), so here, where it joins the steps before it in one layer.
  if (params.has("dflt_start") || params.has("dflt_end")) chain.add_step<DefaultPositions>(params);
}

}  // namespace

bool two_passes_possible(const MachineParameters& params) {
  // Each of these looks at motions a skim leaves out (ModeCommands: the first motion of the job;
  // InitCpos: the last C of any command; WireGuides: every move) to decide what it adds.
  return ProcedureGeneration::needed(params) && ModeCommands::wanted(params).empty() && !params.logical("init_cpos") &&
         !WireGuides::needed(params);
}

std::shared_ptr<JobForecast> forecast_jobs(const MachineParameters& params, toolpath::CommandSource& skimmed) {
  if (!two_passes_possible(params)) return nullptr;
  try {
    Chain chain(skimmed);
    add_structure_filters(chain, params, {});
    auto found = ProcedureGeneration::forecast(chain, params);
    return found ? std::make_shared<JobForecast>(std::move(*found)) : nullptr;
  } catch (const std::exception&) {
    return nullptr;  // one pass then, which reports whatever it was where it is
  }
}

std::unique_ptr<toolpath::CommandSource> build_filter_chain(const MachineParameters& params,
                                                            toolpath::CommandSource& input, WarningSink warn,
                                                            std::shared_ptr<JobForecast> forecast) {
  auto chain = std::make_unique<Chain>(input);
  add_structure_filters(*chain, params, warn);
  // After the filters that add commands to inline jobs, so that those commands travel with their job.
  if (forecast && two_passes_possible(params)) chain->add<ProcedureGeneration>(params, std::move(*forecast));
  else if (ProcedureGeneration::needed(params)) chain->add<ProcedureGeneration>(params);
  if (params.numeric("eps_line") > 0) chain->add<ShortLineFilter>(params.numeric("eps_line"));
  // Always there: even a machine that takes every arc is not sent one that is no arc (check_circle).
  chain->add<ArcFilter>(ArcSettings::from(params), warn);
  if (auto precision = PrecisionSettings::from(params); !precision.does_nothing()) chain->add<PrecisionFilter>(precision);
  if (params.logical("full_gcode")) chain->add<FullCoordinates>();
  return chain;
}

}  // namespace prp
