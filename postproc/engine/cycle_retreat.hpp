// Where a lathe cycle leaves the tool (docs/engine.md, "Turning cycles"). The control runs the
// passes of a `@turning` cycle itself, so the last move the stream shows (the cycle's geometry,
// when it follows in @turn_proc .. @turn_endproc) is not where the tool stops: the PRP's
// rough_retreat, semi_finish_retreat and finish_retreat say whether the cycle returns to its
// start point (Y) or stays at its last point (N). The engine then holds that position in xpos,
// ypos and zpos, without a change, so that the next move writes the axes that really move.
#pragma once

#include <optional>
#include <string_view>

#include "prp/prp.hpp"
#include "toolpath/command.hpp"

namespace postproc {

class CycleRetreat {
public:
  struct Point {
    double x = 0, y = 0, z = 0;
  };

  explicit CycleRetreat(const prp::MachineParameters& machine);

  // After `command`'s procedure ran, with the position the post's variables hold (`where`) and the
  // next command's name: the position the tool is at when a cycle has just ended, else nothing.
  std::optional<Point> after(const toolpath::Command& command, std::string_view next, const Point& where);

private:
  bool rough_, semi_finish_, finish_;
  std::optional<Point> pending_;  // a cycle whose geometry is still being sent
};

}  // namespace postproc
