// Zero snapping and precision rounding (spec 3.1), the last geometric stage: a coordinate closer
// than `zero_value` to 0 becomes 0; an axis that moves less than `zero_value` keeps its previous
// value; coordinates, feeds and spindle speeds are rounded to the PRP's digits.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "prp/filters/command_fields.hpp"
#include "prp/filters/kind_source.hpp"
#include "prp/prp.hpp"

namespace prp {

struct PrecisionSettings {
  double zero_value = 0.0;
  std::optional<int> movement_digits, feed_digits, spin_digits;
  bool every_value_in_full = false;  // tests: no shortcut for values the filter leaves as they are

  static PrecisionSettings from(const MachineParameters& params);
  bool does_nothing() const { return zero_value <= 0 && !movement_digits && !feed_digits && !spin_digits; }
};

// movement_precision as written (spec 3.1): a whole number >= 1 is a digit count, 0 < v < 1 a step
// (0.001: 3 digits), 0 no rounding.
std::optional<int> digits_of(double movement_precision);

// std::round (halves away from zero) without the library call, for every double (inf and NaN too);
// the zero it gives for -0.4 may be +0 where std::round gives -0 (rounding writes no -0 anyway).
double round_half_away(double y);

// Rounding to a number of decimals (spec 3.1): round_half_away(v * 10^digits) / 10^digits, never
// -0. round() gives the general rule's result, bit for bit, for every double; whole numbers (most
// coordinates, feeds and speeds) skip the arithmetic (see precision_filter.cpp for why that is exact).
class DecimalGrid {
public:
  explicit DecimalGrid(int digits);
  double round(double v) const {
    if (on_whole_shortcut(v)) return v == 0.0 ? 0.0 : v;
    return round_general(v);
  }
  double round_general(double v) const;  // the rule as written
  // round(v) == v (so also for -0, which rounds to +0), without the -0 step for whole numbers.
  bool keeps(double v) const { return on_whole_shortcut(v) || round_general(v) == v; }
  // A whole number within the shortcut's range: round(v) is v (+0 for -0).
  bool on_whole_shortcut(double v) const { return whole_within(v, whole_limit_); }
  double whole_limit() const { return whole_limit_; }
  // v is a whole number and |v| <= limit (a limit below 0: never); the cast is only made in range.
  static bool whole_within(double v, double limit) {
    return std::abs(v) <= limit && static_cast<double>(static_cast<std::int64_t>(v)) == v;
  }

private:
  double scale_;        // 10^digits
  double whole_limit_;  // whole numbers up to this stay as they are; -1: no shortcut
};

class PrecisionFilter final : public KindSource {
public:
  PrecisionFilter(toolpath::CommandSource& input, PrecisionSettings settings);
  bool next_with_kind(toolpath::Command& out, CommandKind& kind) override;

private:
  bool leaves(double x, int k, bool axis);  // remembers a fraction that passes (kept_)
  void adjust(toolpath::Value& v, int k, bool moves);  // the steps of spec 3.1, one by one

  KindedInput input_;
  PrecisionSettings s_;
  std::optional<DecimalGrid> movement_, feed_, spin_;
  // The filter's parameters (CommandFields, the first 16) that the settings snap or round, then
  // per parameter the zero_value it snaps with (0 for the feed and the spindle speed: never), and
  // its grid (null: no rounding).
  std::uint32_t active_ = 0;  // bit k: parameter k
  double zero_of_[16];
  const DecimalGrid* grid_of_[16];
  // A whole number on its grid never snaps (zero_value <= 1), nor rounds: per parameter the largest
  // such number its grid's shortcut takes, or -1 (no grid, zero_value above 1, every value in full).
  bool whole_stays_;
  double whole_limit_of_[16];
  double sent_[3];  // where the tool is sent, axis by axis; NaN while unknown (it never snaps to it)
  double kept_[16];  // per parameter, the last fraction it left as it was (NaN: none; never with every_value_in_full)
  CommandFields own_fields_;  // when the input hands on none
};

}  // namespace prp
