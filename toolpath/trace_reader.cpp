#include "toolpath/trace_reader.hpp"

#include <array>
#include <cctype>
#include <cstdint>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>

namespace toolpath {
namespace {

constexpr std::size_t kChunk = 1 << 18;

// ASCII character classes, locale-independent (traces are 8-bit text in any code page), from a
// table: the reader classifies every byte of a job.
enum : std::uint8_t { kBlank = 1, kDigit = 2, kIdentStart = 4, kIdentChar = 8 };
constexpr std::array<std::uint8_t, 256> kClasses = [] {
  std::array<std::uint8_t, 256> t{};
  t[' '] = t['\t'] = kBlank;
  for (int c = '0'; c <= '9'; ++c) t[c] = kDigit | kIdentChar;
  for (int c = 'a'; c <= 'z'; ++c) t[c] = kIdentStart | kIdentChar;
  for (int c = 'A'; c <= 'Z'; ++c) t[c] = kIdentStart | kIdentChar;
  t['_'] = kIdentStart | kIdentChar;
  return t;
}();
bool has_class(char c, std::uint8_t cls) { return (kClasses[static_cast<unsigned char>(c)] & cls) != 0; }
bool is_blank(char c) { return has_class(c, kBlank); }
bool is_digit(char c) { return has_class(c, kDigit); }
bool is_ident_start(char c) { return has_class(c, kIdentStart); }
bool is_ident_char(char c) { return has_class(c, kIdentChar); }

std::size_t skip_blanks(std::string_view s, std::size_t i) {
  // SolidCAM pads its traces with runs of spaces: skip them eight at a time.
  while (i + 8 <= s.size() && std::memcmp(s.data() + i, "        ", 8) == 0) i += 8;
  while (i < s.size() && is_blank(s[i])) ++i;
  return i;
}

std::string_view trim_right(std::string_view s) {
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

// Length of an identifier at the start of `s` (0 if none).
std::size_t ident_length(std::string_view s) {
  if (s.empty() || !is_ident_start(s[0])) return 0;
  std::size_t n = 1;
  while (n < s.size() && is_ident_char(s[n])) ++n;
  return n;
}

// The length of the name when `s` starts with `identifier:` (how a name:value pair opens in the
// inline layout), else 0.
std::size_t pair_name_length(std::string_view s) {
  std::size_t n = ident_length(s);
  return n > 0 && n < s.size() && s[n] == ':' ? n : 0;
}
bool starts_with_pair(std::string_view s) { return pair_name_length(s) > 0; }

// Number syntax: [+-] digits [. digits] [e [+-] digits] with at least one digit in the mantissa.
// The scan also collects the mantissa's digits, so that plain decimals need no second pass.
struct NumberScan {
  std::size_t length = 0;  // 0: not a number
  bool numeric = false;    // it has a point or an exponent
  bool exponent = false;
  bool negative = false;
  int digits = 0;          // in the mantissa
  int decimals = 0;        // digits after the point
  std::uint64_t mantissa = 0;  // exact while digits <= 19
};

NumberScan scan_number(std::string_view s) {
  NumberScan n;
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) n.negative = s[i++] == '-';
  auto digit_run = [&](bool after_point) {
    for (; i < s.size() && is_digit(s[i]); ++i) {
      if (++n.digits <= 19) n.mantissa = n.mantissa * 10 + static_cast<std::uint64_t>(s[i] - '0');
      n.decimals += after_point;
    }
  };
  digit_run(false);
  if (i < s.size() && s[i] == '.') {
    n.numeric = true;
    ++i;
    digit_run(true);
  }
  if (n.digits == 0) return n;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    std::size_t exp_start = j;
    while (j < s.size() && is_digit(s[j])) ++j;
    if (j > exp_start) {
      n.numeric = n.exponent = true;
      i = j;
    }
  }
  n.length = i;
  return n;
}

// The exact double of a scanned plain decimal when its mantissa (at most 19 digits) is below 2^53
// and it has at most 22 decimals: mantissa and power of ten are then exact doubles and one
// correctly rounded division gives what from_chars gives (Clinger's fast path). False otherwise.
bool fast_decimal(const NumberScan& n, double& out) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  if (n.exponent || n.digits > 19 || n.mantissa > (std::uint64_t{1} << 53) || n.decimals > 22) return false;
  const double v = static_cast<double>(n.mantissa) / kPow10[n.decimals];
  out = n.negative ? -v : v;
  return true;
}

// Where a value sits, for error messages; cheap to pass (no string copies on the hot path).
struct Place {
  std::string_view file;
  std::size_t line = 0;
  std::size_t column = 0;
  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    throw InputError({std::string(file), line, column + offset}, message);
  }
};

// Parses `text` into `out`, reusing its string buffer.
void parse_value_into(Value& out, std::string_view text, const Place& where) {
  text = trim_right(text);
  out.flag = ChangeFlag::None;
  if (text.empty()) {
    out.kind = ValueKind::String;
    out.text.clear();
    return;
  }
  const char q = text.front();
  if (q == '\'' || q == '"') {
    if (text.size() < 2 || text.back() != q) where.fail(text.size(), std::string("expected closing ") + q + " of the string");
    out.kind = ValueKind::String;
    out.text.assign(text.substr(1, text.size() - 2));
    return;
  }
  if (const NumberScan n = scan_number(text); n.length > 0) {
    std::string_view rest = text.substr(n.length);
    ChangeFlag flag = ChangeFlag::None;
    if (rest == "T" || rest == "t") flag = ChangeFlag::Changed;
    else if (rest == "F" || rest == "f") flag = ChangeFlag::Unchanged;
    if (rest.empty() || flag != ChangeFlag::None) {
      std::string_view digits = text.substr(0, n.length);
      const char* first = digits.data() + (digits.front() == '+' ? 1 : 0);
      const char* last = digits.data() + digits.size();
      out.flag = flag;
      if (!n.numeric) {
        out.kind = ValueKind::Integer;
        if (n.digits <= 18) {  // exact in an int64
          const auto magnitude = static_cast<std::int64_t>(n.mantissa);
          out.integer = n.negative ? -magnitude : magnitude;
          return;
        }
        auto [ptr, ec] = std::from_chars(first, last, out.integer);
        if (ec != std::errc() || ptr != last) where.fail(0, "integer out of range: " + std::string(digits));
        return;
      }
      out.kind = ValueKind::Numeric;
      if (fast_decimal(n, out.numeric)) return;
      auto [ptr, ec] = std::from_chars(first, last, out.numeric);
      if (ec != std::errc() || ptr != last) where.fail(0, "number out of range: " + std::string(digits));
      return;
    }
  }
  if (iequals(text, "true") || iequals(text, "false")) {
    out.kind = ValueKind::Logical;
    out.logical = iequals(text, "true");
    return;
  }
  // A bare word is an enumeration; anything else is free text (user parameters may hold unquoted
  // words with blanks: `Salamat Abzar Check Shavad!!`).
  out.kind = ident_length(text) == text.size() ? ValueKind::Enum : ValueKind::String;
  out.text.assign(text);
}

// The next parameter slot of `out`, reusing the buffers of an earlier command's parameters.
Parameter& add_parameter(Command& out, std::size_t& used, std::string_view name) {
  if (used == out.parameters.size()) out.parameters.emplace_back();
  Parameter& p = out.parameters[used++];
  if (p.name != name) p.rename(name);  // a reused slot usually held the same name
  return p;
}

}  // namespace

Value parse_value(std::string_view text, const SourcePosition& where) {
  Value v;
  parse_value_into(v, text, Place{where.file, where.line, where.column});
  return v;
}

TraceReader::TraceReader(std::istream& in, std::string file_name) : in_(in), file_(std::move(file_name)) {}

TraceReader::~TraceReader() = default;

std::unique_ptr<TraceReader> TraceReader::open(const std::string& path) {
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file) throw InputError({path, 0, 0}, std::string("cannot open file: ") + std::strerror(errno));
  auto reader = std::make_unique<TraceReader>(*file, path);
  reader->owned_ = std::move(file);
  return reader;
}

void TraceReader::fail(std::size_t column, const std::string& message) const {
  throw InputError({file_, line_number_, column}, message);
}

// Reads the next line into line_ (without "\n" or "\r\n"); false at the end of the input.
bool TraceReader::read_line() {
  line_.clear();
  for (;;) {
    if (buffer_pos_ < buffer_.size()) {
      const char* start = buffer_.data() + buffer_pos_;
      const std::size_t avail = buffer_.size() - buffer_pos_;
      if (const void* nl = std::memchr(start, '\n', avail)) {
        const std::size_t len = static_cast<const char*>(nl) - start;
        line_.append(start, len);
        buffer_pos_ += len + 1;
        break;
      }
      line_.append(start, avail);
      buffer_pos_ = buffer_.size();
    }
    if (stream_done_) {
      if (line_.empty()) return false;
      break;  // last line without a trailing newline
    }
    buffer_.resize(kChunk);
    in_.read(buffer_.data(), static_cast<std::streamsize>(kChunk));
    buffer_.resize(static_cast<std::size_t>(in_.gcount()));
    bytes_read_.store(bytes_read_.load(std::memory_order_relaxed) + buffer_.size(), std::memory_order_relaxed);
    buffer_pos_ = 0;
    if (buffer_.empty()) stream_done_ = true;
    if (in_.bad()) fail(1, "read error");
  }
  if (!line_.empty() && line_.back() == '\r') line_.pop_back();
  ++line_number_;
  return true;
}

bool TraceReader::next(Command& out) {
  // Find the header: skip blank lines; anything else before the first header is an error.
  while (!have_line_) {
    if (!read_line()) return false;
    std::size_t i = skip_blanks(line_, 0);
    if (i == line_.size() || line_[i] == ';') continue;
    have_line_ = true;
  }
  // Reset `out` but keep its parameter slots: refilling them in place avoids allocating per command.
  out.name.clear();
  out.depth = 1;
  out.trace.clear();
  used_parameters_ = 0;
  have_line_ = false;
  if (!parse_header(out)) {
    std::size_t col = skip_blanks(line_, 0) + 1;
    fail(col, "expected a command header `(N)@name` or `@name`");
  }
  out.index = next_index_++;
  bool first = true;
  while (read_line()) {
    std::size_t i = skip_blanks(line_, 0);
    if (i == line_.size() || line_[i] == ';') continue;  // blank lines and `;` comments
    std::string_view rest = std::string_view(line_).substr(i);
    if (rest.front() == '@' || (rest.front() == '(' && rest.find(")@") != std::string_view::npos)) {
      have_line_ = true;  // the next command's header
      break;
    }
    parse_body_line(out, first);
    first = false;
  }
  out.parameters.resize(used_parameters_);
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
    auto [p, ec] = std::from_chars(s.data() + start, s.data() + j, number);
    if (ec != std::errc()) fail(i + 2, "number out of range in the command header");
    has_number = true;
    i = j + 1;
  }
  if (i >= s.size() || s[i] != '@') return false;
  std::size_t name_start = i;
  ++i;
  std::size_t n = ident_length(s.substr(i));
  if (n == 0) fail(i + 1, "expected a command name after `@`");
  i += n;
  out.name.assign(s.substr(name_start, i - name_start));
  std::size_t after_name = i;
  i = skip_blanks(s, i);
  if (s.substr(i, 3) == "==>") {
    if (has_number) {
      if (number < 0) fail(number_column, "expected a depth of 0 or more");
      out.depth = static_cast<int>(number);
    }
    name_may_be_cut_ = (i == after_name);  // SolidCAM cuts long names where `==>` begins
    std::size_t text_start = i + 3;
    parse_pairs(out, std::string_view(line_).substr(text_start), text_start + 1, TraceLine::Kind::Partial);
    return true;
  }
  name_may_be_cut_ = false;
  if (i != s.size()) fail(i + 1, "expected `==>` or the end of the line after the command name");
  return true;
}

void TraceReader::parse_body_line(Command& out, bool first_after_header) {
  std::string_view s = line_;
  std::size_t i = skip_blanks(s, 0);

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
  // Block form: `name : value`.
  std::size_t n = ident_length(rest);
  if (n > 0) {
    std::size_t colon = skip_blanks(s, i + n);
    if (colon < s.size() && s[colon] == ':') {
      std::size_t v = skip_blanks(s, colon + 1);
      Parameter& p = add_parameter(out, used_parameters_, rest.substr(0, n));
      parse_value_into(p.value, s.substr(v), Place{file_, line_number_, v + 1});
      return;
    }
    fail(skip_blanks(s, i + n) + 1, "expected `:` after the parameter name `" + std::string(rest.substr(0, n)) + "`");
  }
  fail(i + 1, "expected `name : value`, `..>` continuation, `> ` output line or a command header");
}

// The text after `==>` or `..>`: blank-separated `name:value` pairs, or free text kept as `otherwise`.
void TraceReader::parse_pairs(Command& out, std::string_view text, std::size_t column, TraceLine::Kind otherwise) {
  std::size_t i = skip_blanks(text, 0);
  if (i == text.size()) return;
  if (!starts_with_pair(text.substr(i))) {
    // Free text: the whole remainder without the one separating blank.
    std::string_view kept = text.substr(text.front() == ' ' ? 1 : 0);
    out.trace.push_back({otherwise, std::string(otherwise == TraceLine::Kind::Partial ? kept : trim_right(kept))});
    return;
  }
  std::size_t next_name = 0;  // the length of the name at i, when the previous value's end measured it
  while (i < text.size()) {
    std::size_t n = next_name > 0 ? next_name : ident_length(text.substr(i));
    next_name = 0;
    if (n == 0 || i + n >= text.size() || text[i + n] != ':')
      fail(column + i, "expected `name:value`");
    std::string_view name = text.substr(i, n);
    std::size_t v = i + n + 1;
    std::size_t end = v;
    if (v < text.size() && (text[v] == '\'' || text[v] == '"')) {
      // A quoted value ends at its quote followed by a blank or the end of the line.
      const char q = text[v];
      std::size_t k = v + 1;
      for (;; ++k) {
        k = text.find(q, k);
        if (k == std::string_view::npos) fail(column + text.size(), std::string("expected closing ") + q + " of the string");
        if (k + 1 == text.size() || is_blank(text[k + 1])) break;
      }
      end = k + 1;
    } else {
      // An unquoted value runs to the next ` name:` (it may hold blanks) or the end of the line.
      end = text.size();
      for (std::size_t k = v; k < text.size(); ++k) {
        if (is_blank(text[k])) {
          std::size_t m = skip_blanks(text, k);
          if (std::size_t name_length = pair_name_length(text.substr(m)); name_length > 0) {
            end = k;
            next_name = name_length;  // i will be m: skip_blanks(text, end)
            break;
          }
        }
      }
    }
    Parameter& p = add_parameter(out, used_parameters_, name);
    parse_value_into(p.value, text.substr(v, end - v), Place{file_, line_number_, column + v});
    i = skip_blanks(text, end);
  }
}

}  // namespace toolpath
