// PrefetchSource: the same commands in the same order as its source, whatever the batch size; the
// source's exception at the place it happened; a stop in the middle of a stream. next_in_place()
// gives what next() gives, and keeps the commands it promises in place while the worker races ahead.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "toolpath/prefetch.hpp"

using toolpath::Command;
using toolpath::PrefetchSource;

namespace {

// Commands @c0, @c1, ... each with one parameter `i`; throws after `fail_after` commands when set.
class Numbered final : public toolpath::CommandSource {
public:
  Numbered(std::size_t count, std::size_t fail_after = SIZE_MAX) : count_(count), fail_after_(fail_after) {}
  bool next(Command& out) override {
    if (produced_ == fail_after_) throw std::runtime_error("broken at " + std::to_string(produced_));
    if (produced_ == count_) return false;
    out.clear();
    out.name = "@c" + std::to_string(produced_);
    out.index = produced_;
    out.set("i", toolpath::Value::make_integer(static_cast<std::int64_t>(produced_)));
    ++produced_;
    return true;
  }

private:
  std::size_t count_, fail_after_, produced_ = 0;
};

void expect_numbered(const Command& c, std::size_t i) {
  EXPECT_EQ(c.name, "@c" + std::to_string(i));
  EXPECT_EQ(c.index, i);
  ASSERT_EQ(c.parameters.size(), 1u);
  EXPECT_EQ(c.parameters[0].value.integer, static_cast<std::int64_t>(i));
}

struct Shape {
  std::size_t commands, batch_size, batches;
};

TEST(PrefetchSource, SameCommandsInOrder) {
  const Shape shapes[] = {{0, 4, 2}, {1, 4, 2}, {3, 4, 2}, {4, 4, 2}, {5, 4, 2}, {8, 4, 2},
                          {9, 4, 2}, {1000, 1, 2}, {1000, 3, 3}, {100000, 256, 4}};
  for (const Shape& s : shapes) {
    SCOPED_TRACE(std::to_string(s.commands) + " commands, batches of " + std::to_string(s.batch_size));
    Numbered source(s.commands);
    PrefetchSource prefetched(source, s.batch_size, s.batches);
    Command c;
    std::size_t n = 0;
    while (prefetched.next(c)) expect_numbered(c, n++);
    EXPECT_EQ(n, s.commands);
    EXPECT_FALSE(prefetched.next(c));  // and stays at the end
  }
}

// A first command taken from the source before: it comes first, then the rest, in any batch size,
// by next() and by next_in_place(); the source's exception still comes where it happened.
TEST(PrefetchSource, StartsWithACommandTakenBefore) {
  const Shape shapes[] = {{1, 4, 2}, {2, 4, 2}, {4, 4, 2}, {5, 4, 2}, {1000, 1, 2}, {1000, 3, 3}, {10000, 256, 4}};
  for (const Shape& s : shapes) {
    for (const bool in_place : {false, true}) {
      SCOPED_TRACE(std::to_string(s.commands) + " commands, batches of " + std::to_string(s.batch_size) +
                   (in_place ? ", in place" : ""));
      Numbered source(s.commands);
      Command first;
      ASSERT_TRUE(source.next(first));
      PrefetchSource prefetched(source, std::move(first), s.batch_size, s.batches);
      std::size_t n = 0;
      Command c;
      for (;;) {
        const Command* got = in_place ? prefetched.next_in_place() : (prefetched.next(c) ? &c : nullptr);
        if (!got) break;
        expect_numbered(*got, n++);
      }
      EXPECT_EQ(n, s.commands);
    }
  }
  Numbered failing(10, 5);
  Command first;
  ASSERT_TRUE(failing.next(first));
  PrefetchSource prefetched(failing, std::move(first), 2, 2);
  Command c;
  for (std::size_t i = 0; i < 5; ++i) {
    ASSERT_TRUE(prefetched.next(c));
    expect_numbered(c, i);
  }
  EXPECT_THROW(prefetched.next(c), std::runtime_error);
}

// Reads like next(), and checks after each call that the `kept` commands before are still intact:
// small batches in a small ring have the worker refill every slot it may as soon as it may.
TEST(PrefetchSource, InPlaceKeepsTheCommandsBefore) {
  const Shape shapes[] = {{0, 4, 2}, {1, 1, 2}, {2, 1, 2}, {3, 2, 2}, {5, 3, 2}, {7, 4, 2},
                          {1000, 1, 2}, {1000, 3, 3}, {1000, 4, 2}, {100000, 256, 4}};
  for (const Shape& s : shapes) {
    SCOPED_TRACE(std::to_string(s.commands) + " commands, batches of " + std::to_string(s.batch_size));
    Numbered source(s.commands);
    PrefetchSource prefetched(source, s.batch_size, s.batches);
    std::vector<const Command*> returned;
    while (const Command* c = prefetched.next_in_place()) {
      returned.push_back(c);
      const std::size_t n = returned.size();
      for (std::size_t back = 0; back <= PrefetchSource::kept && back < n; ++back)
        expect_numbered(*returned[n - 1 - back], n - 1 - back);
      if (::testing::Test::HasFailure()) return;
    }
    EXPECT_EQ(returned.size(), s.commands);
    EXPECT_EQ(prefetched.next_in_place(), nullptr);  // and stays at the end
  }
}

TEST(PrefetchSource, InPlaceRethrowsWhereTheSourceFailed) {
  for (std::size_t fail_after : {0u, 1u, 3u, 4u, 5u, 17u}) {
    SCOPED_TRACE(fail_after);
    Numbered source(100, fail_after);
    PrefetchSource prefetched(source, 4, 2);
    std::size_t n = 0;
    try {
      while (const Command* c = prefetched.next_in_place()) expect_numbered(*c, n++);
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "broken at " + std::to_string(fail_after));
    }
    EXPECT_EQ(n, fail_after);
    EXPECT_EQ(prefetched.next_in_place(), nullptr);
  }
}

TEST(PrefetchSource, RethrowsWhereTheSourceFailed) {
  for (std::size_t fail_after : {0u, 1u, 3u, 4u, 5u, 17u}) {
    SCOPED_TRACE(fail_after);
    Numbered source(100, fail_after);
    PrefetchSource prefetched(source, 4, 2);
    Command c;
    std::size_t n = 0;
    try {
      while (prefetched.next(c)) expect_numbered(c, n++);
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "broken at " + std::to_string(fail_after));
    }
    EXPECT_EQ(n, fail_after);
    EXPECT_FALSE(prefetched.next(c));
  }
}

TEST(PrefetchSource, StopsInTheMiddleOfAStream) {
  Numbered source(SIZE_MAX);  // endless
  {
    PrefetchSource prefetched(source, 8, 2);
    Command c;
    for (std::size_t i = 0; i < 20; ++i) {
      ASSERT_TRUE(prefetched.next(c));
      expect_numbered(c, i);
    }
  }  // the destructor stops the worker: the test ends
  SUCCEED();
}

}  // namespace
