#include "postproc/engine/command_names.hpp"

#include <array>

#include "toolpath/value.hpp"

namespace postproc {
namespace {

constexpr std::array<std::string_view, 105> kNames = {
    // gpptool-commands.md
    "@absolute_mode", "@arc", "@arc4x_cartesian", "@arc4x_polar", "@arc_5x", "@call_prms", "@call_proc",
    "@change_ref_point", "@change_tool", "@change_wire", "@chng_tool_cnext", "@compensation", "@def_tool",
    "@def_turn_tool", "@delay", "@drill", "@drill4x_cartesian", "@drill4x_pnt", "@drill4x_polar", "@drill_point",
    "@end_drill", "@end_job_procs", "@end_loop", "@end_of_file", "@end_of_job", "@end_proc", "@end_program",
    "@feed_spin", "@fourth_axis", "@groove", "@home_data", "@home_number", "@init_cpos", "@line",
    "@line4x_cartesian", "@line4x_dir", "@line4x_polar", "@line_4x", "@line_5x", "@line_on", "@loop",
    "@m_feed_spin", "@machine_plane", "@message", "@mirror", "@move4x_cartesian", "@move4x_dir", "@move4x_polar",
    "@move_4x", "@move_5x", "@proc", "@rapid_move", "@relative_mode", "@rotary_info", "@rotate",
    "@rotate_to_plane", "@start_of_file", "@start_of_job", "@start_program", "@start_tool", "@stop_tool",
    "@thread", "@tmatrix", "@tool_path_info", "@turn_change_tool", "@turn_drill", "@turn_endproc",
    "@turn_opt_parms", "@turn_proc", "@turning", "@wc_abs_rel", "@wc_arc", "@wc_chng_condition",
    "@wc_chng_e_group", "@wc_cut_wire", "@wc_finish_info", "@wc_g49_arc", "@wc_insert_wire", "@wc_line",
    "@wc_move", "@wc_program_plane",
    // what SolidCAM's level-5 traces send besides (the AG_BIG_SABET job of catinrage/achar)
    "@job_plane", "@offset_change", "@setup", "@tool_breakage", "@vmid_info",
    // procedures SolidCAM's own Siemens posts define for commands the manual does not list
    "@arc_yz", "@arc_zx", "@loop_matrix_info", "@transform_info",
    // named by the manual's example posts (gpptool-commands.md 15) and defined by real wire posts
    // (Chmer.gpp, SODICK.GPP of majeretft/Cam-posts) for the engine to call
    "@assign_axis", "@end_cartesian", "@job_info", "@programming_mode", "@round_comp", "@start_cartesian",
    "@wc_angle_status", "@wc_chng_tool", "@wc_info", "@wc_pos", "@wc_pos_pnt",
    // run by the engine itself
    "@init_inc", "@init_post",
    // the controller models' streams (postproc read --dialect)
    "@halt_program", "@marker"};

}  // namespace

std::span<const std::string_view> stream_command_names() { return kNames; }

bool is_stream_command_name(std::string_view name) {
  for (std::string_view n : kNames)
    if (toolpath::iequals(n, name)) return true;
  return false;
}

bool is_basic_motion(std::string_view name) {
  return toolpath::iequals(name, "@rapid_move") || toolpath::iequals(name, "@line") || toolpath::iequals(name, "@arc");
}

bool is_informational(std::string_view name) {
  static constexpr std::array<std::string_view, 20> kInformational = {
      "@def_tool", "@def_turn_tool", "@home_data", "@home_number", "@init_cpos", "@job_info", "@job_plane",
      "@machine_plane", "@message", "@offset_change", "@rotary_info", "@setup", "@tmatrix", "@tool_breakage",
      "@tool_path_info", "@vmid_info", "@wc_abs_rel", "@wc_angle_status", "@wc_info", "@wc_program_plane"};
  for (std::string_view n : kInformational)
    if (toolpath::iequals(n, name)) return true;
  return false;
}

}  // namespace postproc
