#include "postproc/engine/structure.hpp"

#include "toolpath/value.hpp"

namespace postproc {
namespace {

using toolpath::iequals;
using toolpath::Value;

std::int64_t integer_of(const toolpath::Command& c, std::string_view name, std::int64_t fallback) {
  const Value* v = c.find(name);
  if (!v) return fallback;
  return v->kind == toolpath::ValueKind::Integer ? v->integer : static_cast<std::int64_t>(v->as_number());
}

}  // namespace

bool ProgramStructure::starts_body(const toolpath::Command& c) {
  return iequals(c.name, "@proc") || iequals(c.name, "@turn_proc");
}

bool ProgramStructure::calls_subroutine(const toolpath::Command& c) {
  return iequals(c.name, "@call_proc") || iequals(c.name, "@call_prms");
}

bool ProgramStructure::concerns(const toolpath::Command& c) {
  return calls_subroutine(c) || starts_body(c) || iequals(c.name, "@end_proc") || iequals(c.name, "@turn_endproc") ||
         iequals(c.name, "@loop") || iequals(c.name, "@end_loop");
}

void ProgramStructure::before(toolpath::Command& c) {
  if (calls_subroutine(c)) {
    if (procs_.empty()) job_labels_.insert(integer_of(c, "label", 0));
  } else if (starts_body(c)) {
    procs_.push_back(integer_of(c, "label", 0));
  } else if (iequals(c.name, "@end_proc") || iequals(c.name, "@turn_endproc")) {
    std::int64_t open = procs_.empty() ? 0 : procs_.back();
    if (!procs_.empty()) procs_.pop_back();
    if (!c.find("label")) c.set("label", Value::make_integer(open));
    if (!c.find("end_of_job")) c.set("end_of_job", Value::make_logical(job_labels_.count(integer_of(c, "label", 0)) > 0));
  } else if (iequals(c.name, "@loop")) {
    Loop l{integer_of(c, "label", 0), integer_of(c, "loop_level", static_cast<std::int64_t>(loops_.size()) + 1),
           integer_of(c, "loop_count", 1)};
    if (!c.find("loop_level")) c.set("loop_level", Value::make_integer(l.level));
    loops_.push_back(l);
  } else if (iequals(c.name, "@end_loop")) {
    Loop l = loops_.empty() ? Loop{} : loops_.back();
    if (!loops_.empty()) loops_.pop_back();
    if (!c.find("label")) c.set("label", Value::make_integer(l.label));
    if (!c.find("loop_level")) c.set("loop_level", Value::make_integer(l.level));
    if (!c.find("loop_count")) c.set("loop_count", Value::make_integer(l.count));
  }
}

}  // namespace postproc
