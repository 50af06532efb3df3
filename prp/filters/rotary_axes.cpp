#include "prp/filters/rotary_axes.hpp"

#include <cmath>

#include <fmt/format.h>

#include "prp/filters/motion.hpp"

namespace prp {

using K = CommandKind;

namespace {

constexpr KindSet kFourAxisCuts = bit(K::line_4x) | bit(K::line4x_cartesian) | bit(K::line4x_polar) |
                                  bit(K::line4x_dir) | bit(K::arc4x_cartesian) | bit(K::arc4x_polar);
constexpr KindSet kFourAxis = kFourAxisCuts | bit(K::move_4x) | bit(K::move4x_cartesian) | bit(K::move4x_polar) |
                              bit(K::move4x_dir);
constexpr KindSet kFiveAxisCuts = bit(K::line_5x) | bit(K::arc_5x);

}  // namespace

RotaryAxes::RotaryAxes(const MachineParameters& params, WarningSink warn)
    : CommandStep(kFourAxis | kFiveAxisCuts | bit(K::move_5x)),
      warn_(std::move(warn)),
      set_dir_(params.logical("set_dir")),
      positive_only_(params.logical("positive_4x_dir_only")),
      angle_limit_(params.numeric("angle_change_limit")) {}

void RotaryAxes::apply(toolpath::Command& c, CommandKind& kind) {
  if (has(kFourAxis, kind)) four_axis(c, kind);
  else five_axis(c, kind);
}

void RotaryAxes::warn_once(const toolpath::Command& c, const std::string& key, const std::string& message) {
  if (warn_ && warned_.insert(key).second) warn_(c, message);
}

void RotaryAxes::four_axis(toolpath::Command& c, CommandKind& kind) {
  const std::optional<double> c_now = number(c, toolpath::ParamKey::cpos);
  if (!c_now) return;
  const bool known = c_.has_value();          // the first C has no change
  const double change = known ? *c_now - *c_ : 0.0;
  const toolpath::Value* dir = c.find("dir4x");
  if (positive_only_ && has(kFourAxisCuts, kind)) {
    const bool back = dir ? toolpath::iequals(dir->text, "CW") : change < -1e-9;
    if (back)
      warn_once(c, "positive_4x_dir_only",
                fmt::format("{} turns C back{} although the PRP says positive_4x_dir_only = Y: SolidCAM computes such "
                            "cuts turning forward only",
                            c.name, known && !dir ? fmt::format(" by {:g} degrees", -change) : std::string()));
  }
  if (set_dir_ && !dir && (kind == K::move_4x || kind == K::line_4x)) {
    double normalised = std::fmod(*c_now, 360.0);
    if (normalised < 0) normalised += 360.0;
    if (std::abs(normalised - 360.0) < 1e-9) normalised = 0;
    c.name = kind == K::move_4x ? "@move4x_dir" : "@line4x_dir";
    kind = kind == K::move_4x ? K::move4x_dir : K::line4x_dir;
    set_number(c, toolpath::ParamKey::cpos, normalised);
    set_number(c, "dc", change);
    c.set("dir4x", toolpath::Value::make_enum(change < 0 ? "CW" : "CCW"));
  }
  c_ = *c_now;
}

void RotaryAxes::five_axis(const toolpath::Command& c, CommandKind kind) {
  const std::optional<double> a = number(c, toolpath::ParamKey::apos), b = number(c, toolpath::ParamKey::bpos);
  if (has(kFiveAxisCuts, kind) && angle_limit_ > 0) {
    for (const auto& [now, before, axis] : {std::tuple{a, a_, "A"}, std::tuple{b, b_, "B"}}) {
      if (!now || !before || std::abs(*now - *before) <= angle_limit_) continue;
      warn_once(c, "angle_change_limit",
                fmt::format("{} turns {} by {:g} degrees within a cut, more than angle_change_limit = {:g}: SolidCAM "
                            "retracts out of the cut for such a change, this stream does not",
                            c.name, axis, std::abs(*now - *before), angle_limit_));
    }
  }
  if (a) a_ = a;
  if (b) b_ = b;
}

}  // namespace prp
