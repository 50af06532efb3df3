#include "prp/filters/short_line_filter.hpp"

#include <utility>

namespace prp {

bool ShortLineFilter::hand_out(toolpath::Command& out, toolpath::Command& from) {
  swap(out, from);
  sent_.update(out);
  return true;
}

bool ShortLineFilter::is_short(const toolpath::Command& line) const {
  static constexpr toolpath::ParamKey names[] = {toolpath::ParamKey::xpos, toolpath::ParamKey::ypos,
                                                 toolpath::ParamKey::zpos};
  double squared = 0;
  for (int i = 0; i < 3; ++i) {
    auto here = sent_.axis(i);
    auto there = number(line, names[i]);
    if (!there) continue;  // an axis the line does not name does not move
    if (!here) return false;  // unknown start: keep the line
    squared += (*there - *here) * (*there - *here);
  }
  return squared < eps_line_ * eps_line_;
}

bool ShortLineFilter::next(toolpath::Command& out) {
  if (has_queued_) {
    has_queued_ = false;
    return hand_out(out, queued_);
  }
  while (input_.next(current_)) {
    if (current_.is_stream_command() && is(current_, "@line")) {
      // A held short line followed by another line is dropped; the new one is measured from the
      // same last position sent.
      has_held_ = false;
      if (is_short(current_)) {
        swap(held_, current_);
        has_held_ = true;
        continue;
      }
      return hand_out(out, current_);
    }
    if (has_held_) {  // the contour ends here: its last (short) line is kept
      has_held_ = false;
      swap(queued_, current_);
      has_queued_ = true;
      return hand_out(out, held_);
    }
    return hand_out(out, current_);
  }
  if (has_held_) {
    has_held_ = false;
    return hand_out(out, held_);
  }
  return false;
}

}  // namespace prp
