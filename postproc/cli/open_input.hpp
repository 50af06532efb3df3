// Opens an input of `read`, `plot`, ...: a `.trace` stream or NC code read back by a controller
// model of the registry (`--dialect NAME`, machines/registry/). Implemented in cmd_read.cpp.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <string_view>

#include "machines/registry/controller.hpp"
#include "postproc/cli/cli.hpp"
#include "toolpath/source.hpp"

namespace postproc::cli {

// Throws UsageError for an unknown dialect, toolpath::InputError for an unreadable file. Warnings of
// a controller model go to `warnings` when the stream ends.
std::unique_ptr<toolpath::CommandSource> open_source(const std::string& path, const std::string& dialect,
                                                     std::ostream& warnings, const machines::ReadOptions& options = {});

// `--tool-table FILE`: the control's tool table, for the models that apply tool lengths (G43 H).
inline constexpr OptionSpec kToolTableOption{"--tool-table", "", true,
                                             "G-code input: the control's tool table (LinuxCNC format) for G43 H lengths"};
// The reading options the command line gives: the tool table; `read` also --nc-lines.
machines::ReadOptions read_options(const Arguments& args);

// "input format: trace, pikocnc, ...": the --dialect help of a subcommand, from the registry.
std::string dialect_help(std::string_view what);
// The --dialect help of `read` and `run`: the input format, trace by default.
std::string_view input_help();

}  // namespace postproc::cli
