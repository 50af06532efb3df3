// The PikoCNC controller model in the registry (machines/registry/controller.hpp): names pikocnc,
// pikocnc-2025 and pikocnc-2016 (the dialect the program is written in).
#pragma once

#include "machines/registry/controller.hpp"

namespace pikocnc {

const machines::Controller& controller();

}  // namespace pikocnc
