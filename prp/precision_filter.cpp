#include "prp/precision_filter.hpp"

#include <cmath>

namespace prp {
namespace {

constexpr std::string_view kPositions[] = {"xpos", "ypos", "zpos"};
// Lengths rounded with the coordinates.
constexpr std::string_view kLengths[] = {"xpos",   "ypos",   "zpos",          "xcenter",       "ycenter",
                                         "xcenter_rel", "ycenter_rel", "radius", "zstart", "drill_upper_z",
                                         "drill_lower_z", "drill_clearance_z", "drill_depth", "down_step"};

double round_to(double v, int digits) {
  const double scale = std::pow(10.0, digits);
  double r = std::round(v * scale) / scale;
  return r == 0.0 ? 0.0 : r;  // never -0
}

// Values already at the precision stay as they are (an integer stays an integer).
void round_parameter(toolpath::Command& c, std::string_view name, int digits) {
  auto v = number(c, name);
  if (!v) return;
  double r = round_to(*v, digits);
  if (r != *v) set_number(c, name, r);
}

}  // namespace

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

bool PrecisionFilter::next(toolpath::Command& out) {
  if (!input_.next(out)) return false;
  if (!out.is_stream_command()) return true;
  if (s_.zero_value > 0) {
    for (std::string_view name : kLengths) {
      auto v = number(out, name);
      if (v && *v != 0.0 && std::abs(*v) < s_.zero_value) set_number(out, name, 0.0);
    }
    if (moves_tool(out)) {
      for (int i = 0; i < 3; ++i) {
        auto v = number(out, kPositions[i]);
        auto last = sent_.axis(i);
        if (v && last && *v != *last && std::abs(*v - *last) < s_.zero_value) set_number(out, kPositions[i], *last);
      }
    }
  }
  if (s_.movement_digits) {
    for (std::string_view name : kLengths) round_parameter(out, name, *s_.movement_digits);
  }
  if (s_.feed_digits) round_parameter(out, "feed", *s_.feed_digits);
  if (s_.spin_digits) round_parameter(out, "spin", *s_.spin_digits);
  sent_.update(out);
  return true;
}

}  // namespace prp
