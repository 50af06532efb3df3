#include "prp/params/catalogue.hpp"

#include <array>

#include "toolpath/value.hpp"

namespace prp {
namespace {

using K = ValueKind;
using sv = std::string_view;

constexpr std::array<sv, 16> kLanguages{"CHINESE", "CZECH",  "DANISH",  "ENGLISH", "FRENCH",  "GERMAN",
                                        "HEBREW",  "HUNGARIAN", "ITALIAN", "JAPANESE", "KOREAN", "POLISH",
                                        "PORTUGUESE", "RUSSIAN", "SPANISH", "TURKISH"};
constexpr std::array<sv, 3> kMachineTypes{"MILLING", "TURNING", "WIRE_CUT"};
constexpr std::array<sv, 4> kPlanes{"XY", "YZ", "ZX", "ZC"};
constexpr std::array<sv, 2> kXY{"X", "Y"};
constexpr std::array<sv, 3> kXYZ{"X", "Y", "Z"};
constexpr std::array<sv, 6> kRotaryAxes{"ZYX", "ZY", "ZX", "YX", "XY", "XZ"};
constexpr std::array<sv, 2> kDirections{"CW", "CCW"};
constexpr std::array<sv, 4> kGenProcs{"Y", "N", "C", "D"};

constexpr std::span<const sv> none{};

// Spec section 2 (124 keys) and 2.22; defaults from section 3.0 and from the source where stated.
const KeyInfo kKeys[] = {
    // 2.1 internal
    {"machine_type", K::Enumeration, kMachineTypes, true, ""},
    {"post_processor", K::String, none, false, ""},
    {"doc_processor", K::String, none, false, ""},
    {"gpp_file_ext", K::String, none, false, ""},
    {"tool_table_name", K::String, none, false, ""},
    {"max_g_name_length", K::Integer, none, false, "0"},
    {"default_lang", K::Enumeration, kLanguages, true, ""},
    {"dir_gcode", K::String, none, false, ""},
    {"split_gcode_folders", K::Logical, none, false, "N"},
    {"gcode_part_subfolder", K::Logical, none, false, "N"},
    // 2.2 machine initialisation
    {"machine_plane", K::Enumeration, kPlanes, false, "XY"},
    {"abs_coord", K::Logical, none, false, "Y"},
    {"rotate", K::Logical, none, false, "Y"},
    {"mirror", K::Logical, none, false, "Y"},
    {"relative_gcode", K::Logical, none, false, "N"},
    {"_4th_axes_around", K::Enumeration, kXY, false, ""},
    {"first_rotation_angle", K::Enumeration, kXYZ, false, ""},
    {"_5th_axes_around", K::Enumeration, kXYZ, false, ""},
    {"_5x_rotary_axes", K::Enumeration, kRotaryAxes, false, "ZYX"},
    {"direction_4x", K::Enumeration, kDirections, false, ""},
    {"tilt_axis_dir", K::Enumeration, kDirections, false, "CCW"},
    {"positive_4x_dir_only", K::Logical, none, false, "N"},
    {"tilt_axis_dir_CW_CCW", K::Logical, none, false, "N"},
    {"pos_to_coord", K::Logical, none, false, "N"},
    {"pos_to_machine", K::Logical, none, false, "N"},
    {"iMachine_DB_name", K::String, none, false, ""},
    // 2.3 program numbers
    {"prog_num_min", K::Integer, none, false, ""},
    {"prog_num_max", K::Integer, none, false, ""},
    {"prog_num_dflt", K::Integer, none, false, ""},
    {"get_prog_num", K::Logical, none, false, "Y"},
    {"proc_num_min", K::Integer, none, false, ""},
    {"proc_num_max", K::Integer, none, false, ""},
    {"proc_num_dflt", K::Integer, none, false, ""},
    {"get_proc_num", K::Logical, none, false, "Y"},
    // 2.4 procedures
    {"full_gcode", K::Logical, none, false, "N"},
    {"gen_procs", K::Enumeration, kGenProcs, false, "N"},
    {"drill_proc", K::Logical, none, false, "N"},
    {"turn_proc", K::Logical, none, false, "N"},
    {"gen_internal_proc", K::Logical, none, false, "N"},
    {"turn_common_proc", K::Logical, none, false, "N"},
    {"gen_1_line_proc", K::Logical, none, false, "Y"},
    {"optimize_jobs_loop", K::Logical, none, false, "N"},
    {"seq_sub_number", K::Logical, none, false, "N"},
    {"loop_exist", K::Logical, none, false, "Y"},
    {"same_sub_numbers", K::Logical, none, false, "N"},
    {"init_var_after_split", K::Logical, none, false, "N"},
    {"software_transform", K::Logical, none, false, "N"},
    {"software_transform4x", K::Logical, none, false, "N"},
    // 2.5 home
    {"num_homes", K::Integer, none, false, ""},
    {"home_data_at_start", K::Logical, none, false, "N"},
    // 2.6 positioning
    {"dflt_start", K::Point, none, false, ""},
    {"dflt_end", K::Point, none, false, ""},
    // 2.7 compensation
    {"comp_exist", K::Logical, none, false, "Y"},
    {"comp_arc_arc", K::Logical, none, false, "Y"},
    {"comp_arc_line", K::Logical, none, false, "Y"},
    {"comp_line_line", K::Logical, none, false, "Y"},
    {"comp_x_start", K::Logical, none, false, "N"},
    {"comp_by_arcs", K::Logical, none, false, "N"},
    {"Delta_for_TOOL_H", K::Integer, none, false, ""},
    {"comp_by_zero_tool", K::Logical, none, false, "N"},
    {"BS_tools_off_delta", K::Integer, none, false, ""},
    // 2.8 arcs
    {"arc_exist", K::Logical, none, false, "Y"},
    {"arc_3d", K::Logical, none, false, "Y"},
    {"arc_quadrants", K::Logical, none, false, "N"},
    {"arc_gt_180", K::Logical, none, false, "Y"},
    {"arc_max_chord", K::Number, none, false, "30.0000, 1.1811"},
    {"arc_max_angle", K::Number, none, false, "10.0000"},
    {"arc_max_deviation", K::Number, none, false, ""},  // ours: chordal tolerance of linearised arcs
    {"arc_max_radius", K::Number, none, false, ""},
    {"arc_3d_4x", K::Logical, none, false, "Y"},
    {"arc_min_length", K::Number, none, false, "0"},
    {"arc_zx_yz", K::Logical, none, false, "Y"},
    {"arc_in_main_planes", K::Logical, none, false, "Y"},
    {"arc_5x", K::Logical, none, false, "Y"},
    // 2.9 epsilons and precision
    {"eps_angle", K::Number, none, false, "0"},
    {"eps_line", K::Number, none, false, "0"},
    {"zero_value", K::Number, none, false, "0"},
    {"min_delt_arc_rad", K::Number, none, false, ""},
    {"safety_dist", K::Number, none, false, ""},
    {"feed_precision", K::Integer, none, false, ""},
    {"movement_precision", K::Number, none, false, ""},  // the example writes a step (spec 3.1)
    {"spin_precision", K::Integer, none, false, ""},
    // 2.10 feed and spindle
    {"spin_direction", K::Enumeration, kDirections, false, ""},
    {"rapid_feed", K::Number, none, false, ""},
    {"acceleration", K::Number, none, false, ""},
    // 2.11 timing
    {"time_factor", K::Number, none, false, "1"},
    {"block_time", K::Number, none, false, "0"},
    {"change_tool_time", K::Number, none, false, "0"},
    {"calc_job_time", K::Logical, none, false, "N"},
    // 2.12-2.15, 2.18 records
    {"options", K::Record, none, false, ""},
    {"job_opt_type", K::Record, none, false, ""},
    {"drill_type", K::Record, none, false, ""},
    {"turn_type", K::Record, none, false, ""},
    {"thread_type", K::Record, none, false, ""},
    {"groove_type", K::Record, none, false, ""},
    {"wc_pos_type", K::Record, none, false, ""},
    {"wc_macro", K::Record, none, false, ""},
    // 2.16 turning
    {"turning_cycle", K::Logical, none, false, "Y"},
    {"groove_cycle", K::Logical, none, false, "Y"},
    {"combined_cycles", K::Logical, none, false, "N"},
    {"rough_retreat", K::Logical, none, false, "N"},
    {"finish_retreat", K::Logical, none, false, "N"},
    {"semi_finish_retreat", K::Logical, none, false, "N"},
    {"fanuc_cycle", K::Logical, none, false, "Y"},
    // 2.17 fourth axis
    {"set_dir", K::Logical, none, false, "N"},
    // 2.19 wire cut
    {"lower_guide_level", K::Number, none, false, ""},
    {"offset_group_name", K::String, none, false, ""},
    {"u_max", K::Number, none, false, ""},
    {"v_max", K::Number, none, false, ""},
    {"xy_abs", K::Logical, none, false, "Y"},
    {"uv_abs", K::Logical, none, false, "Y"},
    // 2.20 5-axis simulation
    {"auto_angle_pair", K::Logical, none, false, "Y"},
    {"other_angle_pair", K::Logical, none, false, "N"},
    {"angle_change_limit", K::Number, none, false, "150"},
    {"interplat_for_dist", K::Logical, none, false, "N"},
    {"interplat_distance", K::Number, none, false, "1, 0.05"},
    {"retract_distance", K::Number, none, false, "100, 4"},
    {"center_rot_prp_num", K::Integer, none, false, ""},
    {"enable_mx_edit", K::Logical, none, false, "N"},
    {"pole_angle_tolerance", K::Number, none, false, ""},
    {"use_machine_limits", K::Logical, none, false, "N"},
    {"use_tool_H_Length", K::Logical, none, false, "Y"},
    {"use_part_shifting", K::Logical, none, false, "Y"},
    {"use_rot_axis_base_point2", K::Logical, none, false, "Y"},
    {"GCode_part_coordinate", K::Logical, none, false, "Y"},
    // 2.22 used but undocumented
    {"interplat_angle_step", K::Number, none, false, ""},
    {"internal_line", K::Logical, none, false, "N"},
    {"init_cpos", K::Logical, none, false, "N"},
};

constexpr std::array<sv, 6> kLanguageRecordKeys{"options", "job_opt_type", "drill_type",
                                                "turn_type", "thread_type", "groove_type"};
constexpr std::array<sv, 16> kSuffixes{"chi", "cze", "dan", "eng", "fre", "ger", "heb", "hun",
                                       "ita", "jap", "kor", "pol", "por", "rus", "spa", "tur"};
// NONE: real posts declare cycles with no base type (`drill_type = G81_Macro None Y`); such a
// cycle cannot be expanded into moves.
constexpr std::array<sv, 8> kDrillBases{"DRILLING", "F_DRILL", "PECK", "TAPPING",
                                        "BORING", "R_BORING", "F_BORING", "NONE"};

}  // namespace

std::span<const KeyInfo> all_keys() { return kKeys; }

const KeyInfo* find_key(std::string_view key) {
  for (const auto& info : kKeys)
    if (toolpath::iequals(info.name, key)) return &info;
  return nullptr;
}

std::optional<std::string_view> record_base(std::string_view key, std::string_view& lang) {
  lang = {};
  if (const KeyInfo* info = find_key(key); info && info->kind == ValueKind::Record) return info->name;
  for (sv base : kLanguageRecordKeys) {
    if (key.size() != base.size() + 4 || key[base.size()] != '_') continue;
    if (!toolpath::iequals(key.substr(0, base.size()), base)) continue;
    sv suffix = key.substr(base.size() + 1);
    for (sv s : kSuffixes) {
      if (toolpath::iequals(suffix, s)) {
        lang = s;
        return base;
      }
    }
  }
  return std::nullopt;
}

std::optional<std::string_view> drill_base(std::string_view word) {
  for (sv base : kDrillBases)
    if (toolpath::iequals(base, word)) return base;
  return std::nullopt;
}

}  // namespace prp
