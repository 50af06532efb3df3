// The machining-time estimate of spec 3.15, fed with the commands the post receives (after every
// filter): time_factor * (feed time + rapid time) + block_time per motion block + change_tool_time
// per tool change + dwells. Nothing here changes the stream.
#pragma once

#include "prp/filters/motion.hpp"
#include "prp/prp.hpp"

namespace prp {

class TimeEstimate {
public:
  explicit TimeEstimate(TimeSettings settings) : s_(settings) {}
  void add(const toolpath::Command& c);

  double seconds() const;            // the whole estimate so far
  double feed_minutes() const { return feed_minutes_; }
  double rapid_minutes() const { return rapid_minutes_; }
  std::size_t motion_blocks() const { return blocks_; }
  std::size_t tool_changes() const { return tool_changes_; }
  bool rapid_feed_missing() const { return rapids_without_feed_ > 0; }

private:
  TimeSettings s_;
  ToolPosition position_;
  std::optional<double> feed_;
  double feed_minutes_ = 0, rapid_minutes_ = 0, dwell_seconds_ = 0;
  std::size_t blocks_ = 0, tool_changes_ = 0, rapids_without_feed_ = 0;
};

}  // namespace prp
