#include "lsp/transport.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <optional>

#include "toolpath/bounded_read.hpp"
#include "toolpath/value.hpp"

namespace lsp {
namespace {

constexpr std::size_t kMaxHeaderLine = 1024;
constexpr std::size_t kMaxHeaderLines = 32;

}  // namespace

Frame read_frame(std::istream& in, std::size_t max_body) {
  Frame frame;
  std::string line;
  std::optional<std::size_t> length;
  std::string problem;
  std::size_t lines = 0;
  for (;;) {
    const toolpath::LineRead r = toolpath::read_line(in, line, kMaxHeaderLine);
    if (r == toolpath::LineRead::End) return frame;  // End
    if (r == toolpath::LineRead::TooLong) {
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
      problem = "a header line longer than 1024 bytes";
      continue;
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) {
      if (lines == 0) continue;  // blank lines between messages
      break;
    }
    if (++lines > kMaxHeaderLines) problem = "more than 32 header lines";
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) {
      problem = "a header line without `:`: `" + toolpath::excerpt(line) + "`";
      continue;
    }
    const std::string_view name = std::string_view(line).substr(0, colon);
    std::string_view value = std::string_view(line).substr(colon + 1);
    while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.remove_prefix(1);
    while (!value.empty() && (value.back() == ' ' || value.back() == '\t')) value.remove_suffix(1);
    if (!toolpath::iequals(name, "Content-Length")) continue;  // Content-Type and the rest
    std::size_t n = 0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (ec != std::errc{} || end != value.data() + value.size()) {
      problem = "Content-Length is not a number: `" + toolpath::excerpt(value) + "`";
      continue;
    }
    length = n;
  }
  if (problem.empty() && !length) problem = "no Content-Length header";
  if (!problem.empty()) {
    frame.status = FrameStatus::Malformed;
    frame.error = problem;
    return frame;
  }
  if (*length > max_body) {  // skipped in chunks: its bytes are not kept
    std::size_t left = *length;
    char buffer[4096];
    while (left > 0) {
      const std::size_t chunk = std::min(left, sizeof buffer);
      if (!in.read(buffer, static_cast<std::streamsize>(chunk))) break;
      left -= chunk;
    }
    frame.status = left == 0 ? FrameStatus::Malformed : FrameStatus::End;
    frame.error = "a message of " + std::to_string(*length) + " bytes, more than the " + std::to_string(max_body) + " taken";
    return frame;
  }
  frame.body.resize(*length);
  if (*length > 0 && !in.read(frame.body.data(), static_cast<std::streamsize>(*length))) return Frame{};  // End
  frame.status = FrameStatus::Message;
  return frame;
}

void write_frame(std::ostream& out, std::string_view body) {
  out << "Content-Length: " << body.size() << "\r\n\r\n" << body;
  out.flush();
}

}  // namespace lsp
