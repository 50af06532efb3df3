// The Sinumerik 828D/840D model in the registry (machines/registry/controller.hpp): name sinumerik
// (aliases 828d, 840d).
#pragma once

#include "machines/registry/controller.hpp"

namespace sinumerik {

const machines::Controller& controller();

}  // namespace sinumerik
