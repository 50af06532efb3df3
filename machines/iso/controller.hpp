// The ISO-family models in the registry (machines/registry/controller.hpp): fanuc (aliases haas,
// 0i), linuxcnc (pocketnc), mach3 (mach4), grbl. One reader, the dialects' differences as Rules.
#pragma once

#include "machines/registry/controller.hpp"

namespace iso {

const machines::Controller& fanuc();
const machines::Controller& linuxcnc();
const machines::Controller& mach3();
const machines::Controller& grbl();

}  // namespace iso
