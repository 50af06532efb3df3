// Every controller model the tool knows, looked up by any of its names (case-insensitive). The CLI,
// `verify` and `plot` go through here: no controller is named anywhere else.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "machines/registry/controller.hpp"

namespace machines {

std::span<const Controller* const> controllers();
// nullptr when no controller has that name.
const Controller* find_controller(std::string_view name);
// The controller an NC file is read with when none is named (`plot prog.nc`).
const Controller& default_controller();
// "pikocnc, pikocnc-2016, pikocnc-2025, 2xaxiscnc": every name, for messages and help.
std::string controller_names();

}  // namespace machines
