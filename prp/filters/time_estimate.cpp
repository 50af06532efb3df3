#include "prp/filters/time_estimate.hpp"

#include <cmath>
#include <numbers>

namespace prp {

void TimeEstimate::add(const toolpath::Command& c) {
  if (!c.is_stream_command()) return;
  if (is(c, "@change_tool") || is(c, "@turn_change_tool")) ++tool_changes_;
  if (is(c, "@delay")) dwell_seconds_ += number(c, "delay_period").value_or(0);
  if (auto f = number(c, "feed")) feed_ = *f;
  const bool rapid = is(c, "@rapid_move");
  if (!rapid && !is_feed_motion(c)) {
    position_.update(c);
    return;
  }
  ++blocks_;
  double length = 0;
  if (is(c, "@arc") && number(c, "radius") && number(c, "arc_size")) {
    const double sweep = *number(c, "radius") * *number(c, "arc_size") * std::numbers::pi / 180.0;
    // The rise along the plane's normal; for XY arcs (the common case) that is Z.
    auto z = number(c, "zpos");
    auto from = position_.axis(2);
    length = std::hypot(sweep, z && from ? *z - *from : 0.0);
  } else {
    static constexpr std::string_view names[] = {"xpos", "ypos", "zpos"};
    double squared = 0;
    for (int i = 0; i < 3; ++i) {
      auto to = number(c, names[i]);
      auto from = position_.axis(i);
      if (to && from) squared += (*to - *from) * (*to - *from);
    }
    length = std::sqrt(squared);
  }
  if (rapid) {
    if (s_.rapid_feed && *s_.rapid_feed > 0) rapid_minutes_ += length / *s_.rapid_feed;
    else if (length > 0) ++rapids_without_feed_;
  } else if (feed_ && *feed_ > 0) {
    feed_minutes_ += length / *feed_;
  }
  position_.update(c);
}

double TimeEstimate::seconds() const {
  return s_.time_factor * (feed_minutes_ + rapid_minutes_) * 60.0 + s_.block_time * static_cast<double>(blocks_) +
         s_.change_tool_time * static_cast<double>(tool_changes_) + dwell_seconds_;
}

}  // namespace prp
