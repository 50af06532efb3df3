// A synthetic milling job of any length, generated on the fly (nothing is kept): a tool change,
// then `motions` commands alternating @line and @arc around a stepped contour, as SolidCAM sends
// them (every motion carries xpos/ypos/zpos/feed; arcs their centre, radius, angles, direction).
//
// Two shapes of the same job. `flat`: the job inline (@start_of_job .. @end_of_job), what SolidCAM
// sends for a machine with gen_procs = N. `procedures`: what it sends with gen_procs = Y (gpptool
// 2.3, 2.8; the manual's FANUC trace): the main program changes the tool and calls procedure 1,
// whose body, after @end_program, holds the job. It is exactly the stream prp::ProcedureGeneration
// builds from the flat shape, so both shapes post to the same NC program.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>

#include "toolpath/source.hpp"

namespace bench {

enum class JobShape { flat, procedures };

class SyntheticJob final : public toolpath::CommandSource {
public:
  explicit SyntheticJob(std::size_t motions, JobShape shape = JobShape::flat) : motions_(motions), shape_(shape) {}
  bool next(toolpath::Command& out) override;

private:
  std::size_t motions_;
  JobShape shape_;
  std::size_t step_ = 0;   // position in the whole job (header, motions, trailer)
  std::size_t index_ = 0;  // command index
};

// Streams the job of `motions` motions as trace text, as make_job writes it: to `out`, or to a file
// at `path` (std::runtime_error when it cannot be written).
void write_job(std::ostream& out, std::size_t motions, JobShape shape);
void write_job(const std::string& path, std::size_t motions, JobShape shape);

}  // namespace bench
