// Filters that change commands one for one, in place, each only for some kinds of command (the
// checks, rotary axes): the chain runs several of them in one layer (Steps) instead of a layer
// each, which would cost every command a call and a return per filter.
//
//   class MyCheck final : public CommandStep {
//   public:
//     MyCheck() : CommandStep(bit(CommandKind::arc)) {}
//     void apply(toolpath::Command& c, CommandKind& kind) override;  // rename c? then set kind as well
//   };
//   StepFilter<MyCheck> filter(input);  // one step as a filter of its own
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "prp/filters/kind_source.hpp"

namespace prp {

class CommandStep {
public:
  virtual ~CommandStep() = default;
  // Called for each stream command whose kind is in kinds(), in stream order.
  virtual void apply(toolpath::Command& c, CommandKind& kind) = 0;
  // Any other command passes untouched. A step may change its kinds as it goes, in apply() only.
  KindSet kinds() const { return kinds_; }

protected:
  explicit CommandStep(KindSet kinds) : kinds_(kinds) {}
  KindSet kinds_;
};

// Runs its steps, in the order added, on each command of its input.
class Steps final : public KindSource {
public:
  explicit Steps(toolpath::CommandSource& input) : input_(input) {}
  void add(std::unique_ptr<CommandStep> step) {
    wanted_ |= step->kinds();
    steps_.push_back(std::move(step));
  }
  bool next_with_kind(toolpath::Command& out, CommandKind& kind) override {
    if (!input_.next(out, kind)) return false;
    if (has(wanted_, kind) && out.is_stream_command()) apply(out, kind);  // most commands no step wants
    return true;
  }

private:
  void apply(toolpath::Command& out, CommandKind& kind) {
    KindSet wanted = 0;
    for (const auto& step : steps_) {
      if (has(step->kinds(), kind)) step->apply(out, kind);
      wanted |= step->kinds();  // as the step now has them
    }
    wanted_ = wanted;
  }

  KindedInput input_;
  std::vector<std::unique_ptr<CommandStep>> steps_;
  KindSet wanted_ = 0;  // the kinds of all the steps
};

// One step as a filter of its own.
template <class Step>
class StepFilter final : public KindSource {
public:
  template <class... Args>
  explicit StepFilter(toolpath::CommandSource& input, Args&&... args)
      : input_(input), step_(std::forward<Args>(args)...) {}
  bool next_with_kind(toolpath::Command& out, CommandKind& kind) override {
    if (!input_.next(out, kind)) return false;
    if (out.is_stream_command() && has(step_.kinds(), kind)) step_.apply(out, kind);
    return true;
  }

private:
  KindedInput input_;
  Step step_;
};

}  // namespace prp
