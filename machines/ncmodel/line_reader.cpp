#include "machines/ncmodel/line_reader.hpp"

#include <cstring>

#include "toolpath/error.hpp"

namespace ncmodel {

namespace {
constexpr std::size_t kChunk = 256 * 1024;
constexpr std::size_t kMaxLine = std::size_t{16} << 20;
}

bool LineReader::fill() {
  if (at_eof_) return false;
  if (pos_ > 0) {  // drop consumed bytes so the buffer never grows with the file
    buffer_.erase(0, pos_);
    buffer_start_ += pos_;
    pos_ = 0;
  }
  const std::size_t old = buffer_.size();
  buffer_.resize(old + kChunk);
  in_.read(buffer_.data() + old, static_cast<std::streamsize>(kChunk));
  const auto got = static_cast<std::size_t>(in_.gcount());
  buffer_.resize(old + got);
  if (got < kChunk) at_eof_ = true;
  return got > 0;
}

bool LineReader::next(std::string_view& line) {
  std::size_t scan = pos_;
  for (;;) {
    const char* base = buffer_.data();
    const std::size_t size = buffer_.size();
    std::size_t end = scan;
    while (end < size && base[end] != '\n' && base[end] != '\r') {
      const void* nl = std::memchr(base + end, '\n', size - end);
      const std::size_t stop = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - base) : size;
      const void* cr = std::memchr(base + end, '\r', stop - end);
      end = cr ? static_cast<std::size_t>(static_cast<const char*>(cr) - base) : stop;
    }
    const bool need_more = end == size || (base[end] == '\r' && end + 1 == size);
    if (need_more && !at_eof_) {
      const std::size_t consumed = scan - pos_;
      if (end - pos_ > kMaxLine)  // a binary file or a generator gone wrong: memory would grow without bound
        throw toolpath::InputError({file_, line_ + 1, 1}, "line longer than 16 MiB: not a G-code program?");
      if (!fill() && buffer_.size() == pos_) return false;
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
  if (where.offset >= buffer_start_ && where.offset <= buffer_start_ + buffer_.size()) {
    pos_ = static_cast<std::size_t>(where.offset - buffer_start_);
  } else {
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(where.offset));
    buffer_.clear();
    buffer_start_ = where.offset;
    pos_ = 0;
    at_eof_ = false;
  }
  line_ = where.line;
}

}  // namespace ncmodel
