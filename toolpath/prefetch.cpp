#include "toolpath/prefetch.hpp"

#include <algorithm>
#include <utility>

namespace toolpath {

PrefetchSource::PrefetchSource(CommandSource& inner, std::size_t batch_size, std::size_t batches)
    : inner_(inner), ring_(batches < 2 ? 2 : batches) {
  start(batch_size);
}

PrefetchSource::PrefetchSource(CommandSource& inner, Command&& first, std::size_t batch_size, std::size_t batches)
    : inner_(inner), first_(std::move(first)), has_first_(true), ring_(batches < 2 ? 2 : batches) {
  start(batch_size);
}

void PrefetchSource::start(std::size_t batch_size) {
  for (Batch& b : ring_) {
    b.commands.resize(batch_size <= kept ? kept + 1 : batch_size);  // see released_
    for (Command& c : b.commands) c.keep_name_on_heap();
  }
  worker_ = std::thread([this] { work(); });
}

PrefetchSource::~PrefetchSource() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  space_.notify_one();
  worker_.join();
}

void PrefetchSource::work() {
  for (;;) {
    std::size_t index;
    {
      std::unique_lock lock(mutex_);
      if (!stop_ && filled_ - released_ == ring_.size()) {
        worker_waits_ = true;
        space_.wait(lock, [&] { return stop_ || 2 * (filled_ - released_) <= ring_.size(); });
        worker_waits_ = false;
      }
      if (stop_) return;
      index = filled_ % ring_.size();
    }
    Batch& b = ring_[index];
    b.count = 0;
    b.last = false;
    b.error = nullptr;
    if (has_first_) {
      swap(b.commands[b.count++], first_);
      has_first_ = false;
    }
    try {
      while (b.count < b.commands.size() && inner_.next(b.commands[b.count])) ++b.count;
      b.last = b.count < b.commands.size();
    } catch (...) {
      b.error = std::current_exception();
      b.last = true;
    }
    bool wake;
    {
      std::lock_guard lock(mutex_);
      ++filled_;
      worker_done_ = b.last;
      wake = reader_waits_ && (b.last || 2 * (filled_ - released_) >= ring_.size());
    }
    if (wake) data_.notify_one();
    if (b.last) return;
  }
}

bool PrefetchSource::next(Command& out) {
  Command* c = next_in_place();
  if (!c) return false;
  swap(out, *c);  // the worker refills the slot with out's buffers
  return true;
}

Command* PrefetchSource::advance() {
  if (current_) {
    Batch& b = *current_;
    if (position_ < b.count) {  // `kept` commands into the batch: the one before may go
      release_before();
      limit_ = b.count;
      return &b.commands[position_++];
    }
    if (b.last) {
      finished_ = true;
      current_ = nullptr;
      limit_ = position_ = 0;
      if (b.error) std::rethrow_exception(std::exchange(b.error, nullptr));
      return nullptr;
    }
    // Read to its end: held while its last commands may still be in use.
    holding_before_ = true;
  }
  if (finished_) return nullptr;
  {
    std::unique_lock lock(mutex_);
    if (filled_ == taken_) {
      reader_waits_ = true;
      data_.wait(lock, [&] { return filled_ > taken_ && (worker_done_ || 2 * (filled_ - released_) >= ring_.size()); });
      reader_waits_ = false;
    }
    current_ = &ring_[taken_++ % ring_.size()];
  }
  position_ = 0;
  limit_ = holding_before_ ? std::min(current_->count, kept) : current_->count;
  return next_in_place();
}

void PrefetchSource::release_before() {
  bool wake;
  {
    std::lock_guard lock(mutex_);
    ++released_;
    // A waiting side is woken once half of the ring is free (worker) or filled (reader), not at
    // every batch: it then handles several batches in one go instead of trading a wake-up per
    // batch with the other side.
    wake = worker_waits_ && 2 * (filled_ - released_) <= ring_.size();
  }
  holding_before_ = false;
  if (wake) space_.notify_one();
}

}  // namespace toolpath
