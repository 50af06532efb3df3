// The names of the toolpath commands a job may send (gpptool-commands.md, and those SolidCAM's own
// traces show besides), so that a post's procedure of another name is known to be the post's own.
#pragma once

#include <span>
#include <string_view>

namespace postproc {

// Every command name, lower case, "@absolute_mode" .. "@wc_program_plane".
std::span<const std::string_view> stream_command_names();
// True for a command a job may send (case-insensitive), and for @init_post / @init_inc, which the
// engine runs itself.
bool is_stream_command_name(std::string_view name);
// The motion commands whose absence from a post loses moves: @rapid_move, @line, @arc.
bool is_basic_motion(std::string_view name);
// Commands that only inform (the tool list, planes, matrices, homes, messages): many posts have no
// procedure for them, and nothing is lost when one has none.
bool is_informational(std::string_view name);

}  // namespace postproc
