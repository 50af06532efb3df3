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
void copy_short(char* to, const char* from, std::size_t n) {
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

// Text appended through a cursor into a string kept larger than what is written: one capacity
// check per piece instead of one per character, no formatting library on the way. The string
// holds `used` bytes of text; the rest is room, cut off by the owner when it is done.
class Cursor {
public:
  Cursor(std::string& s, std::size_t used) : s_(s) {
    if (s_.size() < used + 256) s_.resize(used + 256);
    p_ = s_.data() + used;
    end_ = s_.data() + s_.size();
  }
  std::size_t used() const { return static_cast<std::size_t>(p_ - s_.data()); }
  // At least n bytes of room at the cursor.
  void room(std::size_t n) {
    if (static_cast<std::size_t>(end_ - p_) < n) grow(n);
  }
  void put(char c) { *p_++ = c; }  // after room()
  void text(std::string_view t) {
    room(t.size());
    copy_short(p_, t.data(), t.size());
    p_ += t.size();
  }
  void blanks(std::size_t n) {
    room(n);
    std::memset(p_, ' ', n);
    p_ += n;
  }
  char*& at() { return p_; }

private:
  void grow(std::size_t n) {
    const std::size_t u = used();
    s_.resize(std::max(s_.size() * 2, u + n + 256));
    p_ = s_.data() + u;
    end_ = s_.data() + s_.size();
  }
  std::string& s_;
  char* p_;
  char* end_;
};

void put_flag(Cursor& out, ChangeFlag flag) {  // after room()
  if (flag == ChangeFlag::Changed) out.put('T');
  if (flag == ChangeFlag::Unchanged) out.put('F');
}

// Writes a numeric value, through the cache when there is one.
void put_number(Cursor& out, double v, NumberCache* cache) {
  if (!cache) {
    out.at() = write_number_text(out.at(), v);
    return;
  }
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
  NumberCache::Entry& e = cache->entries[(bits * 0x9E3779B97F4A7C15u) >> 58];
  if (e.length > 0 && e.bits == bits) {
    std::memcpy(out.at(), e.text, sizeof e.text);  // the room is there: kNumberRoom
    out.at() += e.length;
    return;
  }
  char* const start = out.at();
  out.at() = write_number_text(start, v);
  const auto length = static_cast<std::size_t>(out.at() - start);
  if (length <= sizeof e.text) {
    e.bits = bits;
    e.length = static_cast<std::uint32_t>(length);
    std::memcpy(e.text, start, sizeof e.text);  // the bytes past the text are never copied out
  }
}

void put_value(Cursor& out, const Value& value, NumberCache* cache) {
  switch (value.kind) {
    case ValueKind::Integer:
      out.room(kNumberRoom);
      out.at() = std::to_chars(out.at(), out.at() + kNumberRoom, value.integer).ptr;
      put_flag(out, value.flag);
      break;
    case ValueKind::Numeric:
      out.room(kNumberRoom);
      put_number(out, value.numeric, cache);
      put_flag(out, value.flag);
      break;
    case ValueKind::Logical: out.text(value.logical ? "true" : "false"); break;
    case ValueKind::Enum: out.text(value.text); break;
    case ValueKind::String: {
      const char q = value.text.find('\'') == std::string::npos ? '\'' : '"';
      out.room(value.text.size() + 2);
      out.put(q);
      out.text(value.text);
      out.put(q);
      break;
    }
  }
}

void put_command(Cursor& out, const Command& command, NumberCache* cache) {
  std::size_t line_start = out.used();
  out.room(kNumberRoom + 1);
  out.put('(');
  out.at() = std::to_chars(out.at(), out.at() + kNumberRoom, command.depth).ptr;
  out.put(')');
  out.text(command.name);
  // Long names are written whole, followed by a blank, rather than cut as SolidCAM does: the
  // reader accepts both, and whole names are easier to grep.
  const std::size_t head = out.used() - line_start;
  out.blanks(head >= kArrowColumn ? 1 : kArrowColumn - head);
  out.text("==>");

  std::size_t trace_from = 0;
  bool header_line_taken = false;
  if (!command.trace.empty() && command.trace.front().kind == TraceLine::Kind::Partial) {
    // Unfinished output shares the header line; the parameters then go on continuation lines.
    out.blanks(1);
    out.text(command.trace.front().text);
    trace_from = 1;
    header_line_taken = true;
  }
  std::size_t pairs_on_line = 0;
  for (const auto& p : command.parameters) {
    if (header_line_taken || (pairs_on_line > 0 && out.used() - line_start > kLineWidth)) {
      out.room(kArrowColumn + 4);
      out.put('\n');
      line_start = out.used();
      out.blanks(kArrowColumn);
      out.text("..>");
      pairs_on_line = 0;
      header_line_taken = false;
    }
    out.room(p.name.size() + 2 + kNumberRoom);  // numbers, the most common values, need no other check
    out.put(' ');
    out.text(p.name);
    out.put(':');
    put_value(out, p.value, cache);
    ++pairs_on_line;
  }
  out.room(1);
  out.put('\n');
  for (std::size_t i = trace_from; i < command.trace.size(); ++i) {
    const TraceLine& t = command.trace[i];
    switch (t.kind) {
      case TraceLine::Kind::Output:
      case TraceLine::Kind::Partial:  // only meaningful first; kept as an output line otherwise
        out.blanks(kArrowColumn + 2);
        out.text("> ");
        break;
      case TraceLine::Kind::Note:
        out.blanks(kArrowColumn);
        out.text("..> ");
        break;
      case TraceLine::Kind::Directive: break;
    }
    out.text(t.text);
    out.room(1);
    out.put('\n');
  }
}

}  // namespace

void append_value(std::string& out, const Value& value) {
  Cursor c(out, out.size());
  put_value(c, value, nullptr);
  out.resize(c.used());
}

void append_command(std::string& out, const Command& command) {
  Cursor c(out, out.size());
  put_command(c, command, nullptr);
  out.resize(c.used());
}

void TraceWriter::write(const Command& command) {
  Cursor c(buffer_, used_);
  put_command(c, command, &numbers_);
  used_ = c.used();
  if (used_ > (1u << 17)) flush();
}

void TraceWriter::flush() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(used_));
  used_ = 0;
}

std::size_t write_trace(CommandSource& source, std::ostream& out) {
  TraceWriter writer(out);
  Command command;
  std::size_t count = 0;
  while (source.next(command)) {
    writer.write(command);
    ++count;
  }
  writer.flush();
  return count;
}

}  // namespace toolpath
