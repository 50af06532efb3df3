#include "machines/pikocnc/model/geometry.hpp"

#include <cmath>

namespace pikocnc {

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
