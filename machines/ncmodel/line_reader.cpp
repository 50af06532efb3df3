#include "machines/ncmodel/line_reader.hpp"

#include <algorithm>
#include <cstring>

#include "machines/ncmodel/block_text.hpp"
#include "toolpath/error.hpp"

namespace ncmodel {

namespace {
constexpr std::size_t kChunk = 256 * 1024;
constexpr std::size_t kMaxLine = std::size_t{16} << 20;
}

bool LineReader::fill() {
  if (at_eof_) return false;
  if (pos_ > 0) {  // drop consumed bytes so the buffer never grows with the file
    std::memmove(buffer_.get(), buffer_.get() + pos_, size_ - pos_);
    size_ -= pos_;
    buffer_start_ += pos_;
    pos_ = 0;
  }
  if (capacity_ - size_ < kChunk) {  // a line longer than the chunks so far (or the first fill)
    const std::size_t capacity = std::max(2 * capacity_, size_ + kChunk);
    auto bigger = std::make_unique_for_overwrite<char[]>(capacity);
    if (size_ > 0) std::memcpy(bigger.get(), buffer_.get(), size_);
    buffer_ = std::move(bigger);
    capacity_ = capacity;
  }
  in_.read(buffer_.get() + size_, static_cast<std::streamsize>(kChunk));
  const auto got = static_cast<std::size_t>(in_.gcount());
  size_ += got;
  if (got < kChunk) at_eof_ = true;
  return got > 0;
}

bool LineReader::next(std::string_view& line) {
  std::size_t scan = pos_;
  for (;;) {
    const char* base = buffer_.get();
    const std::size_t size = size_;
    const std::size_t end = scan + find_either(base + scan, size - scan, '\n', '\r');
    const bool need_more = end == size || (base[end] == '\r' && end + 1 == size);
    if (need_more && !at_eof_) {
      const std::size_t consumed = scan - pos_;
      if (end - pos_ > kMaxLine)  // a binary file or a generator gone wrong: memory would grow without bound
        throw toolpath::InputError({file_, line_ + 1, 1}, "line longer than 16 MiB: not a G-code program?");
      if (!fill() && size_ == pos_) return false;
      scan = pos_ + consumed;
      continue;
    }
    if (end == pos_ && end == size) return false;  // nothing left
    line = std::string_view(base + pos_, end - pos_);
    std::size_t after = end;
    if (after < size) after += (base[after] == '\r' && after + 1 < size && base[after + 1] == '\n') ? 2 : 1;
    pos_ = after;
    ++line_;
    return true;
  }
}

void LineReader::seek(const Mark& where) {
  if (where.offset >= buffer_start_ && where.offset <= buffer_start_ + size_) {
    pos_ = static_cast<std::size_t>(where.offset - buffer_start_);
  } else {
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(where.offset));
    size_ = 0;
    buffer_start_ = where.offset;
    pos_ = 0;
    at_eof_ = false;
  }
  line_ = where.line;
}

}  // namespace ncmodel
