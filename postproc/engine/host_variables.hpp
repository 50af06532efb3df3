// The variables the engine declares to the GPPL compiler: every documented command parameter, the
// enumeration constants (read-only integers), and the PRP's external variables.
#pragma once

#include <vector>

#include "gppl/gppl.hpp"
#include "postproc/engine/enumerations.hpp"
#include "prp/prp.hpp"

namespace postproc {

std::vector<gppl::HostVariable> host_variables(const Enumerations& enums, const prp::MachineParameters& machine);

}  // namespace postproc
