#include "toolpath/trace_writer.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string_view>

#include "toolpath/number_text.hpp"

namespace toolpath {
namespace {

constexpr std::size_t kArrowColumn = 20;  // `==>` and `..>` start in column 21, as SolidCAM writes them
constexpr std::size_t kLineWidth = 100;   // parameters wrap onto `..>` lines past this width
constexpr std::size_t kNumberRoom = kMaxNumberText + 1;  // a number or an integer, and its flag

// Copies a short text without a call: two overlapping fixed-size copies (names and enumeration
// words are mostly 4 to 16 bytes).
[[gnu::always_inline]] inline void copy_short(char* to, const char* from, std::size_t n) {
  if (n >= 8 && n <= 16) {
    std::memcpy(to, from, 8);
    std::memcpy(to + n - 8, from + n - 8, 8);
  } else if (n >= 4 && n < 8) {
    std::memcpy(to, from, 4);
    std::memcpy(to + n - 4, from + n - 4, 4);
  } else if (n > 0 && n < 4) {
    to[0] = from[0];
    to[n / 2] = from[n / 2];
    to[n - 1] = from[n - 1];
  } else if (n > 16) {
    std::memcpy(to, from, n);
  }
}

// Blanks to copy from: a run of blanks is written as one fixed-size copy (kHeadRoom bytes).
constexpr std::size_t kHeadRoom = 32;  // a continuation line's head: '\n', the blanks and "..> "
constexpr char kBlanks[kHeadRoom + 1] = "                                ";
static_assert(kArrowColumn + 5 <= kHeadRoom);

// Writes `n` (at most kArrowColumn + 2) blanks at `p`; it may write up to kHeadRoom bytes.
[[gnu::always_inline]] inline char* put_blanks(char* p, std::size_t n) {
  std::memcpy(p, kBlanks, kHeadRoom);
  return p + n;
}

[[gnu::always_inline]] inline char* put_text(char* p, std::string_view t) {
  copy_short(p, t.data(), t.size());
  return p + t.size();
}

char* put_flag(char* p, ChangeFlag flag) {
  if (flag != ChangeFlag::None) *p++ = flag == ChangeFlag::Changed ? 'T' : 'F';  // one test for most values
  return p;
}

// Writes a numeric value, through the cache when there is one.
[[gnu::always_inline]] inline char* put_number(char* p, double v, NumberCache* cache) {
  if (!cache) return write_number_text(p, v);
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
  NumberCache::Entry& e = cache->entries[(bits * 0x9E3779B97F4A7C15u) >> 58];
  if (e.length > 0 && e.bits == bits) {
    std::memcpy(p, e.text, sizeof e.text);  // the room is there: kNumberRoom
    return p + e.length;
  }
  char* const end = write_number_text(p, v);
  const auto length = static_cast<std::size_t>(end - p);
  if (length <= sizeof e.text) {
    e.bits = bits;
    e.length = static_cast<std::uint32_t>(length);
    std::memcpy(e.text, p, sizeof e.text);  // the bytes past the text are never copied out
  }
  return end;
}

// The most bytes put_value writes for `value` (and may touch past its text). kNumberRoom + 2 and
// its text's size bound it whatever its kind (command_room).
std::size_t value_room(const Value& value) {
  switch (value.kind) {
    case ValueKind::Integer:
    case ValueKind::Numeric: return kNumberRoom;
    case ValueKind::Logical: return 5;
    case ValueKind::Enum: return value.text.size();
    case ValueKind::String: return value.text.size() + 2;
  }
  return 0;
}

// Writes the value at `p`, which has value_room(value) bytes of room. Inline in the parameter loop.
[[gnu::always_inline]] inline char* put_value(char* p, const Value& value, NumberCache* cache) {
  switch (value.kind) {
    case ValueKind::Integer: return put_flag(std::to_chars(p, p + kNumberRoom, value.integer).ptr, value.flag);
    case ValueKind::Numeric: return put_flag(put_number(p, value.numeric, cache), value.flag);
    case ValueKind::Logical: return put_text(p, value.logical ? "true" : "false");
    case ValueKind::Enum: return put_text(p, value.text);
    case ValueKind::String: {
      const char q = value.text.find('\'') == std::string::npos ? '\'' : '"';
      *p++ = q;
      p = put_text(p, value.text);
      *p++ = q;
      return p;
    }
  }
  return p;
}

// At least the bytes put_command writes for `command`: every piece at its largest, and a
// continuation line's head before every parameter (more than the wrapping ever starts). With this
// room known once, the pieces are written through a plain pointer, without a check each. A value
// is given the room of a number and of its text, whatever its kind (no branch on it; a recycled
// numeric slot may keep an old text, which only makes the bound larger).
std::size_t command_room(const Command& command) {
  std::size_t n = 2 + kNumberRoom + command.name.size() + kHeadRoom + 4;
  n += command.parameters.size() * (kHeadRoom + 2 + kNumberRoom + 2);
  for (const auto& p : command.parameters) n += p.name.size() + p.value.text.size();
  for (const auto& t : command.trace) n += kHeadRoom + t.text.size() + 1;
  return n;
}

// Writes `command` at `p`, which has command_room(command) bytes of room; returns the end.
char* put_command(char* p, const Command& command, NumberCache* cache) {
  char* line_start = p;
  *p++ = '(';
  if (command.depth >= 0 && command.depth <= 9) *p++ = static_cast<char>('0' + command.depth);  // nearly every command
  else p = std::to_chars(p, p + kNumberRoom, command.depth).ptr;
  *p++ = ')';
  p = put_text(p, command.name);
  // Long names are written whole, followed by a blank, rather than cut as SolidCAM does: the
  // reader accepts both, and whole names are easier to grep.
  const auto head = static_cast<std::size_t>(p - line_start);
  p = put_blanks(p, head >= kArrowColumn ? 1 : kArrowColumn - head);
  p = put_text(p, "==>");

  std::size_t trace_from = 0;
  bool header_line_taken = false;
  if (!command.trace.empty() && command.trace.front().kind == TraceLine::Kind::Partial) {
    // Unfinished output shares the header line; the parameters then go on continuation lines.
    *p++ = ' ';
    p = put_text(p, command.trace.front().text);
    trace_from = 1;
    header_line_taken = true;
  }
  bool pairs_on_line = false;
  for (const auto& param : command.parameters) {
    if (header_line_taken || (pairs_on_line && static_cast<std::size_t>(p - line_start) > kLineWidth)) {
      *p++ = '\n';
      line_start = p;
      p = put_text(put_blanks(p, kArrowColumn), "..>");
      header_line_taken = false;
    }
    *p++ = ' ';
    p = put_text(p, param.name);
    *p++ = ':';
    p = put_value(p, param.value, cache);
    pairs_on_line = true;
  }
  *p++ = '\n';
  for (std::size_t i = trace_from; i < command.trace.size(); ++i) {
    const TraceLine& t = command.trace[i];
    switch (t.kind) {
      case TraceLine::Kind::Output:
      case TraceLine::Kind::Partial:  // only meaningful first; kept as an output line otherwise
        p = put_text(put_blanks(p, kArrowColumn + 2), "> ");
        break;
      case TraceLine::Kind::Note: p = put_text(put_blanks(p, kArrowColumn), "..> "); break;
      case TraceLine::Kind::Directive: break;
    }
    p = put_text(p, t.text);
    *p++ = '\n';
  }
  return p;
}

// Appends through put: `out` grows by `room` bytes, of which the written ones are kept.
template <class Put>
void append_with(std::string& out, std::size_t room, Put put) {
  const std::size_t used = out.size();
  out.resize(used + room);
  out.resize(static_cast<std::size_t>(put(out.data() + used) - out.data()));
}

}  // namespace

void append_value(std::string& out, const Value& value) {
  append_with(out, value_room(value), [&](char* p) { return put_value(p, value, nullptr); });
}

void append_command(std::string& out, const Command& command) {
  append_with(out, command_room(command), [&](char* p) { return put_command(p, command, nullptr); });
}

void TraceWriter::write(const Command& command) {
  const std::size_t room = command_room(command);
  if (buffer_.size() < used_ + room) buffer_.resize(std::max(buffer_.size() * 2, used_ + room + (1u << 17)));
  used_ = static_cast<std::size_t>(put_command(buffer_.data() + used_, command, &numbers_) - buffer_.data());
  if (used_ > (1u << 17)) flush();
}

void TraceWriter::flush() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(used_));
  used_ = 0;
}

std::size_t write_trace(CommandSource& source, std::ostream& out) {
  TraceWriter writer(out);
  Command command;
  command.keep_name_on_heap();  // sources hand commands over by swapping with it
  std::size_t count = 0;
  while (source.next(command)) {
    writer.write(command);
    ++count;
  }
  writer.flush();
  return count;
}

}  // namespace toolpath
