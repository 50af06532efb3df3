// Language Server Protocol messages over a byte stream: a few header lines (`Content-Length: N`
// is required, `Content-Type` is accepted), a blank line, then N bytes of JSON.
#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>

namespace lsp {

enum class FrameStatus { Message, End, Malformed };

struct Frame {
  FrameStatus status = FrameStatus::End;
  std::string body;   // Message: the JSON text
  std::string error;  // Malformed: what was wrong (its headers, or its body, were skipped)
};

// The next message. A malformed header block or a body longer than `max_body` bytes is skipped
// and reported as Malformed, so the stream can go on with the next message; End when the input
// ends (also inside a message).
Frame read_frame(std::istream& in, std::size_t max_body = std::size_t{64} << 20);
void write_frame(std::ostream& out, std::string_view body);

}  // namespace lsp
