// Runs a command source on a worker thread, so that reading and filtering a stream overlap with
// posting it: on a long job the two halves take about the same time (docs/performance.md).
//
//   PrefetchSource ahead(filtered);   // the worker starts pulling from `filtered`
//   while (ahead.next(command)) ...   // the same commands, in the same order
//
// Commands cross in batches through a small ring: memory stays flat whatever the job length, and
// a command handed back by next() lends its buffers to the worker, so nothing is allocated in the
// steady state. An exception thrown by the source is rethrown by next() where the stream reached
// it, after the commands read before it. `inner` is only used by the worker until the destructor
// has stopped it.
//
// next_in_place() hands out the command where it lies in the ring instead (no swap: the engine
// reads each command there, with the one before and the one after it).
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "toolpath/source.hpp"

namespace toolpath {

class PrefetchSource final : public CommandSource {
public:
  explicit PrefetchSource(CommandSource& inner, std::size_t batch_size = 256, std::size_t batches = 4);
  // Starts with `first`, a command already taken from `inner` (to look at it before the rest):
  // what a LookaheadSource in between would do, without its call on every command.
  PrefetchSource(CommandSource& inner, Command&& first, std::size_t batch_size = 256, std::size_t batches = 4);
  ~PrefetchSource() override;
  PrefetchSource(const PrefetchSource&) = delete;
  PrefetchSource& operator=(const PrefetchSource&) = delete;

  bool next(Command& out) override;

  // The next command in its ring slot, which the caller may change; nullptr at the end (or after
  // the source's exception, rethrown here). It and the `kept` commands returned before it stay in
  // place until the next call. Use either this or next() on one source, not both.
  static constexpr std::size_t kept = 2;
  Command* next_in_place() {
    if (position_ < limit_) return &current_->commands[position_++];
    return advance();
  }

private:
  struct Batch {
    std::vector<Command> commands;
    std::size_t count = 0;     // commands filled
    bool last = false;         // the stream ends (or failed) after these
    std::exception_ptr error;  // what the source threw after `count` commands
  };

  void start(std::size_t batch_size);  // the ring's commands, then the worker
  void work();
  Command* advance();  // next_in_place() at the end of a batch, or where the batch before is released
  void release_before();

  CommandSource& inner_;
  Command first_;
  bool has_first_ = false;  // first_ goes at the head of the first batch
  std::vector<Batch> ring_;
  // Batches filled by the worker, taken and released by the reader, counted from the start: the
  // worker fills ring_[filled_ % size] while fewer than size are unreleased; the reader reads
  // ring_[(taken_ - 1) % size]. The batch before it is released only once the reader is `kept`
  // commands into this one (every batch but the last holds more than `kept`).
  std::size_t filled_ = 0, taken_ = 0, released_ = 0;
  bool stop_ = false;
  // Each side is woken only when it sleeps: a notify per batch costs a futex call even with nobody
  // waiting, and on two cores the three stages of a run usually find their batch ready.
  bool worker_waits_ = false, reader_waits_ = false;
  bool worker_done_ = false;  // the last batch is filled
  std::mutex mutex_;
  std::condition_variable space_;  // the worker waits for a released batch
  std::condition_variable data_;   // the reader waits for a filled batch
  // The reader's side (only next() and next_in_place() touch these).
  Batch* current_ = nullptr;  // the batch being read (no division per command); nullptr before the first
  std::size_t position_ = 0;  // its next command
  std::size_t limit_ = 0;     // where advance() is due: its end, or `kept` while the batch before is held
  bool holding_before_ = false;  // the batch before current_ is not released yet
  bool finished_ = false;
  std::thread worker_;  // last: starts once everything above is ready
};

}  // namespace toolpath
