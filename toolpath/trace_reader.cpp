#include "toolpath/trace_reader.hpp"

#include <array>
#include <cctype>
#include <cstdint>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <limits>

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
  // Mostly one blank or none; SolidCAM pads with runs of spaces: skip those eight at a time.
  while (i < s.size() && is_blank(s[i])) {
    if (i + 8 <= s.size() && std::memcmp(s.data() + i, "        ", 8) == 0) i += 8;
    else ++i;
  }
  return i;
}

std::string_view trim_right(std::string_view s) {
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

// Length of an identifier at the start of `s` (0 if none).
std::size_t ident_length(std::string_view s) {
  if (s.empty() || !is_ident_start(s[0])) return 0;
  const char* p = s.data() + 1;
  const char* const end = s.data() + s.size();
  while (p < end && is_ident_char(*p)) ++p;
  return static_cast<std::size_t>(p - s.data());
}

// The length of the name when `s` starts with `identifier:` (how a name:value pair opens in the
// inline layout), else 0.
std::size_t pair_name_length(std::string_view s) {
  std::size_t n = ident_length(s);
  return n > 0 && n < s.size() && s[n] == ':' ? n : 0;
}

// Number syntax: [+-] digits [. digits] [e [+-] digits] with at least one digit in the mantissa.
// The scan also collects the mantissa's digits, so that plain decimals need no second pass.
struct NumberScan {
  std::size_t length = 0;  // 0: not a number
  bool numeric = false;    // it has a point or an exponent
  bool exponent = false;
  bool negative = false;
  int digits = 0;          // in the mantissa
  int decimals = 0;        // digits after the point
  std::uint64_t mantissa = 0;  // exact while digits <= 19 (wrapped past that)
};

NumberScan scan_number(std::string_view s) {
  NumberScan n;
  const char* p = s.data();
  const char* const end = p + s.size();
  if (p < end && (*p == '+' || *p == '-')) n.negative = *p++ == '-';
  // Digits accumulate without a bound check: the mantissa is used only when digits <= 19.
  std::uint64_t mantissa = 0;
  unsigned d = 0;
  const char* start = p;
  while (p < end && (d = static_cast<unsigned char>(*p) - unsigned{'0'}) <= 9) mantissa = mantissa * 10 + d, ++p;
  int digits = static_cast<int>(p - start);
  if (p < end && *p == '.') {
    n.numeric = true;
    start = ++p;
    while (p < end && (d = static_cast<unsigned char>(*p) - unsigned{'0'}) <= 9) mantissa = mantissa * 10 + d, ++p;
    n.decimals = static_cast<int>(p - start);
    digits += n.decimals;
  }
  n.digits = digits;
  n.mantissa = mantissa;
  if (digits == 0) return n;
  if (p < end && (*p == 'e' || *p == 'E')) {
    const char* q = p + 1;
    if (q < end && (*q == '+' || *q == '-')) ++q;
    const char* exp_start = q;
    while (q < end && is_digit(*q)) ++q;
    if (q > exp_start) {
      n.numeric = n.exponent = true;
      p = q;
    }
  }
  n.length = static_cast<std::size_t>(p - s.data());
  return n;
}

// Where an unquoted inline value that starts at `v` ends: at the blanks before the next
// `name:` (whose name length goes to `next_name`), else at the end of the line. It may hold blanks.
std::size_t value_end(std::string_view text, std::size_t v, std::size_t& next_name) {
  for (std::size_t k = v; k < text.size(); ++k) {
    if (is_blank(text[k])) {
      const std::size_t m = skip_blanks(text, k);
      if (const std::size_t name_length = pair_name_length(text.substr(m)); name_length > 0) {
        next_name = name_length;  // the caller's next pair starts at m = skip_blanks(text, k)
        return k;
      }
      k = m - 1;
    }
  }
  next_name = 0;
  return text.size();
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

// The change flag written right after a number (`10T`, `10F`); None for anything else.
ChangeFlag flag_letter(char c) {
  switch (c) {
    case 'T': case 't': return ChangeFlag::Changed;
    case 'F': case 'f': return ChangeFlag::Unchanged;
    default: return ChangeFlag::None;
  }
}

// Stores a scanned number that needs no from_chars (an integer of up to 18 digits, or a decimal
// fast_decimal takes) into `out`; false, and `out` untouched, for any other.
bool store_exact_number(Value& out, const NumberScan& n, ChangeFlag flag) {
  if (!n.numeric) {
    if (n.digits > 18) return false;
    const auto magnitude = static_cast<std::int64_t>(n.mantissa);  // exact in an int64
    out.kind = ValueKind::Integer;
    out.integer = n.negative ? -magnitude : magnitude;
  } else {
    double v;
    if (!fast_decimal(n, v)) return false;
    out.kind = ValueKind::Numeric;
    out.numeric = v;
  }
  out.flag = flag;
  return true;
}

// Stores the scanned number `digits` (its text, without the flag) into `out`.
void store_number(Value& out, const NumberScan& n, std::string_view digits, ChangeFlag flag, const Place& where) {
  if (store_exact_number(out, n, flag)) return;
  const char* first = digits.data() + (digits.front() == '+' ? 1 : 0);
  const char* last = digits.data() + digits.size();
  out.flag = flag;
  if (!n.numeric) {
    out.kind = ValueKind::Integer;
    auto [ptr, ec] = std::from_chars(first, last, out.integer);
    if (ec != std::errc() || ptr != last) where.fail(0, "integer out of range: " + std::string(digits));
    return;
  }
  out.kind = ValueKind::Numeric;
  auto [ptr, ec] = std::from_chars(first, last, out.numeric);
  if (ec != std::errc() || ptr != last) where.fail(0, "number out of range: " + std::string(digits));
}

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
    const std::size_t rest = text.size() - n.length;  // a number, alone or with its change flag
    const ChangeFlag flag = rest == 1 ? flag_letter(text.back()) : ChangeFlag::None;
    if (rest == 0 || flag != ChangeFlag::None) return store_number(out, n, text.substr(0, n.length), flag, where);
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

// Case-sensitive equality of short names without a call to memcmp: words of 8 or 4 bytes, the
// last one overlapping the one before.
bool same_bytes(std::string_view a, std::string_view b) {
  const std::size_t n = a.size();
  if (n != b.size()) return false;
  const char *p = a.data(), *q = b.data();
  auto differ = [](const char* x, const char* y, auto word) {
    decltype(word) u, v;
    std::memcpy(&u, x, sizeof u);
    std::memcpy(&v, y, sizeof v);
    return u != v;
  };
  if (n >= 8) {
    for (std::size_t i = 0; i + 8 < n; i += 8)
      if (differ(p + i, q + i, std::uint64_t{})) return false;
    return !differ(p + n - 8, q + n - 8, std::uint64_t{});
  }
  if (n >= 4) return !differ(p, q, std::uint32_t{}) && !differ(p + n - 4, q + n - 4, std::uint32_t{});
  for (std::size_t i = 0; i < n; ++i)
    if (p[i] != q[i]) return false;
  return true;
}

[[gnu::noinline]] Parameter& new_slot(Command& out, std::size_t& used, std::string_view name) {
  if (used == out.parameters.size()) out.parameters.emplace_back();
  Parameter& p = out.parameters[used++];
  p.rename(name);
  return p;
}

// The next parameter slot of `out`, reusing the buffers of an earlier command's parameters. A
// reused slot often held the same name: then nothing is copied and the key stays.
Parameter& add_parameter(Command& out, std::size_t& used, std::string_view name) {
  if (used < out.parameters.size() && same_bytes(out.parameters[used].name, name)) return out.parameters[used++];
  return new_slot(out, used, name);
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

// Points line_ at the next line (without "\n" or "\r\n"), inside the chunk when the line is
// whole there, else in carry_; false at the end of the input.
bool TraceReader::read_line() {
  carry_.clear();
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
    std::string_view rest = line_.substr(i);
    if (rest.front() == '@' || (rest.front() == '(' && rest.find(")@") != std::string_view::npos)) {
      have_line_ = true;  // the next command's header
      break;
    }
    parse_body_line(out, first, i);
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

// The length of the `name:` that starts at `at` in `text` (0 if there is none), for the pair that
// will fill parameter slot `slot` of `out`. A recycled command mostly repeats the names of the
// one before in order, so the slot's name is tried first: a keyed name is a known identifier, and
// followed by `:` it is the whole name there.
std::size_t TraceReader::pair_name_at(const Command& out, std::size_t slot, std::string_view text, std::size_t at) const {
  if (slot < out.parameters.size()) {
    const Parameter& p = out.parameters[slot];
    const std::size_t n = p.name.size();
    if (p.key != ParamKey::none && at + n < text.size() && text[at + n] == ':' && same_bytes(text.substr(at, n), p.name))
      return n;
  }
  return pair_name_length(text.substr(at));
}

// The text after `==>` or `..>`: blank-separated `name:value` pairs, or free text kept as `otherwise`.
void TraceReader::parse_pairs(Command& out, std::string_view text, std::size_t column, TraceLine::Kind otherwise) {
  std::size_t i = skip_blanks(text, 0);
  if (i == text.size()) return;
  std::size_t next_name = pair_name_at(out, used_parameters_, text, i);  // the length of the name at i, once measured
  if (next_name == 0) {
    // Free text: the whole remainder without the one separating blank.
    std::string_view kept = text.substr(text.front() == ' ' ? 1 : 0);
    out.trace.push_back({otherwise, std::string(otherwise == TraceLine::Kind::Partial ? kept : trim_right(kept))});
    return;
  }
  while (i < text.size()) {
    std::size_t n = next_name > 0 ? next_name : pair_name_at(out, used_parameters_, text, i);
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
    } else if (const NumberScan number = scan_number(text.substr(v)); number.length > 0) {
      // The common case, a number (with its change flag) then blanks and the next `name:` or the
      // end of the line: stored at once. Anything else after the digits takes the general path.
      std::size_t k = v + number.length;
      const ChangeFlag flag = k < text.size() ? flag_letter(text[k]) : ChangeFlag::None;
      if (flag != ChangeFlag::None) ++k;
      if (k == text.size() || is_blank(text[k])) {
        std::size_t m = k == text.size() ? k : k + 1;
        if (m < text.size() && is_blank(text[m])) m = skip_blanks(text, m);
        next_name = m == text.size() ? 0 : pair_name_at(out, used_parameters_ + 1, text, m);
        if (m == text.size() || next_name > 0) {
          Value& value = add_parameter(out, used_parameters_, name).value;
          if (!store_exact_number(value, number, flag))
            store_number(value, number, text.substr(v, number.length), flag, Place{file_, line_number_, column + v});
          i = m;
          continue;
        }
      }
      end = value_end(text, v, next_name);
    } else {
      end = value_end(text, v, next_name);
    }
    Parameter& p = add_parameter(out, used_parameters_, name);
    parse_value_into(p.value, text.substr(v, end - v), Place{file_, line_number_, column + v});
    i = skip_blanks(text, end);
  }
}

}  // namespace toolpath
