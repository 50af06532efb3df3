// Internal to `postproc verify`: the motion single toolpath commands stand for (verify_expected.cpp).
// Subroutine calls and loops are expanded before the commands get here (verify_expansion.cpp).
#pragma once

#include <deque>
#include <memory>
#include <optional>
#include <string_view>

#include "postproc/checks/verify.hpp"
#include "toolpath/value.hpp"

namespace postproc::verify {

inline bool is(const toolpath::Command& c, std::string_view name) { return toolpath::iequals(c.name, name); }

inline std::optional<double> number(const toolpath::Command& c, std::string_view name) { return c.number(name); }

// Turns commands, in the order the machine runs them, into motion appended to `out`, keeping the
// tool's position, the spindle state and the drill cycle between commands.
class CommandModel {
public:
  CommandModel(const prp::MachineParameters& machine, const machines::VerifyProfile& profile, std::deque<Motion>& out);
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
