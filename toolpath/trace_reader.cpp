#include "toolpath/trace_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>

#include "toolpath/bounded_read.hpp"
#include "toolpath/short_text.hpp"
#include "toolpath/trace_syntax.hpp"

namespace toolpath {

using namespace trace_syntax;

namespace {

constexpr std::size_t kChunk = 1 << 18;
// No trace line comes near this; a longer one (a binary file, a runaway generator) would only
// take memory without bound.
constexpr std::size_t kMaxLine = std::size_t{16} << 20;
// A line holds at most kMaxLine bytes and two chunks more (the carry check comes after a chunk is
// appended): a column always fits the 32 bits a Parameter keeps (parse_pairs stores it as is).
static_assert(kMaxLine + 2 * kChunk < 0xffffffff);

// A line that starts with `(` is a header when `)@` follows somewhere: mostly right after the
// number, `(1)@line`, so that is looked at first.
bool opens_header(std::string_view rest) {
  std::size_t j = 1;
  while (j < rest.size() && is_digit(rest[j])) ++j;
  return rest.substr(j, 2) == ")@" || rest.find(")@") != std::string_view::npos;
}

// A line (from its first byte that is not a blank) that starts a command: `@name`, `(N)@name`.
bool starts_command(std::string_view rest) { return rest.front() == '@' || (rest.front() == '(' && opens_header(rest)); }

// Whether a command name (`@` and identifier bytes) is @arc, @line or @rapid_move in any case, the
// motions the skim leaves out, without a call. OR 0x20 makes letters lower case and leaves digits
// alone; `@` and `_` become bytes no identifier has, the same on both sides.
bool is_skimmed_motion(std::string_view n) {
  constexpr std::uint64_t fold = 0x2020202020202020;
  constexpr std::string_view arc = "@arc", line = "@line", rapid = "@rapid_move";
  switch (n.size()) {
    case 4: return (load_word(n, 0, 4) | fold) == (load_word(arc, 0, 4) | fold);
    case 5: return (load_word(n, 0, 5) | fold) == (load_word(line, 0, 5) | fold);
    case 11:
      return (load_word(n, 0, 8) | fold) == (load_word(rapid, 0, 8) | fold) &&
             (load_word(n, 3, 8) | fold) == (load_word(rapid, 3, 8) | fold);
    default: return false;
  }
}

}  // namespace

TraceReader::TraceReader(std::istream& in, std::string file_name)
    : in_(in), file_(std::move(file_name)), memos_(std::make_unique<KeyMemo[]>(param_key_count + 1)) {}

TraceReader::~TraceReader() = default;

std::unique_ptr<TraceReader> TraceReader::open(const std::string& path) {
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file) throw InputError({path, 0, 0}, std::string("cannot open file: ") + std::strerror(errno));
  auto reader = std::make_unique<TraceReader>(*file, path);
  reader->owned_ = std::move(file);
  return reader;
}

void TraceReader::screen_values(const ValueScreen* by_key) {
  for (std::size_t k = 0; k <= param_key_count; ++k) {
    memos_[k] = KeyMemo{};  // kept verdicts were by other screens
    memos_[k].screen = by_key[k];
  }
  screening_ = true;
}

void TraceReader::fail(std::size_t column, const std::string& message) const {
  throw InputError({file_, line_number_, column}, message);
}

// Points line_ at the next line (without "\n" or "\r\n"), inside the chunk when the line is
// whole there, else in carry_; false at the end of the input.
bool TraceReader::read_line() {
  carry_.clear();
  header_ahead_ = false;
  for (;;) {
    if (buffer_pos_ < buffer_.size()) {
      const char* start = buffer_.data() + buffer_pos_;
      const std::size_t avail = buffer_.size() - buffer_pos_;
      if (const void* nl = std::memchr(start, '\n', avail)) {
        const std::size_t len = static_cast<const char*>(nl) - start;
        buffer_pos_ += len + 1;
        if (carry_.empty()) {
          line_ = {start, len};
        } else {
          carry_.append(start, len);
          line_ = carry_;
        }
        break;
      }
      carry_.append(start, avail);  // the line goes on in the next chunk
      if (carry_.size() > kMaxLine) {
        ++line_number_;
        fail(1, "line longer than 16 MiB: not a trace file?");
      }
      buffer_pos_ = buffer_.size();
    }
    if (stream_done_) {
      if (carry_.empty()) return false;
      line_ = carry_;  // last line without a trailing newline
      break;
    }
    buffer_.resize(kChunk);
    in_.read(buffer_.data(), static_cast<std::streamsize>(kChunk));
    buffer_.resize(static_cast<std::size_t>(in_.gcount()));
    bytes_read_.store(bytes_read_.load(std::memory_order_relaxed) + buffer_.size(), std::memory_order_relaxed);
    buffer_pos_ = 0;
    if (buffer_.empty()) stream_done_ = true;
    if (in_.bad()) fail(1, "read error");
  }
  if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
  count_lines(1);
  return true;
}

// The fast path. Most lines of a job are a header `(N)@name   ==> pairs` or a continuation
// `   ..> pairs` whose pairs the common run reads (trace_pairs.cpp) whole, and a header or
// continuation line is recognised from its first bytes. The fast path reads such lines straight
// from the chunk, where a line ends at its '\n' and the chunk at the string's '\0', so the line
// end is found by the scan itself instead of a memchr pass before it. It touches only what the
// general rule sets again when it reads the same line: on anything else (a line cut by the end of
// the chunk, a value the run does not take, free text, a blank line) it leaves the line unread
// and the general rule reads it from its start, the same way with or without the fast path.

// The unread line starts with `(digits)@`: a header (also by the general rule, opens_header).
// Known until the reader moves: the body loop asks before it stops, next() again after.
bool TraceReader::header_ahead() {
  if (header_ahead_) return true;
  const char* p = buffer_.data() + buffer_pos_;  // at the chunk's end: its '\0'
  if (*p != '(' || general_only_) return false;
  const char* const digits = ++p;
  while (is_digit(*p)) ++p;
  header_ahead_ = p != digits && p[0] == ')' && p[1] == '@';  // p[1]: at most the '\0'
  return header_ahead_;
}

// A header `(N)@name   ==> pairs` (header_ahead() holds), N of at most nine digits, and the
// continuation lines after it (fast_lines): the number of lines taken, 0 when the general rule
// reads the header.
std::size_t TraceReader::fast_header(Command& out) {
  const char* const line = buffer_.data() + buffer_pos_;
  const char* p = line + 1;
  unsigned depth = 0;  // wraps harmlessly past nine digits: the general rule reads those
  while (is_digit(*p)) depth = depth * 10 + static_cast<unsigned>(*p++ - '0');
  if (p - line > 10 || !is_ident_start(p[2])) return 0;
  const char* const name = p + 1;
  p += 3;
  while (is_ident_char(*p)) ++p;
  shelf_.rename(out, {name, static_cast<std::size_t>(p - name)});
  const char* const after_name = p;
  p = skip_terminated_blanks(p, buffer_.data() + buffer_.size());
  if (p[0] != '=' || p[1] != '=' || p[2] != '>') return 0;  // each read only after the one before matched
  // Set for the general rule as well when it reads the header again: it sets both the same way.
  out.depth = static_cast<int>(depth);
  name_may_be_cut_ = p == after_name;
  return fast_lines(out, p + 3, line);
}

// Continuation lines `   ..> pairs` (fast_lines): whether it took one.
bool TraceReader::fast_continuation(Command& out) {
  if (general_only_) return false;
  const char* const line = buffer_.data() + buffer_pos_;
  const char* const p = skip_terminated_blanks(line, buffer_.data() + buffer_.size());
  if (p[0] != '.' || p[1] != '.' || p[2] != '>') return false;  // each read only after the one before matched
  return fast_lines(out, p + 3, line) > 0;
}

// Resets `out` but keeps its parameter slots: refilling them in place avoids allocating per command.
void TraceReader::begin_command(Command& out) {
  out.depth = 1;  // out.name: still the name of what out's parameters last held (see parse_header)
  out.trace.clear();
  used_parameters_ = 0;
  screen_passed_ = true;
  screen_need_ = 0;
  have_line_ = false;
}

// skim_job_motions(): a basic motion inside a job (after its opening tool changes), or any command
// deeper than the stream, whose header has the level-5 layout `(depth)@name   ==>` (the name cannot
// go on below). Any other header is kept and read in full, which is always right.
bool TraceReader::skipped_in_skim(std::string_view h) const {
  // The line end ('\n', '\r' or '\0') follows h in memory: the scans stop there.
  const char* p = h.data();
  const char* const end = p + h.size();
  if (h.size() >= 16) {
    // SolidCAM's own spelling, `(1)@line` and a blank, told by whole words; any other spelling
    // (another depth, case or padding) is read below.
    constexpr std::string_view line = "(1)@line", arc = "(1)@arc ", rapid = "(1)@rapid_move ";
    const std::uint64_t head = load_word(h, 0, 8);
    const char* after = nullptr;
    if (head == load_word(line, 0, 8) && p[8] == ' ') after = p + 8;
    else if (head == load_word(arc, 0, 8)) after = p + 7;
    else if (head == load_word(rapid, 0, 8) && load_word(h, 8, 7) == load_word(rapid, 8, 7)) after = p + 14;
    if (after) {
      const char* q = skip_terminated_blanks(after, end);
      return end - q >= 3 && q[0] == '=' && q[1] == '=' && q[2] == '>' && in_job_ && !job_leading_;
    }
  }
  if (*p != '(') return false;
  const char* const digits = ++p;
  unsigned depth = 0;
  while (is_digit(*p) && p - digits < 9) depth = depth * 10 + static_cast<unsigned>(*p++ - '0');
  if (p == digits || p[0] != ')' || p[1] != '@') return false;  // p[1]: at most the line end
  const char* const name = p + 1;
  p += 2;
  while (is_ident_char(*p)) ++p;
  const char* const after_name = p;
  p = skip_terminated_blanks(p, end);
  if (p == after_name || end - p < 3 || p[0] != '=' || p[1] != '=' || p[2] != '>') return false;
  if (depth >= 2) return true;
  if (!in_job_ || job_leading_) return false;
  return is_skimmed_motion({name, static_cast<std::size_t>(after_name - name)});
}

// The skim's fast path: whole lines of the chunk that it leaves out, straight from the chunk. A
// line that is not a header (the first byte after its blanks is neither `@` nor `(`) belongs to a
// skipped command; a header is read as skipped_in_skim reads it. It stops before a line that
// goes on in the next chunk, a header to keep, and anything else the general loop must look at.
void TraceReader::skip_in_chunk() {
  const char* p = buffer_.data() + buffer_pos_;
  const char* const end = buffer_.data() + buffer_.size();
  std::size_t lines = 0, skipped = 0;
  for (;;) {
    const char* const nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (!nl) break;
    const char* q = skip_terminated_blanks(p, nl);
    if (*q == '(' && q == p) {
      if (!skipped_in_skim({p, static_cast<std::size_t>(nl - p)})) break;
      ++skipped;
    } else if (*q == '(' || *q == '@') {
      break;
    }
    ++lines;
    p = nl + 1;
  }
  if (lines == 0) return;
  take_lines(p, lines);
  next_index_ += skipped;
}

// Puts the header of the next command a skim keeps in line_ (have_line_), counting the ones it
// skips; false at the end of the input.
bool TraceReader::skim_to_kept_header() {
  for (;; have_line_ = false) {
    if (!have_line_ && seen_header_) skip_in_chunk();
    if (!have_line_ && !read_line()) return false;
    const std::size_t i = skip_blanks(line_, 0);
    if (i == line_.size() || line_[i] == ';') continue;
    const std::string_view rest = line_.substr(i);
    if (!starts_command(rest)) {
      if (seen_header_) continue;  // a line of a skipped command (a kept one reads its own)
      have_line_ = true;           // before the first header: the general rule says what is wrong
      return true;
    }
    seen_header_ = true;
    if (!skipped_in_skim(rest)) {
      have_line_ = true;
      return true;
    }
    ++next_index_;
  }
}

// Where a kept command leaves the skim: in a job or not, and whether the job's opening tool
// changes go on (procedure generation keeps those with the main program).
void TraceReader::follow_job(const Command& kept) {
  if (!kept.is_stream_command()) return;
  const std::string_view n = kept.name;
  if (iequals(n, "@start_of_job")) {
    in_job_ = job_leading_ = true;
  } else if (iequals(n, "@end_of_job")) {
    in_job_ = job_leading_ = false;
  } else if (!iequals(n, "@change_tool") && !iequals(n, "@turn_change_tool") && !iequals(n, "@chng_tool_cnext")) {
    job_leading_ = false;
  }
}

bool TraceReader::next(Command& out) {
  if (skim_ && !skim_to_kept_header()) return false;
  const bool fresh = out.parameters.capacity() == 0;
  std::size_t fast = 0;  // lines the fast path took, the header first
  if (!have_line_ && header_ahead()) {
    begin_command(out);
    out.line = next_line32();
    fast = fast_header(out);
    if (fast == 0) have_line_ = read_line();  // the general rule reads it again (the chunk holds it)
  }
  const bool header_read = fast > 0;
  if (!header_read) {
    // Find the header: skip blank lines; anything else before the first header is an error.
    while (!have_line_) {
      if (!read_line()) return false;
      std::size_t i = skip_blanks(line_, 0);
      if (i == line_.size() || line_[i] == ';') continue;
      have_line_ = true;
    }
    begin_command(out);
    if (!parse_header(out)) {
      std::size_t col = skip_blanks(line_, 0) + 1;
      fail(col, "expected a command header `(N)@name` or `@name`");
    }
    out.line = line32_;
  }
  out.index = next_index_++;
  bool first = fast <= 1;  // the next line is the first after the header
  for (;;) {
    if (header_ahead()) break;  // the next command's, read by the next call
    if (fast_continuation(out)) {
      first = false;
      continue;
    }
    if (!read_line()) break;
    std::size_t i = skip_blanks(line_, 0);
    if (i == line_.size() || line_[i] == ';') continue;  // blank lines and `;` comments
    std::string_view rest = line_.substr(i);
    if (starts_command(rest)) {
      have_line_ = true;  // the next command's header
      break;
    }
    parse_body_line(out, first, i);
    first = false;
  }
  out.parameters.resize(used_parameters_);
  if (fresh) shelf_.keep(out);
  if (skim_) follow_job(out);
  return true;
}

// `(N)@name` [blanks] [`==>` pairs]. In the inline layout N is the depth; in the block form it is
// the command's sequence number, which the reader recomputes from the position.
bool TraceReader::parse_header(Command& out) {
  std::string_view s = line_;
  std::size_t i = skip_blanks(s, 0);
  bool has_number = false;
  long number = 1;
  std::size_t number_column = i + 2;
  if (i < s.size() && s[i] == '(') {
    std::size_t j = i + 1;
    std::size_t start = j;
    if (j < s.size() && s[j] == '-') ++j;
    while (j < s.size() && is_digit(s[j])) ++j;
    if (j == start || j >= s.size() || s[j] != ')') fail(i + 2, "expected a number and `)` in the command header");
    const bool negative = s[start] == '-';
    const std::size_t digits = j - start - negative;
    if (digits > 0 && digits <= std::numeric_limits<long>::digits10) {  // no from_chars call for `(1)`
      number = 0;
      for (std::size_t d = start + negative; d < j; ++d) number = number * 10 + (s[d] - '0');
      if (negative) number = -number;
    } else {
      auto [p, ec] = std::from_chars(s.data() + start, s.data() + j, number);
      if (ec != std::errc()) fail(i + 2, "number out of range in the command header");
    }
    has_number = true;
    i = j + 1;
  }
  if (i >= s.size() || s[i] != '@') return false;
  std::size_t name_start = i;
  ++i;
  std::size_t n = ident_length(s.substr(i));
  if (n == 0) fail(i + 1, "expected a command name after `@`");
  i += n;
  shelf_.rename(out, s.substr(name_start, i - name_start));
  std::size_t after_name = i;
  i = skip_blanks(s, i);
  if (s.substr(i, 3) == "==>") {
    if (has_number) {
      if (number < 0) fail(number_column, "expected a depth of 0 or more");
      out.depth = static_cast<int>(number);
    }
    name_may_be_cut_ = (i == after_name);  // SolidCAM cuts long names where `==>` begins
    std::size_t text_start = i + 3;
    parse_pairs(out, line_.substr(text_start), text_start + 1, TraceLine::Kind::Partial);
    return true;
  }
  name_may_be_cut_ = false;
  if (i != s.size()) fail(i + 1, "expected `==>` or the end of the line after the command name");
  return true;
}

// `i`: the first byte of line_ that is not a blank.
void TraceReader::parse_body_line(Command& out, bool first_after_header, std::size_t i) {
  std::string_view s = line_;

  // A cut name continues at column 4 of the next line: `   ut                 > N290 S1910`.
  if (first_after_header && name_may_be_cut_ && i == 3 && is_ident_char(s[i])) {
    std::size_t j = i;
    while (j < s.size() && is_ident_char(s[j])) ++j;
    std::size_t k = skip_blanks(s, j);
    if (k == s.size() || s[k] == '>' || s.substr(k, 3) == "..>") {
      out.name.append(s.substr(i, j - i));
      if (k == s.size()) return;
      i = k;
    }
  }

  std::string_view rest = s.substr(i);
  if (rest.substr(0, 3) == "..>") {
    std::size_t text_start = i + 3;
    parse_pairs(out, s.substr(text_start), text_start + 1, TraceLine::Kind::Note);
    return;
  }
  if (rest.front() == '>' && (rest.size() == 1 || rest[1] == ' ')) {
    out.trace.push_back({TraceLine::Kind::Output, std::string(rest.size() > 1 ? rest.substr(2) : std::string_view{})});
    return;
  }
  if (rest.substr(0, 2) == "!!") {
    out.trace.push_back({TraceLine::Kind::Directive, std::string(trim_right(rest))});
    return;
  }
  // Block form: `name : value` (`name<<i>> : value` for an array element).
  std::size_t n = parameter_name_length(rest);
  if (n > 0) {
    std::size_t colon = skip_blanks(s, i + n);
    if (colon < s.size() && s[colon] == ':') {
      std::size_t v = skip_blanks(s, colon + 1);
      screen_passed_ = false;
      Parameter& p = add_parameter(out, used_parameters_, rest.substr(0, n));
      mark_position(p, line_number_, v + 1);
      parse_value_into(p.value, s.substr(v), Place{file_, line_number_, v + 1});
      return;
    }
    fail(skip_blanks(s, i + n) + 1, "expected `:` after the parameter name `" + excerpt(rest.substr(0, n)) + "`");
  }
  fail(i + 1, "expected `name : value`, `..>` continuation, `> ` output line or a command header");
}

}  // namespace toolpath
