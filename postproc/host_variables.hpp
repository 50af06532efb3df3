// The variables the engine declares to the GPPL compiler: every documented command parameter, the
// enumeration constants (read-only integers), and the drill-cycle parameters the PRP declares.
#pragma once

#include <vector>

#include "gppl/gppl.hpp"
#include "postproc/enumerations.hpp"
#include "postproc/prp_settings.hpp"

namespace postproc {

std::vector<gppl::HostVariable> host_variables(const Enumerations& enums, const PrpSettings& prp);

}  // namespace postproc
