#include "machines/pikocnc/geometry.hpp"

#include <cmath>

namespace pikocnc {

double sweep_angle(const Eigen::Vector2d& start, const Eigen::Vector2d& end, const Eigen::Vector2d& centre, bool ccw) {
  const double a0 = std::atan2(start.y() - centre.y(), start.x() - centre.x());
  const double a1 = std::atan2(end.y() - centre.y(), end.x() - centre.x());
  double s = ccw ? a1 - a0 : a0 - a1;
  while (s <= 1e-12) s += 2 * kPi;
  while (s > 2 * kPi + 1e-12) s -= 2 * kPi;
  return s;
}

double angle_degrees(const Eigen::Vector2d& p, const Eigen::Vector2d& centre) {
  double a = std::atan2(p.y() - centre.y(), p.x() - centre.x()) * 180.0 / kPi;
  if (a < 0) a += 360.0;
  if (a >= 360.0) a -= 360.0;
  return clean(a);
}

double clean(double v) {
  const double scaled = v * 1e9;
  double rounded;
  if (std::abs(scaled) < 1e15) {
    constexpr double kShift = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
    rounded = (scaled + kShift) - kShift;
  } else {
    rounded = std::round(scaled);
  }
  if (rounded == scaled) return v == 0.0 ? 0.0 : v;  // already short: keep it as it is
  const double r = rounded / 1e9;
  return r == 0.0 ? 0.0 : r;
}

}  // namespace pikocnc
