// Reading files that come from users without taking memory without bound: a whole file up to a
// size, a line up to a length, and a short excerpt of input text for a message
// (docs/reliability.md). The size is never asked first: a device (/dev/zero) reports none.
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <string_view>

namespace toolpath {

// The whole file at `path`, read in chunks. Throws InputError naming the file (no position):
// `cannot_open` when it cannot be opened, `too_large` (say "larger than 64 MiB: not a PRP file?")
// as soon as more than `limit` bytes were read, "read error: <reason>" when reading fails.
std::string read_file_bounded(const std::string& path, std::size_t limit, std::string_view too_large,
                              std::string_view cannot_open = "cannot open file");

enum class LineRead { Line, End, TooLong };

// std::getline with a bound: the next line, without its "\n", into `line`. End when the stream
// had nothing left (or failed); TooLong as soon as the line is longer than `limit` characters
// (`line` then holds its first part and the stream is left inside the line).
LineRead read_line(std::istream& in, std::string& line, std::size_t limit);

// `text` for quoting in a message: whole up to `max` characters, else its first `max` and "...".
std::string excerpt(std::string_view text, std::size_t max = 40);

}  // namespace toolpath
