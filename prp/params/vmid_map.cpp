// The VMID -> PRP table. Element and attribute names are those MachineIdEditor writes (seen in
// public VMID files of several versions); each attribute maps to the PRP key of the same meaning.
// Attributes whose coding we could not establish (plane and direction codes) are left out.
#include "prp/params/vmid_map.hpp"

#include <array>

namespace prp {
namespace {

using V = VmidValue;

constexpr VmidAttribute kAttributes[] = {
    // <Machine>
    {"PostProcessor", "Name", "post_processor", V::Text},
    // <Controller>
    {"PrecisionDef", "MovementPrecision", "movement_precision", V::Number},
    {"PrecisionDef", "FeedPrecision", "feed_precision", V::Integer},
    {"PrecisionDef", "SpinPrecision", "spin_precision", V::Integer},
    {"ArcExecution", "SupportArcs", "arc_exist", V::Flag},
    {"ArcExecution", "SupportHelicalArcs", "arc_3d", V::Flag},
    {"ArcExecution", "Support4xHelicalArcs", "arc_3d_4x", V::Flag},
    {"ArcExecution", "Support90degArcs", "arc_quadrants", V::Flag},
    {"ArcExecution", "SupportGrt180degArcs", "arc_gt_180", V::Flag},
    {"ArcExecution", "SupportArcsZX_YZ", "arc_zx_yz", V::Flag},
    {"ArcExecution", "SupportOnlyArcsInMainPlanes", "arc_in_main_planes", V::Flag},
    {"ArcExecution", "MaxChordLength", "arc_max_chord", V::Length},
    {"ArcExecution", "MaxArcAngle", "arc_max_angle", V::Number},
    {"ArcExecution", "MaxArcRadius", "arc_max_radius", V::Length},
    {"ArcExecution", "MinArcLength", "arc_min_length", V::Length},
    {"ArcExecution", "MinArcAngle", "eps_angle", V::Number},
    {"ProgramNumbers", "MinProgramNumber", "prog_num_min", V::Integer},
    {"ProgramNumbers", "MaxProgramNumber", "prog_num_max", V::Integer},
    {"ProgramNumbers", "DefaultProgramNumber", "prog_num_dflt", V::Integer},
    {"ProgramNumbers", "MinProcedureNumber", "proc_num_min", V::Integer},
    {"ProgramNumbers", "MaxProcedureNumber", "proc_num_max", V::Integer},
    {"ProgramNumbers", "DefaultProcedureNumber", "proc_num_dflt", V::Integer},
    // The machine's kind: Chmer.vmid (majeretft/Cam-posts, a Makino wire machine) says 6 on <Machine>
    // and on its "Main WireEdm" combination; the milling VMIDs of catinrage/achar say 0.
    {"Machine", "OperationType", "machine_type", V::MachineType},
    {"CompensationDef", "Compensation", "comp_exist", V::Flag},
    {"CompensationDef", "MinDeltArcRad", "min_delt_arc_rad", V::Length},
    {"TurningDef", "TurningCycle", "turning_cycle", V::Flag},
    {"TurningDef", "GrooveCycle", "groove_cycle", V::Flag},
    {"TurningDef", "CombinedCycles", "combined_cycles", V::Flag},
    {"PosToMachNoParams", "TiltAxisDirCW_CCW", "tilt_axis_dir_CW_CCW", V::Flag},
    {"PosToMachNoParams", "Positive4xDirOnly", "positive_4x_dir_only", V::Flag},
    {"PosToMachNoParams", "Set_dir", "set_dir", V::Flag},
    {"PosToMachNoParams", "CenterRotMacNum", "center_rot_prp_num", V::Integer},
    {"PosToMachNoParams", "SoftwareTransform4x", "software_transform4x", V::Flag},
    // <WorkingStyle> (older files hold the sub0 attributes on WorkingStyle itself)
    {"WorkingStyle", "PosToMach", "pos_to_machine", V::Flag},
    {"WorkingStyle", "DppFile", "doc_processor", V::Text},
    {"WorkingStyle", "DeltaForToolH", "Delta_for_TOOL_H", V::Integer},
    {"WorkingStyle", "HomeDataAtStart", "home_data_at_start", V::Flag},
    {"WorkingStyle", "SafetyDist", "safety_dist", V::Length},
    {"WorkingStyle", "MachToolTableName", "tool_table_name", V::Text},
    {"WorkingStyle", "CompensationByZero", "comp_by_zero_tool", V::Flag},
    {"WorkingStyle", "FinishRetreat", "finish_retreat", V::Flag},
    {"WorkingStyle", "SemiFinishRetreat", "semi_finish_retreat", V::Flag},
    {"sub0", "CompensationByZero", "comp_by_zero_tool", V::Flag},
    {"sub0", "FinishRetreat", "finish_retreat", V::Flag},
    {"sub0", "SemiFinishRetreat", "semi_finish_retreat", V::Flag},
    {"sub0", "SoftwareTransform", "software_transform", V::Flag},
    {"GcodeOutput", "FileExtn", "gpp_file_ext", V::Text},
    {"GcodeOutput", "FileMaxLen", "max_g_name_length", V::Integer},
    {"GcodeOutput", "GcodeFolder", "dir_gcode", V::Text},
    {"GcodeOutput", "SepDirForeachGcodeFile", "split_gcode_folders", V::Flag},
    {"GcodeOutput", "SepDirForeachGcodePart", "gcode_part_subfolder", V::Flag},
    {"ProceduresDef", "GenProc", "gen_procs", V::GenProcs},
    {"ProceduresDef", "DrillProc", "drill_proc", V::Flag},
    {"ProceduresDef", "TurningProc", "turn_proc", V::Flag},
    {"ProceduresDef", "GenInternalProc", "gen_internal_proc", V::Flag},
    {"ProceduresDef", "TurnCommonPoc", "turn_common_proc", V::Flag},
    {"ProceduresDef", "GenSingleLineProc", "gen_1_line_proc", V::Flag},
    {"ProceduresDef", "OptimizeJobsLoop", "optimize_jobs_loop", V::Flag},
    {"ProceduresDef", "LoopExist", "loop_exist", V::Flag},
    {"ProceduresDef", "SameSubNumbers", "same_sub_numbers", V::Flag},
    {"ProceduresDef", "InitVarAfterSplit", "init_var_after_split", V::Flag},
    {"ProceduresDef", "SoftwareTransform", "software_transform", V::Flag},
    {"ProceduresDef", "SoftwareTransform4x", "software_transform4x", V::Flag},
    {"Sim5xOptions", "AutoAnglePair", "auto_angle_pair", V::Flag},
    {"Sim5xOptions", "OtherAnglePair", "other_angle_pair", V::Flag},
    {"Sim5xOptions", "UseToolH_Length", "use_tool_H_Length", V::Flag},
    {"Sim5xOptions", "UsePartShifting", "use_part_shifting", V::Flag},
    {"Sim5xOptions", "UseRotAxisBasePoint2", "use_rot_axis_base_point2", V::Flag},
    {"Sim5xOptions", "OutputGcodePartCoordinate", "GCode_part_coordinate", V::Flag},
    {"Sim5xOptions", "InterplatForDist", "interplat_for_dist", V::Flag},
    {"Sim5xOptions", "EnableMxEdit", "enable_mx_edit", V::Flag},
    {"Sim5xOptions", "UseMachineLimits", "use_machine_limits", V::Flag},
    {"Sim5xOptions", "RetractDistance", "retract_distance", V::Length},
    {"Sim5xOptions", "InterplatDistance", "interplat_distance", V::Length},
    {"Sim5xOptions", "AngleChangeLimit", "angle_change_limit", V::Number},
    {"Sim5xOptions", "InterplatAngleStep", "interplat_angle_step", V::Number},
    {"Sim5xOptions", "PoleAngleTolerance", "pole_angle_tolerance", V::Number},
    {"WireEdmDef", "AbsXY", "xy_abs", V::Flag},
    {"WireEdmDef", "AbsUV", "uv_abs", V::Flag},
    {"TimingDef", "TimeFactor", "time_factor", V::Number},
    {"TimingDef", "BlockTime", "block_time", V::Number},
};

// Drill base types in DrillType order: G81 is 0, G82 1, G83 2, G84 3 and G86 4 in real files, the
// order in which the manual lists the base types.
constexpr std::array<std::string_view, 7> kDrillBases{"DRILLING", "F_DRILL", "PECK", "TAPPING",
                                                      "BORING", "R_BORING", "F_BORING"};

}  // namespace

std::span<const VmidAttribute> vmid_attributes() { return kAttributes; }

ValueKind vmid_kind(VmidValue value) {
  switch (value) {
    case VmidValue::Flag: return ValueKind::Logical;
    case VmidValue::Integer: return ValueKind::Integer;
    case VmidValue::Number:
    case VmidValue::Length: return ValueKind::Number;
    case VmidValue::Text: return ValueKind::String;
    case VmidValue::GenProcs:
    case VmidValue::MachineType: return ValueKind::Enumeration;
  }
  return ValueKind::String;
}

std::optional<VarType> vmid_value_type(std::string_view value_type) {
  if (value_type == "1") return VarType::Logical;
  if (value_type == "2") return VarType::String;
  if (value_type == "3") return VarType::Numeric;
  if (value_type == "4" || value_type == "5") return VarType::Integer;
  return std::nullopt;
}

std::optional<std::string_view> vmid_drill_base(std::string_view drill_type) {
  if (drill_type.size() != 1 || drill_type[0] < '0' || drill_type[0] > '6') return std::nullopt;
  return kDrillBases[static_cast<std::size_t>(drill_type[0] - '0')];
}

}  // namespace prp
