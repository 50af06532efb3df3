// Opens an input of `read`, `plot`, ...: a `.trace` stream or NC code read back by a controller
// model (`--dialect pikocnc`, `--dialect 2xaxiscnc`). Implemented in cmd_read.cpp.
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include "toolpath/source.hpp"

namespace postproc::cli {

// Throws UsageError for an unknown dialect, toolpath::InputError for an unreadable file. Warnings of
// a controller model go to `warnings` when the stream ends.
std::unique_ptr<toolpath::CommandSource> open_source(const std::string& path, const std::string& dialect,
                                                     std::ostream& warnings, bool nc_lines = false);

}  // namespace postproc::cli
