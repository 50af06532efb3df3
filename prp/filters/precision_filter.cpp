#include "prp/filters/precision_filter.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "prp/filters/motion.hpp"

namespace prp {
namespace {

// The parameters the filter touches are the first CommandFields: lengths (rounded with the
// coordinates; the first three are the tool position), then the feed and the spindle speed.
using F = CommandFields;
constexpr int kFeed = F::feed, kSpin = F::spin, kParameters = kSpin + 1;
static_assert(F::xpos == 0 && F::ypos == 1 && F::zpos == 2, "the tool position comes first");

std::optional<DecimalGrid> grid_of(const std::optional<int>& digits) {
  if (!digits) return std::nullopt;
  return DecimalGrid(*digits);
}

}  // namespace

// Why a whole number v with |v| <= whole_limit_ rounds to itself (-0 to +0) under the general rule:
// 10^digits is a double exactly for 0 <= digits <= 22, and whole_limit_ * 10^digits <= 2^53, so
// v * 10^digits is a whole number of at most 2^53: a double, so the product is exact. Rounding a
// whole number changes nothing, and dividing it by 10^digits gives v exactly, a double, so the
// quotient is exact as well; the rule's last step makes -0 into +0. Any other value (a fraction,
// a larger number, inf, NaN, or digits < 0, where 10^digits is not a double) takes the general rule.
DecimalGrid::DecimalGrid(int digits) : scale_(std::pow(10.0, digits)), whole_limit_(-1.0) {
  if (digits < 0 || digits > 22) return;
  double exact = 1.0;
  std::uint64_t power = 1;  // 10^digits while it stays below 2^53, else 0
  for (int i = 0; i < digits; ++i) {
    exact *= 10.0;  // exact up to 10^22
    power = power != 0 && power * 10 <= (std::uint64_t{1} << 53) ? power * 10 : 0;
  }
  if (exact != scale_) return;  // pow() was not exact: no shortcut
  whole_limit_ = power == 0 ? 0.0 : static_cast<double>((std::uint64_t{1} << 53) / power);
}

double DecimalGrid::round_general(double v) const {
  const double r = round_half_away(v * scale_) / scale_;
  return r == 0.0 ? 0.0 : r;  // never -0
}

double round_half_away(double y) {
  if (!(std::abs(y) < 4503599627370496.0)) return y;  // 2^52: already whole (or inf, NaN)
  double t = static_cast<double>(static_cast<std::int64_t>(y));  // towards zero
  const double fraction = y - t;                                   // exact
  if (fraction >= 0.5) t += 1.0;
  else if (fraction <= -0.5) t -= 1.0;
  return t;
}

std::optional<int> digits_of(double v) {
  if (v >= 1.0) return static_cast<int>(std::lround(v));
  if (v > 0.0) return static_cast<int>(std::lround(-std::log10(v)));
  return std::nullopt;
}

PrecisionSettings PrecisionSettings::from(const MachineParameters& p) {
  PrecisionSettings s;
  s.zero_value = p.numeric("zero_value");
  if (p.has("movement_precision")) s.movement_digits = digits_of(p.numeric("movement_precision"));
  if (p.has("feed_precision")) s.feed_digits = static_cast<int>(p.integer("feed_precision"));
  if (p.has("spin_precision")) s.spin_digits = static_cast<int>(p.integer("spin_precision"));
  return s;
}

PrecisionFilter::PrecisionFilter(toolpath::CommandSource& input, PrecisionSettings settings)
    : input_(input),
      s_(settings),
      movement_(grid_of(s_.movement_digits)),
      feed_(grid_of(s_.feed_digits)),
      spin_(grid_of(s_.spin_digits)),
      whole_stays_(!s_.every_value_in_full && s_.zero_value <= 1.0) {
  for (int k = 0; k < kParameters; ++k) {
    zero_of_[k] = k < kFeed ? s_.zero_value : 0.0;
    const auto& grid = k < kFeed ? movement_ : k == kFeed ? feed_ : spin_;
    grid_of_[k] = grid ? &*grid : nullptr;
    // adjust() changes nothing, and follows no axis, for a parameter that neither snaps nor rounds.
    if (zero_of_[k] > 0 || grid_of_[k]) active_ |= std::uint32_t{1} << k;
    whole_limit_of_[k] = whole_stays_ && grid_of_[k] ? grid_of_[k]->whole_limit() : -1.0;
  }
  for (double& axis : sent_) axis = std::numeric_limits<double>::quiet_NaN();
  for (double& value : kept_) value = std::numeric_limits<double>::quiet_NaN();
}

// True when adjust() would leave x as it is. Each test is false for zero_value <= 0 and for an
// unknown (NaN) axis, as adjust() would skip them. A fraction equal to the last one the tests
// kept for this parameter (kept_: a contour's depth, an arc's radius) skips them: they give the
// same for equal values (NaN equals none; -0 and +0 fare alike).
inline bool PrecisionFilter::leaves(double x, int k, bool axis) {
  // A whole number is at least 1 from 0, so it snaps to 0 only for a zero_value above 1.
  if (!DecimalGrid::whole_within(x, whole_limit_of_[k]) && x != kept_[k]) {
    if (s_.every_value_in_full || (std::abs(x) < zero_of_[k] && x != 0.0)) return false;
    // With whole_stays_, x is known to be off the grid's whole-number shortcut.
    const DecimalGrid* grid = grid_of_[k];
    if (grid && !(whole_stays_ ? grid->round_general(x) == x : grid->keeps(x))) return false;
    kept_[k] = x;
  }
  return !(axis && std::abs(x - sent_[k]) < s_.zero_value && x != sent_[k]);
}

// Most values are already at the precision and far from zero and from the axis they move on:
// telling that takes a few comparisons and at most one rounding, and such a value is left as it
// is; any other goes through adjust(), the steps as spec 3.1 orders them. Each parameter is the
// first of its name (as Command::find finds it), read from the fields the arc filter before this
// one found, or found here in one pass; the parameters are independent, so their order is not
// the command's.
bool PrecisionFilter::next_with_kind(toolpath::Command& out, CommandKind& kind) {
  if (!input_.next(out, kind)) return false;
  if (!out.is_stream_command()) return true;
  const CommandFields* fields = input_.fields();
  if (!fields) {
    own_fields_.find(out);
    fields = &own_fields_;
  }
  const int axes = has(kMovesTool, kind) ? 3 : 0;  // parameters below this are axes the tool moves on
  for (std::uint32_t todo = fields->present & active_; todo != 0; todo &= todo - 1) {
    const int k = std::countr_zero(todo);
    toolpath::Value* v = fields->slots[k];
    if (!is_number(*v)) continue;
    const double x = number_of(*v);
    if (!leaves(x, k, k < axes)) adjust(*v, k, axes != 0);
    else if (k < axes) sent_[k] = x;
  }
  return true;
}

// Snap to zero, keep an axis that barely moved, round, in the order of spec 3.1. Values already at
// the precision stay as they are (an integer stays an integer); a changed value becomes numeric
// and keeps its change flag.
void PrecisionFilter::adjust(toolpath::Value& v, int k, bool moves) {
  const double zero = s_.zero_value;
  double x = number_of(v);
  bool changed = false;
  auto set = [&](double r) {
    if (r != x) x = r, changed = true;
  };
  if (k < kFeed) {
    if (zero > 0 && x != 0.0 && std::abs(x) < zero) set(0.0);
    if (zero > 0 && moves && k < 3) {
      const double last = sent_[k];
      if (!std::isnan(last) && x != last && std::abs(x - last) < zero) set(last);
    }
    if (movement_) set(movement_->round(x));
  } else if (k == kFeed && feed_) {
    set(feed_->round(x));
  } else if (k == kSpin && spin_) {
    set(spin_->round(x));
  }
  if (changed) v = toolpath::Value::make_numeric(x, v.flag);
  if (moves && k < 3) sent_[k] = x;  // where the tool is sent (ToolPosition::update, in this pass)
}

}  // namespace prp
