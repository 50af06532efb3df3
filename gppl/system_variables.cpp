// Defaults follow spec 12.2's recommendation: the manual's example values, skipline TRUE,
// gcode_space FALSE, and '' (format not set: fall through to the defaults) for coordinate-set formats.
#include "gppl/system_variables.hpp"

namespace gppl {

namespace {

constexpr SystemVariable kSystem[] = {
    // passed from SolidCAM (12.1)
    {"gcode", Type::Integer, false, "", 0},
    {"mcode", Type::Integer, false, "", 0},
    {"rotated", Type::Logical, false, "", 0},
    {"mirrored", Type::Logical, false, "", 0},
    {"prev_command", Type::String, false, "", 0},
    {"current_command", Type::String, false, "", 0},
    {"next_command", Type::String, false, "", 0},
    {"first_user_proc", Type::Integer, false, "", 0},
    // output format and numbering (12.2)
    {"remove_blanks", Type::Logical, false, "", 0},
    {"gcode_space", Type::Logical, false, "", 0},
    {"gcode_f", Type::String, false, "2.0(p)", 0},
    {"mcode_f", Type::String, false, "2.0(p)", 0},
    {"numeric_def_f", Type::String, false, "5.3", 0},
    {"integer_def_f", Type::String, false, "5.0(p)", 0},
    {"xpos_f", Type::String, false, "5.3(p)", 0},
    {"ypos_f", Type::String, false, "5.3(p)", 0},
    {"zpos_f", Type::String, false, "5.3(p)", 0},
    {"apos_f", Type::String, false, "5.3(p)", 0},
    {"feed_f", Type::String, false, "4.0(p)", 0},
    {"xlpos_f", Type::String, false, "", 0},
    {"ylpos_f", Type::String, false, "", 0},
    {"zlpos_f", Type::String, false, "", 0},
    {"xhpos_f", Type::String, false, "", 0},
    {"yhpos_f", Type::String, false, "", 0},
    {"zhpos_f", Type::String, false, "", 0},
    {"xmpos_f", Type::String, false, "", 0},
    {"ympos_f", Type::String, false, "", 0},
    {"zmpos_f", Type::String, false, "", 0},
    {"xtpos_f", Type::String, false, "", 0},
    {"ytpos_f", Type::String, false, "", 0},
    {"ztpos_f", Type::String, false, "", 0},
    {"xopos_f", Type::String, false, "", 0},
    {"yopos_f", Type::String, false, "", 0},
    {"zopos_f", Type::String, false, "", 0},
    {"xtopos_f", Type::String, false, "", 0},
    {"ytopos_f", Type::String, false, "", 0},
    {"ztopos_f", Type::String, false, "", 0},
    {"end_block_text", Type::String, false, "", 0},
    {"blknum_letter", Type::String, false, "N", 0},
    {"blknum_exist", Type::Logical, false, "", 1},
    {"blknum_gen", Type::Logical, false, "", 0},
    {"blknum_f", Type::String, false, "5.0(p)", 0},
    {"blknum", Type::Integer, false, "", 5},
    {"blknum_delta", Type::Integer, false, "", 5},
    {"blknum_max", Type::Integer, false, "", 32000},
    {"skipline", Type::Logical, false, "", 1},
    {"num_user_procs", Type::Integer, false, "", 1},
    {"print_file_size", Type::Integer, false, "", 0},  // 1: the engine replaces `$$file_size$$`
    {"clear_change_after_gen", Type::Logical, false, "", 0},
    // special and read-only (12.3)
    {"PI", Type::Numeric, true, "", 3.14159265358979323846},
    {"TRUE", Type::Logical, true, "", 1},
    {"FALSE", Type::Logical, true, "", 0},
    {"inch_system", Type::Logical, true, "", 0},
};

}  // namespace

std::span<const SystemVariable> system_variables() { return kSystem; }

}  // namespace gppl
