// The variables the engine declares to the GPPL compiler: every documented command parameter, the
// enumeration constants (read-only integers), and the PRP's external variables.
#pragma once

#include <vector>

#include "gppl/gppl.hpp"
#include "postproc/engine/enumerations.hpp"
#include "prp/prp.hpp"
#include "toolpath/source.hpp"

namespace postproc {

std::vector<gppl::HostVariable> host_variables(const Enumerations& enums, const prp::MachineParameters& machine);

// Every parameter name the job carries (SolidCAM writes the machine's user parameters into the
// trace), typed by its first value (an enumeration word as an integer code, as a run assigns it).
// `postproc check --job` declares them: a post that reads them is then as defined as in a run.
std::vector<gppl::HostVariable> job_variables(toolpath::CommandSource& job);

}  // namespace postproc
