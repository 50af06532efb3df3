#include "toolpath/source.hpp"

#include <utility>

namespace toolpath {

bool LookaheadSource::next(Command& out) {
  // After the first peek it only passes commands on: that case first.
  if (!has_buffered_ && !at_end_) [[likely]] {
    if (inner_.next(out)) return true;
    at_end_ = true;
    return false;
  }
  if (!has_buffered_) return false;
  swap(out, buffered_);  // hand over the buffered command; `buffered_` keeps `out`'s buffers
  has_buffered_ = false;
  return true;
}

const Command* LookaheadSource::peek() {
  if (has_buffered_) return &buffered_;
  if (at_end_) return nullptr;
  if (!inner_.next(buffered_)) {
    at_end_ = true;
    return nullptr;
  }
  has_buffered_ = true;
  return &buffered_;
}

}  // namespace toolpath
