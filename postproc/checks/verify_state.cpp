// Machine-state checks of `postproc verify` (StateChecks in verify.hpp): what a program does that no
// machine should, whatever the toolpath says. Errors make scrap: a feed move with the spindle
// stopped, or at feed 0. Warnings are suspect: a rapid across X Y below the level the last plunge
// started from, a tool change with the tool still down there, cutter compensation switched on or off
// on an arc. A rotary axis turned beyond the travel the machine file (a VMID) gives it is scrap: the
// control stops with an overtravel alarm.
#include <fmt/format.h>

#include <algorithm>

#include "postproc/checks/verify.hpp"
#include "postproc/checks/verify_modeller.hpp"
#include "toolpath/value.hpp"

namespace postproc::verify {
namespace {

constexpr double kTolerance = 0.001;  // mm

}  // namespace

void StateChecks::find(toolpath::Severity severity, std::size_t line, std::string what) {
  for (Finding& f : findings_)
    if (f.what == what) {
      ++f.count;
      return;
    }
  findings_.push_back({severity, line, 1, std::move(what)});
}

bool StateChecks::any_error() const {
  return std::any_of(findings_.begin(), findings_.end(),
                     [](const Finding& f) { return f.severity == toolpath::Severity::Error; });
}

void StateChecks::rotary_travel(const toolpath::Command& c, std::size_t line) {
  static constexpr std::array<std::string_view, 3> kRotary = {"apos", "bpos", "cpos"};
  for (const prp::RotaryLimits& r : rotary_) {
    const std::optional<double> angle = c.number(kRotary[static_cast<std::size_t>(r.axis - 'A')]);
    if (!angle) continue;
    const double a = *angle;
    const bool below = a < r.min - kTolerance, above = a > r.max + kTolerance;
    if (below || above)
      find(toolpath::Severity::Error, line,
           fmt::format("{} turned past its {} limit {:g} (travel {:g} .. {:g} in the machine file): an overtravel alarm",
                       r.axis, below ? "lower" : "upper", below ? r.min : r.max, r.min, r.max));
  }
}

void StateChecks::command(const toolpath::Command& c, std::size_t line) {
  using toolpath::Severity;
  if (!rotary_.empty()) rotary_travel(c, line);
  if (is(c, "@start_tool")) spindle_on_ = true;
  if (is(c, "@stop_tool")) spindle_on_ = false;
  if (is(c, "@compensation")) compensation_changed_ = true;
  if (is(c, "@machine_move")) machine_moved_ = true;  // to a machine position (home): not placed here
  if (is(c, "@change_tool") && !machine_moved_ && plunge_from_ && position_.z() < *plunge_from_ - kTolerance)
    find(Severity::Warning, line,
         fmt::format("a tool change with the tool at Z{:.3f}, below Z{:.3f} where its last plunge started: no retract",
                     position_.z(), *plunge_from_));
  const bool rapid = is(c, "@rapid_move"), arc = is(c, "@arc"), feed = arc || is(c, "@line");
  if (!rapid && !feed) return;
  Eigen::Vector3d to = position_;
  static constexpr std::array<std::string_view, 3> kAxes = {"xpos", "ypos", "zpos"};
  for (int a = 0; a < 3; ++a)
    if (const toolpath::Value* v = c.find(kAxes[static_cast<std::size_t>(a)])) to[a] = v->as_number();
  if (feed && !planar_) {
    if (!spindle_on_) find(Severity::Error, line, "a feed move with the spindle stopped");
    if (const toolpath::Value* f = c.find(toolpath::ParamKey::feed); !f || f->as_number() <= 0)
      find(Severity::Error, line, "a feed move at feed 0: no F was given");
  }
  if (feed) {
    if (arc && compensation_changed_)
      find(Severity::Warning, line,
           "cutter compensation switched on or off on an arc (controls want a line for it: Fanuc alarm PS0034)");
    if (to.z() < position_.z() - kTolerance) plunge_from_ = position_.z();
  }
  if (rapid && plunge_from_ && (to.head<2>() - position_.head<2>()).norm() > kTolerance &&
      std::min(to.z(), position_.z()) < *plunge_from_ - kTolerance)
    find(Severity::Warning, line,
         fmt::format("a rapid across X Y at Z{:.3f}, below Z{:.3f} where the last plunge started",
                     std::min(to.z(), position_.z()), *plunge_from_));
  compensation_changed_ = machine_moved_ = false;
  position_ = to;
}

}  // namespace postproc::verify
