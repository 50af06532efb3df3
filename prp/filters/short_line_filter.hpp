// Drops straight lines shorter than `eps_line` (spec 3.1), measured from the last position sent on,
// so a chain of tiny segments still advances; the last line of a contour is always kept so the
// contour ends where the toolpath says. Holds back at most one line.
#pragma once

#include "prp/filters/motion.hpp"
#include "toolpath/source.hpp"

namespace prp {

class ShortLineFilter final : public toolpath::CommandSource {
public:
  ShortLineFilter(toolpath::CommandSource& input, double eps_line) : input_(input), eps_line_(eps_line) {}
  bool next(toolpath::Command& out) override;

private:
  bool is_short(const toolpath::Command& line) const;
  bool hand_out(toolpath::Command& out, toolpath::Command& from);

  toolpath::CommandSource& input_;
  double eps_line_;
  ToolPosition sent_;  // where the commands handed out so far leave the tool
  toolpath::Command current_, held_, queued_;
  bool has_held_ = false, has_queued_ = false;
};

}  // namespace prp
