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

class OutputLine {
public:
  OutputLine() { grow(256); }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  char operator[](std::size_t i) const { return data_[i]; }
  std::string_view view() const { return {data_.get(), size_}; }
  operator std::string_view() const { return view(); }

  void clear() { size_ = 0; }
  void shrink(std::size_t n) { size_ = std::min(size_, n); }

  // At least `n` writable bytes at the end; nothing counts until commit().
  char* room(std::size_t n) {
    if (capacity_ - size_ < n) grow(size_ + n);
    return data_.get() + size_;
  }
  void commit(const char* end) { size_ = static_cast<std::size_t>(end - data_.get()); }

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
    size_ += n;
  }
  void push_back(char c) { *room(1) = c, ++size_; }
  void append_fill(std::size_t n, char c) {
    if (n == 0) return;
    std::memset(room(n), c, n);
    size_ += n;
  }
  void insert(std::size_t at, char c) {
    char* base = room(1);  // may move the text: take the base after growing
    base -= size_;
    std::memmove(base + at + 1, base + at, size_ - at);
    base[at] = c;
    ++size_;
  }
  void remove_all(char c) { size_ = static_cast<std::size_t>(std::remove(data_.get(), data_.get() + size_, c) - data_.get()); }

private:
  void grow(std::size_t wanted) {
    const std::size_t capacity = std::max(wanted, 2 * capacity_);
    auto bigger = std::make_unique_for_overwrite<char[]>(capacity);
    if (size_ > 0) std::memcpy(bigger.get(), data_.get(), size_);
    data_ = std::move(bigger);
    capacity_ = capacity;
  }

  std::unique_ptr<char[]> data_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace gppl
