// The 2XAxisCNC model in the registry (machines/registry/controller.hpp): name 2xaxiscnc.
#pragma once

#include "machines/registry/controller.hpp"

namespace twoaxis {

const machines::Controller& controller();

}  // namespace twoaxis
