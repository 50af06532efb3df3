#include "prp/filters/drill_expansion.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace prp {
namespace {

// `file:line:column` of the cycle's name: a PRP line or a VMID <DrillCycle>'s GppName alike (a line
// number alone means nothing in an XML file that may be one long line).
std::string position(const toolpath::SourcePosition& where) {
  if (where.line == 0) return where.file;  // not from a file's text
  return fmt::format("{}:{}:{}", where.file, where.line, where.column);
}

}  // namespace

bool DrillExpansion::needed(const MachineParameters& params) {
  for (const Record* r : params.records("drill_type"))
    if (r->flag && !*r->flag) return true;
  return false;
}

bool DrillExpansion::next(toolpath::Command& out) {
  for (;;) {
    if (!pending_.empty()) {
      swap(out, pending_.front());
      pending_.pop_front();
      return true;
    }
    if (!input_.next(out)) return false;
    if (!out.is_stream_command()) return true;
    if (is(out, "@start_of_job")) {
      if (const toolpath::Value* v = out.find("job_name")) job_ = v->text;
    } else if (is(out, "@call_proc")) {
      if (const toolpath::Value* v = out.find("message")) job_ = v->text;
    } else if (is(out, "@drill")) {
      start_cycle(out);
      if (expanding_) continue;  // the cycle itself is not sent
    } else if (expanding_ && is(out, "@drill_point")) {
      expand_hole(out);
      continue;
    } else if (expanding_ && is(out, "@end_drill")) {
      expanding_ = false;
      continue;
    }
    return true;
  }
}

void DrillExpansion::start_cycle(const toolpath::Command& drill) {
  expanding_ = false;
  const toolpath::Value* type = drill.find("drill_type");
  if (!type) return;
  const Record* record = params_.drill_cycle(type->text);
  if (!record) {
    if (warn_) warn_(drill, fmt::format("drill_type `{}` is declared by no drill_type record of the PRP", type->text));
    return;
  }
  if (!record->flag || *record->flag) return;  // the machine (or the post) has the cycle

  const std::string where = fmt::format("drill cycle `{}` (base {}, declared at {}) of job `{}`", record->name,
                                        record->base, position(record->name_where), job_);
  if (record->base == "TAPPING" || record->base == "R_BORING")
    throw StreamError(drill, where + " is marked N, but it needs spindle reversal or a spindle stop, which "
                                     "cannot be written as plain moves");
  if (record->base == "NONE")
    throw StreamError(drill, where + " is marked N, but it has no base type (None): nothing says which moves "
                                     "it stands for");
  for (const char* level : {"drill_clearance_z", "drill_upper_z", "drill_lower_z"})
    if (!number(drill, level)) throw StreamError(drill, fmt::format("{}: the @drill has no {}", where, level));
  dwell_.reset();
  if (record->base == "F_DRILL" || record->base == "F_BORING") {
    const std::optional<std::string> dwell = dwell_parameter(*record);
    if (!dwell)
      throw StreamError(drill, where + " needs a dwell: its record must declare exactly one parameter whose name "
                                       "contains `delay` or `dwell`");
    dwell_ = number(drill, *dwell);
    if (!dwell_) throw StreamError(drill, fmt::format("{}: the @drill gives no value for `{}`", where, *dwell));
  }
  if (record->base == "PECK" && !(number(drill, "down_step").value_or(0) > 0))
    throw StreamError(drill, where + ": a peck cycle needs down_step > 0");
  drill_ = drill;
  base_ = record->base;
  expanding_ = true;
}

void DrillExpansion::expand_hole(const toolpath::Command& point) {
  const double clear = *number(drill_, "drill_clearance_z");
  const double upper = *number(drill_, "drill_upper_z");
  const double lower = *number(drill_, "drill_lower_z");
  const auto feed = number(drill_, "feed");
  const double x = number(point, "xpos").value_or(number(drill_, "xpos").value_or(0));
  const double y = number(point, "ypos").value_or(number(drill_, "ypos").value_or(0));

  auto move = [&](const char* name, double z, bool with_feed) {
    toolpath::Command c;
    make_motion(c, name, point, Eigen::Vector3d(x, y, z), with_feed ? feed : std::nullopt);
    pending_.push_back(std::move(c));
  };
  auto dwell = [&] {
    toolpath::Command c;
    c.name = "@delay";
    c.index = point.index;
    c.line = point.line;
    c.parameters.push_back({"delay_period", toolpath::Value::make_numeric(*dwell_)});
    pending_.push_back(std::move(c));
  };

  move("@rapid_move", clear, false);
  move("@rapid_move", upper, false);
  if (base_ == "PECK") {
    const double step = *number(drill_, "down_step");
    const double depth = upper - lower;
    auto steps = number(drill_, "num_down_steps");
    const int n = std::max(1, steps ? static_cast<int>(std::lround(*steps)) : static_cast<int>(std::ceil(depth / step - 1e-9)));
    double previous = upper;
    for (int k = 1; k <= n; ++k) {
      const double level = k == n ? lower : std::max(lower, upper - k * step);
      if (k > 1) move("@rapid_move", previous, false);
      move("@line", level, true);
      move("@rapid_move", upper, false);
      previous = level;
    }
  } else {
    move("@line", lower, true);
    if (dwell_) dwell();
    if (base_ == "BORING" || base_ == "F_BORING") move("@line", upper, true);
    else move("@rapid_move", upper, false);
  }
  move("@rapid_move", clear, false);
  pending_.back().trace = point.trace;
}

}  // namespace prp
