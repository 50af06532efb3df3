// What the engine tracks about the program's structure while it streams: which subroutine body a
// command is in, which labels the main program calls (job subroutines), and the loop nesting. It
// fills in structural parameters a stream leaves out (`label` and `end_of_job` of @end_proc,
// `loop_level`, `loop_count` and `label` of @end_loop), so that hand-written streams stay short.
#pragma once

#include <cstdint>
#include <set>
#include <vector>

#include "toolpath/command.hpp"

namespace postproc {

class ProgramStructure {
public:
  // Call before the command's parameters are assigned: completes the command where it can.
  void before(toolpath::Command& command);
  // False for a command that before() leaves alone and that changes nothing it tracks (most of them).
  static bool concerns(const toolpath::Command& command);

  // True inside a subroutine body (between @proc and its @end_proc).
  bool in_subroutine() const { return !procs_.empty(); }
  // True when `command` starts a subroutine body or calls a subroutine: where the engine's modal
  // reset applies (docs/engine.md, "Modal memory at subroutine boundaries").
  static bool starts_body(const toolpath::Command& command);
  static bool calls_subroutine(const toolpath::Command& command);

private:
  struct Loop {
    std::int64_t label = 0, level = 0, count = 0;
  };
  std::vector<std::int64_t> procs_;  // labels of the open subroutine bodies
  std::set<std::int64_t> job_labels_;
  std::vector<Loop> loops_;
};

}  // namespace postproc
