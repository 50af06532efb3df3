#include "prp/filters/structure_check.hpp"

#include <fmt/format.h>

#include "prp/filters/motion.hpp"

namespace prp {

namespace {

using K = CommandKind;
// The only commands check() looks at.
constexpr KindSet kChecked = bit(K::call_proc) | bit(K::call_prms) | bit(K::loop) | bit(K::rotate) | bit(K::mirror) |
                             bit(K::change_ref_point) | bit(K::compensation) | bit(K::proc) |
                             bit(K::start_of_file) | bit(K::home_number) | bit(K::turning) | bit(K::groove);

}  // namespace

// With the tool changes (@change_tool, and @start_tool among the others) that may lack a direction.
StructureCheck::StructureCheck(const MachineParameters& p, WarningSink warn)
    : CommandStep(kChecked | bit(K::change_tool) | bit(K::other)),
      warn_(std::move(warn)),
      gen_procs_(p.text("gen_procs")),
      procs_off_(toolpath::iequals(gen_procs_, "N")),
      calls_with_parameters_(toolpath::iequals(gen_procs_, "D")),
      loop_exist_(p.logical("loop_exist")),
      rotate_(p.logical("rotate")),
      mirror_(p.logical("mirror")),
      software_transform_(p.logical("software_transform")),
      comp_exist_(p.logical("comp_exist")),
      wire_cut_(p.has("machine_type") && toolpath::iequals(p.text("machine_type"), "WIRE_CUT")),
      turning_cycle_(p.logical("turning_cycle")),
      groove_cycle_(p.logical("groove_cycle")),
      programs_(program_numbers(p)),
      procedures_(procedure_numbers(p)) {
  if (p.has("num_homes")) num_homes_ = p.integer("num_homes");
}

void StructureCheck::apply(toolpath::Command& c, CommandKind& kind) {
  if (has(kChecked, kind)) check(c, kind);
  // SolidCAM always says which way the tool turns; a hand-made job that does not (the manual's
  // example job) means the usual CW, which posts test with `tool_direction eq CW`.
  if ((kind == K::change_tool || (kind == K::other && toolpath::iequals(c.name, "@start_tool"))) &&
      !c.find(toolpath::ParamKey::tool_direction))
    c.set(toolpath::ParamKey::tool_direction, toolpath::Value::make_enum("CW"));
}

void StructureCheck::check(const toolpath::Command& c, CommandKind kind) {
  // Each kind of mismatch is reported once, at its first command: a trace repeats them.
  auto warn = [&](const std::string& message) {
    if (warn_ && warned_.insert(c.name).second) warn_(c, message);
  };
  switch (kind) {
    // A wire machine runs each pass of a contour as a call of its subroutine, whatever gen_procs says:
    // Chmer.vmid (GenProc 0) and SODICK.PRP (gen_procs = Y) both come with posts built on @call_prms.
    case K::call_proc:
      if (procs_off_ && !wire_cut_) warn("@call_proc although the PRP says gen_procs = N");
      break;
    case K::call_prms:
      if (!calls_with_parameters_ && !wire_cut_)
        warn(fmt::format("@call_prms although the PRP says gen_procs = {} (only D calls with parameters)", gen_procs_));
      break;
    case K::loop:
      if (!loop_exist_) warn("@loop although the PRP says loop_exist = N");
      break;
    case K::rotate:
      if (!rotate_) warn("@rotate although the PRP says rotate = N");
      break;
    case K::mirror:
      if (!mirror_) warn("@mirror although the PRP says mirror = N");
      break;
    case K::turning:
      if (!turning_cycle_) warn("@turning although the PRP says turning_cycle = N (the control has no turning cycle)");
      break;
    case K::groove:
      if (!groove_cycle_) warn("@groove although the PRP says groove_cycle = N (the control has no grooving cycle)");
      break;
    default: break;
  }
  if (software_transform_ && (kind == K::loop || kind == K::rotate || kind == K::mirror || kind == K::change_ref_point))
    warn(fmt::format("{} although the PRP says software_transform = Y", c.name));

  if (kind == K::compensation && !comp_exist_) {
    if (const toolpath::Value* side = c.find("side"); side && !toolpath::iequals(side->text, "COMP_OFF"))
      throw StreamError(c, fmt::format("compensation {} on a machine without it (comp_exist = N)", side->text));
  }
  if (kind == K::proc || kind == K::call_proc || kind == K::call_prms) {
    if (auto label = number(c, "label"); label && !procedures_.contains(static_cast<std::int64_t>(*label)))
      throw StreamError(c, fmt::format("procedure label {} is outside proc_num_min .. proc_num_max ({} .. {})",
                                       *label, procedures_.min.value_or(0), procedures_.max.value_or(0)));
  }
  // SolidCAM asks for a number within the range; a job made for another machine keeps its own, posted
  // as it is (an error here only stopped real posts on our sample jobs).
  if (kind == K::start_of_file) {
    if (auto n = number(c, "program_number"); n && !programs_.contains(static_cast<std::int64_t>(*n)))
      warn(fmt::format("program number {} is outside prog_num_min .. prog_num_max ({} .. {}); posted as it is", *n,
                       programs_.min.value_or(0), programs_.max.value_or(0)));
  }
  if (kind == K::home_number && num_homes_) {
    if (auto h = number(c, "home_number"); h && *h > static_cast<double>(*num_homes_))
      warn(fmt::format("home_number {} is above num_homes {}", *h, *num_homes_));
  }
}

DefaultPositions::DefaultPositions(const MachineParameters& p)
    : CommandStep(bit(CommandKind::start_program) | bit(CommandKind::end_program)) {
  if (p.has("dflt_start")) start_ = p.point("dflt_start");
  if (p.has("dflt_end")) end_ = p.point("dflt_end");
}

void DefaultPositions::apply(toolpath::Command& c, CommandKind& kind) {
  if (c.find("xpos") || c.find("ypos") || c.find("zpos")) return;
  if (start_ && kind == CommandKind::start_program) set_point(c, *start_);
  if (end_ && kind == CommandKind::end_program) set_point(c, *end_);
}

}  // namespace prp
