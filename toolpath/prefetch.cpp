#include "toolpath/prefetch.hpp"

#include <utility>

namespace toolpath {

PrefetchSource::PrefetchSource(CommandSource& inner, std::size_t batch_size, std::size_t batches)
    : inner_(inner), ring_(batches < 2 ? 2 : batches) {
  for (Batch& b : ring_) b.commands.resize(batch_size < 1 ? 1 : batch_size);
  worker_ = std::thread([this] { work(); });
}

PrefetchSource::~PrefetchSource() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

void PrefetchSource::work() {
  for (;;) {
    std::size_t index;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return stop_ || filled_ - released_ < ring_.size(); });
      if (stop_) return;
      index = filled_ % ring_.size();
    }
    Batch& b = ring_[index];
    b.count = 0;
    b.last = false;
    b.error = nullptr;
    try {
      while (b.count < b.commands.size() && inner_.next(b.commands[b.count])) ++b.count;
      b.last = b.count < b.commands.size();
    } catch (...) {
      b.error = std::current_exception();
      b.last = true;
    }
    {
      std::lock_guard lock(mutex_);
      ++filled_;
    }
    changed_.notify_all();
    if (b.last) return;
  }
}

bool PrefetchSource::next(Command& out) {
  for (;;) {
    if (holding_) {
      Batch& b = *current_;
      if (position_ < b.count) {
        swap(out, b.commands[position_++]);  // the worker refills the slot with out's buffers
        return true;
      }
      if (b.last) {
        finished_ = true;
        holding_ = false;
        if (b.error) std::rethrow_exception(std::exchange(b.error, nullptr));
        return false;
      }
      {
        std::lock_guard lock(mutex_);
        ++released_;
      }
      changed_.notify_all();
      holding_ = false;
    }
    if (finished_) return false;
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return filled_ > released_; });
    holding_ = true;
    current_ = &ring_[released_ % ring_.size()];
    position_ = 0;
  }
}

}  // namespace toolpath
