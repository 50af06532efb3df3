// `init_cpos = Y` (spec 3.13, gpptool 8.13): before the first move of each simultaneous 4-axis job
// the machine is told where to put its C zero so the job does not unwind the part: @init_cpos with
// `prev_cpos`, the C angle the previous job ended at, and `best_cpos`, that same physical position
// renamed by whole turns so the job's first C is less than half a turn away.
#pragma once

#include <optional>

#include "prp/prp.hpp"

namespace prp {

// prev_cpos + 360 k, the k that brings it closest to `first` (ties towards the smaller angle).
double best_cpos(double prev_cpos, double first);

class InitCpos final : public toolpath::CommandSource {
public:
  explicit InitCpos(toolpath::CommandSource& input) : input_(input) {}
  bool next(toolpath::Command& out) override;

private:
  toolpath::CommandSource& input_;
  std::optional<double> cpos_;  // the last C angle sent
  bool new_job_ = false;        // no 4-axis move yet in the current job
  toolpath::Command held_;
  bool has_held_ = false;
};

}  // namespace prp
