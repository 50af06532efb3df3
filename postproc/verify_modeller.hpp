// Internal to `postproc verify`: the motion single toolpath commands stand for (verify_expected.cpp).
// Subroutine calls and loops are expanded before the commands get here (verify_expansion.cpp).
#pragma once

#include <deque>
#include <memory>

#include "postproc/verify.hpp"

namespace postproc::verify {

// Turns commands, in the order the machine runs them, into motion appended to `out`, keeping the
// tool's position, the spindle state and the drill cycle between commands.
class CommandModel {
public:
  CommandModel(const prp::MachineParameters& machine, std::deque<Motion>& out);
  ~CommandModel();
  CommandModel(const CommandModel&) = delete;
  CommandModel& operator=(const CommandModel&) = delete;
  // Throws std::runtime_error naming the command when verify cannot model it.
  void command(const toolpath::Command& c);

private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace postproc::verify
