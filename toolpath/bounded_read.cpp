#include "toolpath/bounded_read.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "toolpath/error.hpp"

namespace toolpath {

std::string read_file_bounded(const std::string& path, std::size_t limit, std::string_view too_large,
                              std::string_view cannot_open) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, std::string(cannot_open));
  std::string out;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    out.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (out.size() > limit) throw InputError({path, 0, 0}, std::string(too_large));
  }
  if (in.bad()) throw InputError({path, 0, 0}, std::string("read error: ") + std::strerror(errno));
  return out;
}

LineRead read_line(std::istream& in, std::string& line, std::size_t limit) {
  line.clear();
  char chunk[1 << 12];
  for (;;) {
    in.getline(chunk, sizeof chunk);
    const auto got = static_cast<std::size_t>(in.gcount());
    if (!in.fail()) {
      // The line end was taken (and counted in gcount, not stored), or the input ended after it.
      line.append(chunk, in.eof() ? got : got - 1);
      return line.size() > limit ? LineRead::TooLong : LineRead::Line;
    }
    if (in.eof() || in.bad()) return line.empty() ? LineRead::End : LineRead::Line;  // a last part, then the end
    // The chunk filled up before the line end: take it and go on.
    line.append(chunk, got);
    if (line.size() > limit) return LineRead::TooLong;
    in.clear();
  }
}

std::string excerpt(std::string_view text, std::size_t max) {
  if (text.size() <= max) return std::string(text);
  return std::string(text.substr(0, max)) + "...";
}

}  // namespace toolpath
