// The text of the output line being built (spec 6.2). Internal to gppl/run.
//
// A std::string would have to be filled before it could be written to, so a formatted number went
// through a buffer of its own first; here the printer writes straight past the end (room()) and
// commit() keeps what it wrote.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string_view>

namespace gppl {

// The end and the limit are kept as pointers: room(), commit() and the appends, a dozen a block,
// then need no base-plus-offset arithmetic.
class OutputLine {
public:
  OutputLine() { grow(256); }
  OutputLine(const OutputLine&) = delete;  // the pointers point into its own buffer
  OutputLine& operator=(const OutputLine&) = delete;

  std::size_t size() const { return static_cast<std::size_t>(end_ - data_.get()); }
  bool empty() const { return end_ == data_.get(); }
  char operator[](std::size_t i) const { return data_[i]; }
  std::string_view view() const { return {data_.get(), size()}; }
  operator std::string_view() const { return view(); }

  void clear() { end_ = data_.get(); }
  void shrink(std::size_t n) {
    if (n < size()) end_ = data_.get() + n;
  }

  // At least `n` writable bytes at the end; nothing counts until commit().
  char* room(std::size_t n) {
    if (static_cast<std::size_t>(limit_ - end_) < n) grow(size() + n);
    return end_;
  }
  void commit(const char* end) { end_ += end - end_; }  // `end` lies in the room just given

  void append(std::string_view text) {
    const std::size_t n = text.size();
    char* to = room(n);
    const char* from = text.data();
    // Most texts are a few letters (' X', 'G', 'N'): two overlapping word copies instead of a
    // memcpy call, reading no byte outside the text.
    auto copy = [&]<typename Word>(Word) {
      Word head, tail;
      std::memcpy(&head, from, sizeof(Word));
      std::memcpy(&tail, from + n - sizeof(Word), sizeof(Word));
      std::memcpy(to, &head, sizeof(Word));
      std::memcpy(to + n - sizeof(Word), &tail, sizeof(Word));
    };
    // The shortest first: they are the most frequent, and an empty text (end_block_text) costs two tests.
    if (n <= 3) {
      if (n > 0) to[0] = from[0], to[n / 2] = from[n / 2], to[n - 1] = from[n - 1];  // all of them
    } else if (n < 8) {
      copy(std::uint32_t{});
    } else if (n <= 16) {
      copy(std::uint64_t{});
    } else {
      std::memcpy(to, from, n);
    }
    end_ = to + n;
  }
  void push_back(char c) {
    char* to = room(1);
    *to = c;
    end_ = to + 1;
  }
  void append_fill(std::size_t n, char c) {
    if (n == 0) return;
    char* to = room(n);
    std::memset(to, c, n);
    end_ = to + n;
  }
  void insert(std::size_t at, char c) {
    room(1);  // may move the text: take the position after growing
    char* p = data_.get() + at;
    std::memmove(p + 1, p, static_cast<std::size_t>(end_ - p));
    *p = c;
    ++end_;
  }
  void remove_all(char c) { end_ = std::remove(data_.get(), end_, c); }

private:
  void grow(std::size_t wanted) {
    const auto size = static_cast<std::size_t>(end_ - data_.get());
    const std::size_t capacity = std::max(wanted, 2 * static_cast<std::size_t>(limit_ - data_.get()));
    auto bigger = std::make_unique_for_overwrite<char[]>(capacity);
    if (size > 0) std::memcpy(bigger.get(), data_.get(), size);
    data_ = std::move(bigger);
    end_ = data_.get() + size;
    limit_ = data_.get() + capacity;
  }

  std::unique_ptr<char[]> data_;
  char* end_ = nullptr;    // of the text
  char* limit_ = nullptr;  // of the buffer
};

}  // namespace gppl
