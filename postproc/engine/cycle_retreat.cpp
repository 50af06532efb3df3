#include "postproc/engine/cycle_retreat.hpp"

namespace postproc {

using toolpath::iequals;

CycleRetreat::CycleRetreat(const prp::MachineParameters& machine)
    : rough_(machine.logical("rough_retreat")),
      semi_finish_(machine.logical("semi_finish_retreat")),
      finish_(machine.logical("finish_retreat")) {}

namespace {

bool flag(const toolpath::Command& c, std::string_view name) {
  const toolpath::Value* v = c.find(name);
  if (!v) return false;
  if (v->kind == toolpath::ValueKind::Logical) return v->logical;
  return v->as_number() != 0;
}

}  // namespace

std::optional<CycleRetreat::Point> CycleRetreat::after(const toolpath::Command& command, std::string_view next,
                                                       const Point& where) {
  if (iequals(command.name, "@turn_endproc")) {
    std::optional<Point> done = pending_;
    pending_.reset();
    return done;
  }
  if (!iequals(command.name, "@turning")) return std::nullopt;
  // The pass that ends the cycle decides: a finish pass (PROFILE, or a combined cycle with its
  // finish), else a semi-finish pass, else the rough passes.
  const toolpath::Value* work = command.find("work_type");
  bool back_to_start = rough_;
  if ((work && iequals(work->text, "PROFILE")) || flag(command, "finish")) back_to_start = finish_;
  else if (flag(command, "semi_finish")) back_to_start = semi_finish_;
  Point end = where;
  if (!back_to_start) {
    const toolpath::Value* x = command.find("last_pos_x");
    const toolpath::Value* z = command.find("last_pos_z");
    if (!x || !z) return std::nullopt;  // no last point given: nothing better than the stream's own
    end.x = x->as_number();
    end.z = z->as_number();
  }
  if (iequals(next, "@turn_proc")) {
    pending_ = end;
    return std::nullopt;
  }
  return end;
}

}  // namespace postproc
