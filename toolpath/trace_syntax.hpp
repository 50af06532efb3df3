// The lexical pieces of the `.trace` format shared by the reader (trace_reader.cpp) and the value
// parser (trace_value.cpp): character classes, names, numbers. Internal to the toolpath library;
// inline because the reader runs them on every byte of a job.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "toolpath/command.hpp"
#include "toolpath/error.hpp"
#include "toolpath/short_text.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/value.hpp"

namespace toolpath::trace_syntax {

// ASCII character classes, locale-independent (traces are 8-bit text in any code page), from a
// table: the reader classifies every byte of a job.
enum : std::uint8_t { kBlank = 1, kDigit = 2, kIdentStart = 4, kIdentChar = 8 };
inline constexpr std::array<std::uint8_t, 256> kClasses = [] {
  std::array<std::uint8_t, 256> t{};
  t[' '] = t['\t'] = kBlank;
  for (int c = '0'; c <= '9'; ++c) t[c] = kDigit | kIdentChar;
  for (int c = 'a'; c <= 'z'; ++c) t[c] = kIdentStart | kIdentChar;
  for (int c = 'A'; c <= 'Z'; ++c) t[c] = kIdentStart | kIdentChar;
  t['_'] = kIdentStart | kIdentChar;
  return t;
}();
inline bool has_class(char c, std::uint8_t cls) { return (kClasses[static_cast<unsigned char>(c)] & cls) != 0; }
inline bool is_blank(char c) { return has_class(c, kBlank); }
inline bool is_digit(char c) { return has_class(c, kDigit); }
inline bool is_ident_start(char c) { return has_class(c, kIdentStart); }
inline bool is_ident_char(char c) { return has_class(c, kIdentChar); }

inline std::size_t skip_blanks(std::string_view s, std::size_t i) {
  // Mostly one blank or none; SolidCAM pads with runs of spaces: look at eight bytes at a time,
  // the first that is not a space found from the word.
  constexpr std::uint64_t kSpaces = 0x2020202020202020;
  while (i + 8 <= s.size()) {
    std::uint64_t w;
    std::memcpy(&w, s.data() + i, 8);
    const std::uint64_t other = w ^ kSpaces;
    if (other == 0) {
      i += 8;
      continue;
    }
    if constexpr (std::endian::native == std::endian::little) i += static_cast<std::size_t>(std::countr_zero(other)) / 8;
    if (s[i] != ' ' && s[i] != '\t') return i;
    ++i;
  }
  while (i < s.size() && is_blank(s[i])) ++i;
  return i;
}

// skip_blanks for text that a byte other than a blank follows in memory (the reader's chunk ends
// in the string's '\0'): the words are loaded below `end`, the last bytes looked at one by one.
inline const char* skip_terminated_blanks(const char* p, const char* end) {
  constexpr std::uint64_t kSpaces = 0x2020202020202020;
  while (end - p >= 8) {
    std::uint64_t w;
    std::memcpy(&w, p, 8);
    const std::uint64_t other = w ^ kSpaces;
    if (other == 0) {
      p += 8;
      continue;
    }
    if constexpr (std::endian::native == std::endian::little) p += std::countr_zero(other) / 8;
    break;
  }
  while (*p == ' ' || *p == '\t') ++p;
  return p;
}

inline std::string_view trim_right(std::string_view s) {
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

// Length of an identifier at the start of `s` (0 if none).
inline std::size_t ident_length(std::string_view s) {
  if (s.empty() || !is_ident_start(s[0])) return 0;
  const char* p = s.data() + 1;
  const char* const end = s.data() + s.size();
  while (p < end && is_ident_char(*p)) ++p;
  return static_cast<std::size_t>(p - s.data());
}

// The length of an array index at the start of `s`, `<<2>>` or `<<3,2>>`, else 0: a parameter may
// be one element of a host array (`call_prms<<2>> : 5.`, `chng_cond<<3,1>> : '0.25'`).
inline std::size_t index_suffix_length(std::string_view s) {
  if (s.size() < 5 || s[0] != '<' || s[1] != '<') return 0;
  std::size_t i = 2;
  for (int part = 0; part < 2; ++part) {
    const std::size_t digits = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    if (i == digits) return 0;
    if (i >= s.size() || s[i] != ',') break;
    ++i;
  }
  return i + 1 < s.size() && s[i] == '>' && s[i + 1] == '>' ? i + 2 : 0;
}

// A parameter name: an identifier, with an array index when it names an element.
inline std::size_t parameter_name_length(std::string_view s) {
  const std::size_t n = ident_length(s);
  return n == 0 ? 0 : n + index_suffix_length(s.substr(n));
}

// The length of the name when `s` starts with `name:` (how a name:value pair opens in the inline
// layout), else 0.
inline std::size_t pair_name_length(std::string_view s) {
  std::size_t n = parameter_name_length(s);
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

inline NumberScan scan_number(std::string_view s) {
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

// scan_number for text followed in memory by a byte that cannot continue a number: the reader's
// lines are followed by '\n', '\r' or '\0'. The same result, without bound checks.
inline NumberScan scan_terminated_number(const char* s) {
  // Locals, put together at the end: the inlined scan then keeps them in registers.
  const char* p = s;
  bool negative = false;
  if (*p == '+' || *p == '-') negative = *p++ == '-';
  std::uint64_t mantissa = 0;
  unsigned d = 0;
  const char* start = p;
  while ((d = static_cast<unsigned char>(*p) - unsigned{'0'}) <= 9) mantissa = mantissa * 10 + d, ++p;
  int digits = static_cast<int>(p - start);
  int decimals = 0;
  bool numeric = false;
  if (*p == '.') {
    numeric = true;
    start = ++p;
    while ((d = static_cast<unsigned char>(*p) - unsigned{'0'}) <= 9) mantissa = mantissa * 10 + d, ++p;
    decimals = static_cast<int>(p - start);
    digits += decimals;
  }
  bool exponent = false;
  if (digits > 0 && (*p | 0x20) == 'e') {  // 'e' or 'E', no other byte
    const char* q = p + 1;
    if (*q == '+' || *q == '-') ++q;
    const char* exp_start = q;
    while (is_digit(*q)) ++q;
    if (q > exp_start) {
      numeric = exponent = true;
      p = q;
    }
  }
  return {digits == 0 ? 0 : static_cast<std::size_t>(p - s), numeric, exponent, negative, digits, decimals, mantissa};
}

// The exact double of a scanned plain decimal when its mantissa (at most 19 digits) is below 2^53
// and it has at most 22 decimals: mantissa and power of ten are then exact doubles and one
// correctly rounded division gives what from_chars gives (Clinger's fast path). False otherwise.
inline bool fast_decimal(const NumberScan& n, double& out) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  // Up to 15 digits the mantissa is below 10^15 < 2^53 and there are at most 15 decimals.
  if (n.exponent || (n.digits > 15 && (n.digits > 19 || n.mantissa > (std::uint64_t{1} << 53) || n.decimals > 22)))
    return false;
  // The mantissa is at most 2^53 here: converted as a signed integer, exactly the same double
  // without the fix-up an unsigned conversion takes.
  const double v = static_cast<double>(static_cast<std::int64_t>(n.mantissa)) / kPow10[n.decimals];
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
inline constexpr std::array<ChangeFlag, 256> kFlagLetters = [] {
  std::array<ChangeFlag, 256> t{};
  t['T'] = t['t'] = ChangeFlag::Changed;
  t['F'] = t['f'] = ChangeFlag::Unchanged;
  return t;
}();
inline ChangeFlag flag_letter(char c) { return kFlagLetters[static_cast<unsigned char>(c)]; }

// Stores a scanned number that needs no from_chars (an integer of up to 18 digits, or a decimal
// fast_decimal takes) into `out`; false, and `out` untouched, for any other.
inline bool store_exact_number(Value& out, const NumberScan& n, ChangeFlag flag) {
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

// What the reader's fast path keeps per key (trace_pairs.cpp): the consumer's screen, and the
// number the key's value last was, as text, with what it gave. SolidCAM writes every parameter of
// a command each time, most of them unchanged, so the same bytes come back and need no scan and
// conversion. A number's value depends on its bytes only, so bytes that match give what the scan
// would give, and pass the key's screen as they did. The entry keeps its own copy of the value,
// never the slot's Value: the filters round values in place, and slots travel between commands.
struct alignas(64) KeyMemo {  // one line each, found by a shift
  ValueScreen screen;
  // The number and its flag letter, in the bytes of `mask` (little-endian); none when `text` is 0
  // (a value's first byte is never 0) and `mask` all ones.
  std::uint64_t text = 0;
  std::uint64_t mask = ~std::uint64_t{0};
  std::uint64_t bits = 0;  // the Integer, or the Numeric's bits
  std::uint8_t size = 0;   // the bytes of the number and its flag
  ValueKind kind = ValueKind::Integer;
  ChangeFlag flag = ChangeFlag::None;
  bool passed = false;  // the kept value passes `screen`
  // A parameter whose value changes every time (a coordinate along a contour) would pay for the
  // comparison and the copy each time: after a few misses in a row it rests for a while.
  std::uint8_t misses = 0;  // in a row
  std::uint8_t rest = 0;    // numbers of the key read before it keeps one again
  static constexpr std::uint8_t kMissesBeforeRest = 2, kRest = 64;

  static std::uint64_t word(const char* v) {
    std::uint64_t w;
    std::memcpy(&w, v, 8);
    return w;
  }
  // Whether the value at `v` is the one kept, then a blank or a line end, which no number goes on
  // past (`bound`: the last byte that may be read).
  [[gnu::always_inline]] bool holds(const char* v, const char* bound) const {
    if (v + 8 > bound || ((word(v) ^ text) & mask) != 0) return false;
    constexpr std::uint64_t kEnds = 1ull << ' ' | 1ull << '\t' | 1ull << '\n' | 1ull << '\r';
    const auto after = static_cast<unsigned char>(v[size]);
    return after <= ' ' && ((kEnds >> after) & 1) != 0;
  }
  // Stores the kept value into `out` as store_exact_number stored it; returns where it ends.
  [[gnu::always_inline]] const char* recall(const char* v, Value& out) {
    misses = 0;
    out.kind = kind;
    out.flag = flag;
    if (kind == ValueKind::Integer) out.integer = static_cast<std::int64_t>(bits);
    else std::memcpy(&out.numeric, &bits, sizeof bits);
    return v + size;
  }
  // Keeps `value`, just stored from the number (and flag) from `v` to `end` as the kept one did
  // not hold, when it fits and the entry is not resting; `passes`: whether it passes `screen`.
  [[gnu::always_inline]] void keep(const char* v, const char* end, const char* bound, const Value& value, bool passes) {
    if constexpr (std::endian::native != std::endian::little) return;
    if (rest != 0) return void(--rest);
    if (text != 0 && ++misses == kMissesBeforeRest) {
      misses = 0;
      rest = kRest;
      text = 0;
      mask = ~std::uint64_t{0};
      return;
    }
    const std::size_t n = static_cast<std::size_t>(end - v);  // 1 to 8 for a number that fits
    if (n > 8 || v + 8 > bound) return;
    mask = ~std::uint64_t{0} >> (8 * (8 - n));
    text = word(v) & mask;
    size = static_cast<std::uint8_t>(n);
    kind = value.kind;
    flag = value.flag;
    passed = passes;
    if (kind == ValueKind::Integer) bits = static_cast<std::uint64_t>(value.integer);
    else std::memcpy(&bits, &value.numeric, sizeof bits);
  }
};

// Records where a parameter's value starts (saturating: positions past 2^32 are not told apart).
inline void mark_position(Parameter& p, std::size_t line, std::size_t column) {
  constexpr std::size_t kMax = 0xffffffff;
  p.line = static_cast<std::uint32_t>(line < kMax ? line : kMax);
  p.column = static_cast<std::uint32_t>(column < kMax ? column : kMax);
}

// Names parameter slot `used` of `out` (added when there is none) and counts it (trace_pairs.cpp).
Parameter& new_slot(Command& out, std::size_t& used, std::string_view name);

// The next parameter slot of `out`, reusing the buffers of an earlier command's parameters. A
// reused slot often held the same name: then nothing is copied and the key stays.
inline Parameter& add_parameter(Command& out, std::size_t& used, std::string_view name) {
  if (used < out.parameters.size() && same_short_text(out.parameters[used].name, name)) return out.parameters[used++];
  return new_slot(out, used, name);
}

// Stores the scanned number `digits` (its text, without the flag) into `out` (trace_value.cpp).
void store_number(Value& out, const NumberScan& n, std::string_view digits, ChangeFlag flag, const Place& where);

// Stores a bare word (an identifier): TRUE or FALSE in any case as Logical, else an Enum. Inline:
// the reader stores a word or two per command, mostly the one the slot holds already.
[[gnu::always_inline]] inline void store_word(Value& out, std::string_view word) {
  out.flag = ChangeFlag::None;
  if ((word.size() == 4 || word.size() == 5) && (iequals(word, "true") || iequals(word, "false"))) {
    out.kind = ValueKind::Logical;
    out.logical = iequals(word, "true");
    return;
  }
  out.kind = ValueKind::Enum;
  // A recycled slot mostly holds the same word (`arc_direction:CCW` command after command).
  if (!same_short_text(out.text, word)) out.text.assign(word);
}

// Parses one value's text into `out`, reusing its string buffer (trace_value.cpp).
void parse_value_into(Value& out, std::string_view text, const Place& where);

}  // namespace toolpath::trace_syntax
