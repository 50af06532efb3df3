// The hand-written Fanuc post (scope and method: hand_post.hpp). Each GPPL procedure of
// machines/fanuc/fanuc.gpp that a make_job job reaches is one member function of Post below, in
// the order of the post, with the post's lines quoted where they are not obvious.
#include "bench/hand_post.hpp"

#include <fcntl.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <unistd.h>

#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <system_error>

namespace bench::hand_post {
namespace {

constexpr std::size_t kReadBlock = std::size_t{1} << 20;
constexpr std::size_t kReadSlack = 128;              // a final '\n' the file lacks, and the scanner's look-ahead
constexpr std::size_t kWriteBlock = std::size_t{1} << 20;
constexpr std::size_t kLineRoom = 512;               // one command's NC text, besides its strings
constexpr double kZeroValue = 0.001;                 // fanuc.prp: zero_value
constexpr std::int64_t kMaxArcRadius = 2'000'000;    // fanuc.prp: arc_max_radius 2000 mm, in thousandths
constexpr std::int64_t kFirstLabel = 1;              // fanuc.prp: proc_num_dflt
constexpr std::int64_t kLastBlockNumber = 99990;     // fanuc.gpp: @forced_g

[[noreturn]] void refuse(std::uint64_t offset, const std::string& what) {
  throw OutOfScope("hand_post: byte " + std::to_string(offset) + " of the trace: " + what +
                   " (the hand-written post takes the jobs make_job writes, nothing else)");
}

[[noreturn]] void system_failure(const std::string& what) {
  throw std::system_error(errno, std::generic_category(), "hand_post: " + what);
}

inline bool is_digit(char c) { return static_cast<unsigned char>(c - '0') < 10; }

// The scanner does not look at the bytes one by one. It classifies 64 bytes at a time into bit
// masks (blanks, line ends, colons: Window) and walks the name:value pairs with bit scans; what
// does not fit in a window, and the rest, finds its end eight bytes at a time (little-endian
// words). It may read up to 63 bytes past the '\n' that ends the last line, which the buffers
// leave room for (kReadSlack).
static_assert(std::endian::native == std::endian::little);
constexpr std::uint64_t kOnes = 0x0101010101010101ull;
inline std::uint64_t load8(const char* p) {
  std::uint64_t w;
  std::memcpy(&w, p, 8);
  return w;
}
// The high bit of each byte of w that is c. Above the first such byte there may be false ones,
// never below: the lowest flag, which is all the scanner uses, is exact (also in an OR of masks).
inline std::uint64_t bytes_equal(std::uint64_t w, char c) {
  const std::uint64_t x = w ^ (kOnes * static_cast<unsigned char>(c));
  return (x - kOnes) & ~x & (kOnes << 7);
}
inline const char* first_flagged(const char* p, std::uint64_t mask) { return p + (std::countr_zero(mask) >> 3); }
// The first byte from p that is not a blank.
inline const char* skip_blanks(const char* p) {
  for (;;) {
    if (const std::uint64_t other = load8(p) ^ (kOnes * ' ')) {
      p += std::countr_zero(other) >> 3;
      if (*p != '\t') return p;
      ++p;
    } else {
      p += 8;
    }
  }
}
// The first ':', blank or line end from p (the end of a parameter name).
inline const char* name_end(const char* p) {
  for (;; p += 8) {
    const std::uint64_t w = load8(p);
    if (const std::uint64_t m = bytes_equal(w, ':') | bytes_equal(w, ' ') | bytes_equal(w, '\n') | bytes_equal(w, '\t'))
      return first_flagged(p, m);
  }
}
// The first blank or line end from p (the end of a value that is not a string).
inline const char* value_end(const char* p) {
  for (;; p += 8) {
    const std::uint64_t w = load8(p);
    if (const std::uint64_t m = bytes_equal(w, ' ') | bytes_equal(w, '\n') | bytes_equal(w, '\t')) return first_flagged(p, m);
  }
}

// 64 bytes from `base`, classified: bit i of a mask stands for base[i].
struct Window {
  const char* base = nullptr;
  std::uint64_t blank = 0, newline = 0, colon = 0;

  void load(const char* p) {
    base = p;
#if defined(__SSE2__)
    const __m128i space = _mm_set1_epi8(' '), tab = _mm_set1_epi8('\t'), nl = _mm_set1_epi8('\n'), co = _mm_set1_epi8(':');
    std::uint64_t b = 0, n = 0, c = 0;
    for (int k = 0; k < 4; ++k) {
      const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16 * k));
      const auto bits = [&](__m128i eq) {
        return static_cast<std::uint64_t>(static_cast<unsigned>(_mm_movemask_epi8(eq))) << (16 * k);
      };
      b |= bits(_mm_or_si128(_mm_cmpeq_epi8(v, space), _mm_cmpeq_epi8(v, tab)));
      n |= bits(_mm_cmpeq_epi8(v, nl));
      c |= bits(_mm_cmpeq_epi8(v, co));
    }
    blank = b;
    newline = n;
    colon = c;
#else
    blank = newline = colon = 0;
    for (int i = 0; i < 64; ++i) {
      blank |= static_cast<std::uint64_t>(p[i] == ' ' || p[i] == '\t') << i;
      newline |= static_cast<std::uint64_t>(p[i] == '\n') << i;
      colon |= static_cast<std::uint64_t>(p[i] == ':') << i;
    }
#endif
  }
};

constexpr auto kNameChar = [] {
  std::array<bool, 256> t{};
  for (int c = 'a'; c <= 'z'; ++c) t[c] = true;
  for (int c = 'A'; c <= 'Z'; ++c) t[c] = true;
  for (int c = '0'; c <= '9'; ++c) t[c] = true;
  t['_'] = true;
  return t;
}();
inline bool is_name_char(char c) { return kNameChar[static_cast<unsigned char>(c)]; }

constexpr std::array<double, 23> kPow10 = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                           1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr auto kIntPow10 = [] {
  std::array<std::uint64_t, 20> t{};
  t[0] = 1;
  for (std::size_t i = 1; i < t.size(); ++i) t[i] = t[i - 1] * 10;
  return t;
}();

// ------------------------------------------------------------------ numbers

// A number as the trace writes it. Up to 15 digits without an exponent (every make_job value) it
// is kept as its decimal text says, `mantissa` / 10^`decimals`: that text is then also the value's
// 15-significant-digit form, on which GPPL's display formats round. Anything longer is read as
// the double the engine reads (`general`).
struct Number {
  std::uint64_t mantissa = 0;
  int decimals = 0;
  bool negative = false;
  bool exact = true;
  double general = 0;
  char flag = 0;  // 'T' or 'F' after the number: the trace's change flag
};

// Reads the number at p, which must end at a blank or the end of the line; nullptr if it does not.
[[gnu::always_inline]] inline const char* parse_number(const char* p, Number& n) {
  const char* const start = p;
  n.negative = *p == '-';
  if (*p == '-' || *p == '+') ++p;
  const char* const digits = p;
  std::uint64_t m = 0;  // wraps past 19 digits: then unused
  while (is_digit(*p)) m = m * 10 + static_cast<unsigned>(*p++ - '0');
  std::ptrdiff_t count = p - digits;
  int decimals = 0;
  if (*p == '.') {
    const char* const fraction = ++p;
    while (is_digit(*p)) m = m * 10 + static_cast<unsigned>(*p++ - '0');
    decimals = static_cast<int>(p - fraction);
    count += decimals;
  }
  if (count == 0) return nullptr;
  n.exact = count <= 15 && *p != 'e' && *p != 'E';
  if (!n.exact) {
    if (*p == 'e' || *p == 'E') {
      ++p;
      if (*p == '+' || *p == '-') ++p;
      const char* const exponent = p;
      while (is_digit(*p)) ++p;
      if (p == exponent) return nullptr;
    }
    auto [end, ec] = std::from_chars(start + (*start == '+'), p, n.general);
    if (ec != std::errc() || end != p) return nullptr;
  }
  n.mantissa = m;
  n.decimals = decimals;
  n.flag = 0;
  if (*p == 'T' || *p == 'F') n.flag = *p++;
  return *p == ' ' || *p == '\n' ? p : nullptr;
}

// The double the engine holds: correctly rounded, as from_chars gives it (both operands of the
// division are exact doubles when there are at most 15 digits).
inline double to_double(const Number& n) {
  if (!n.exact) return n.general;
  const double v = n.decimals == 0 ? static_cast<double>(n.mantissa) : static_cast<double>(n.mantissa) / kPow10[n.decimals];
  return n.negative ? -v : v;
}

// What a GPPL display format with `digits` decimals prints of the number, as an integer count of
// 10^-digits: the 15-significant-digit form rounded half away from zero.
std::int64_t display_units(const Number& n, int digits, std::uint64_t offset) {
  std::uint64_t m = n.mantissa;
  int k = n.decimals;
  bool negative = n.negative;
  if (!n.exact) {
    if (!std::isfinite(n.general) || std::abs(n.general) >= 1e14) refuse(offset, "a number beyond 1e14");
    char text[32];
    std::snprintf(text, sizeof text, "%.14e", std::abs(n.general));  // d.dddddddddddddde[+-]xx
    m = 0;
    for (const char* c = text; *c != 'e'; ++c)
      if (*c != '.') m = m * 10 + static_cast<unsigned>(*c - '0');
    k = 14 - std::atoi(std::strchr(text, 'e') + 1);
    negative = std::signbit(n.general);
  }
  std::uint64_t units;
  if (k <= digits) {
    units = m * kIntPow10[digits - k];
  } else if (k - digits >= 19) {
    units = 0;  // m < 10^15 is below half of 10^19
  } else {
    const std::uint64_t p = kIntPow10[k - digits];
    units = m / p + ((m % p) * 2 >= p ? 1 : 0);
  }
  return negative ? -static_cast<std::int64_t>(units) : static_cast<std::int64_t>(units);
}

// The precision filter's zero snap: a length closer than zero_value to 0 becomes 0.
double zero_snapped(double x) { return x != 0.0 && std::abs(x) < kZeroValue ? 0.0 : x; }

// The precision filter's rounding to 0.001, round_half_away(x * 1000), as integer thousandths.
std::int64_t round_milli(double x, std::uint64_t offset) {
  const double y = x * 1000.0;
  if (!(std::abs(y) < 9e15)) refuse(offset, "a length beyond 9e12 mm");
  auto t = static_cast<std::int64_t>(y);  // towards zero
  const double fraction = y - static_cast<double>(t);
  if (fraction >= 0.5) ++t;
  else if (fraction <= -0.5) --t;
  return t;
}

// A length after the precision filter (zero snap, then rounding), in thousandths. Up to three
// decimals (and below 2^40 thousandths, where x * 1000 is within far less than 0.5 of the
// integer) the text gives it directly, and a non-zero value is at least 0.001: no snap.
inline std::int64_t filtered_milli(const Number& n, std::uint64_t offset) {
  if (n.exact && n.decimals <= 3 && n.mantissa < (std::uint64_t{1} << 40)) {
    const auto u = static_cast<std::int64_t>(n.mantissa * kIntPow10[3 - n.decimals]);
    return n.negative ? -u : u;
  }
  return round_milli(zero_snapped(to_double(n)), offset);
}

bool same_word(std::string_view a, std::string_view b) {  // enumerations compare without case
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if ((a[i] | 0x20) != (b[i] | 0x20)) return false;
  return true;
}

// ------------------------------------------------------------------ output

constexpr auto kDigitPairs = [] {
  std::array<char, 200> t{};
  for (int i = 0; i < 100; ++i) {
    t[2 * i] = static_cast<char>('0' + i / 10);
    t[2 * i + 1] = static_cast<char>('0' + i % 10);
  }
  return t;
}();

// '5.3' fractions: ".ddd" and how much of it is printed (the point, then the digits up to the last
// that is not 0): 500 -> ".5", 0 -> ".".
struct Fraction {
  char text[4];
  std::uint8_t length;
};
constexpr auto kFractions = [] {
  std::array<Fraction, 1000> t{};
  for (int f = 0; f < 1000; ++f) {
    Fraction& x = t[f];
    x.text[0] = '.';
    x.text[1] = static_cast<char>('0' + f / 100);
    x.text[2] = static_cast<char>('0' + f / 10 % 10);
    x.text[3] = static_cast<char>('0' + f % 10);
    int last = 3;
    while (last > 0 && x.text[last] == '0') --last;
    x.length = static_cast<std::uint8_t>(last + 1);
  }
  return t;
}();

inline char* put_uint(char* p, std::uint64_t v) {
  if (v < 10) {
    *p = static_cast<char>('0' + v);
    return p + 1;
  }
  if (v < 100) {
    std::memcpy(p, &kDigitPairs[2 * v], 2);
    return p + 2;
  }
  int count = 3;
  while (count < 20 && v >= kIntPow10[count]) ++count;
  char* const end = p + count;
  char* s = end;
  while (v >= 100) {
    s -= 2;
    std::memcpy(s, &kDigitPairs[2 * (v % 100)], 2);
    v /= 100;
  }
  if (v >= 10) {
    s -= 2;
    std::memcpy(s, &kDigitPairs[2 * v], 2);
  } else {
    *--s = static_cast<char>('0' + v);
  }
  return end;
}

inline char* put_int(char* p, std::int64_t v) {  // '5.0(p)' of an integer
  if (v < 0) {
    *p++ = '-';
    return put_uint(p, 0 - static_cast<std::uint64_t>(v));
  }
  return put_uint(p, static_cast<std::uint64_t>(v));
}

// '5.3' of thousandths: "-12.345", "50.", "0.5". A negative value here is never 0 (no "-0.").
inline char* put_milli(char* p, std::int64_t u) {
  std::uint64_t a = static_cast<std::uint64_t>(u);
  if (u < 0) {
    *p++ = '-';
    a = 0 - a;
  }
  p = put_uint(p, a / 1000);
  const Fraction& f = kFractions[a % 1000];
  std::memcpy(p, f.text, 4);
  return p + f.length;
}

// '5.3/1' of thousandths: at least one fraction digit ("10.0").
inline char* put_milli_one_decimal(char* p, std::int64_t u) {
  p = put_milli(p, u);
  if (p[-1] == '.') *p++ = '0';
  return p;
}

// '5.1(p)' of tenths: no point when the tenth is 0 ("1500", "1500.5").
inline char* put_tenths(char* p, std::int64_t t) {
  std::uint64_t a = static_cast<std::uint64_t>(t);
  if (t < 0) {
    *p++ = '-';
    a = 0 - a;
  }
  p = put_uint(p, a / 10);
  if (a % 10 != 0) {
    p[0] = '.';
    p[1] = static_cast<char>('0' + a % 10);
    p += 2;
  }
  return p;
}

inline char* put(char* p, std::string_view s) {
  std::memcpy(p, s.data(), s.size());
  return p + s.size();
}

// The NC file's bytes: one buffer, emptied by write() (or appended to a string) when full. Lines
// are separated, not terminated: GPPL starts each new line (nb, nl) with the break, so the file
// ends with "%" and no line break, as the engine writes it.
class Out {
public:
  explicit Out(int fd) : fd_(fd) { allocate(kWriteBlock + kLineRoom); }
  explicit Out(std::string* text) : text_(text) { allocate(kWriteBlock + kLineRoom); }

  // Makes room for n more bytes at w.
  void room(std::size_t n) {
    if (static_cast<std::size_t>(limit_ - w) < n) make_room(n);
  }
  // Opens a new line; room for its bytes must have been made.
  void line() {
    if (started_) *w++ = '\n';
    started_ = true;
    ++lines_;
  }
  void flush() {
    const std::size_t n = static_cast<std::size_t>(w - buffer_.get());
    if (text_) {
      text_->append(buffer_.get(), n);
    } else {
      for (std::size_t done = 0; done < n;) {
        const ssize_t k = ::write(fd_, buffer_.get() + done, n - done);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) system_failure("cannot write the NC file");
        done += static_cast<std::size_t>(k);
      }
    }
    bytes_ += n;
    w = buffer_.get();
  }
  std::uint64_t lines() const { return lines_; }
  std::uint64_t bytes() const { return bytes_; }

  char* w = nullptr;  // where the next byte goes

private:
  void allocate(std::size_t size) {
    buffer_.reset(new char[size]);
    w = buffer_.get();
    limit_ = w + size;
  }
  void make_room(std::size_t n) {
    flush();
    if (static_cast<std::size_t>(limit_ - w) < n) allocate(n + kLineRoom);  // a text longer than the buffer
  }

  int fd_ = -1;
  std::string* text_ = nullptr;
  std::unique_ptr<char[]> buffer_;
  char* limit_ = nullptr;
  bool started_ = false;
  std::uint64_t lines_ = 0, bytes_ = 0;
};

// ------------------------------------------------------------------ the post

// Where the values of one command's pairs are, by key: their first byte and their length.
template <int Count>
struct Values {
  const char* at[Count];
  std::uint32_t size[Count];
};

// A value's text as last seen (up to 8 bytes) and what it gave: the same text gives the same value,
// and for an axis the same result of the precision filter (the axis was sent where that text put
// it, so the "barely moved" rule keeps it there). The parse is skipped.
struct Remembered {
  std::uint64_t word = 0;
  std::uint32_t size = 0;  // 0: nothing remembered
  char flag = 0;
  std::int64_t milli = 0;
  double number = 0;
  Number parsed;

  static std::uint64_t masked(const char* p, std::uint32_t size) {
    return load8(p) & (size >= 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * size)) - 1);
  }
  bool same(const char* p, std::uint32_t n) const { return size != 0 && n == size && masked(p, n) == word; }
  void keep(const char* p, std::uint32_t n) {
    size = n <= 8 ? n : 0;
    word = masked(p, n);
  }
};

// A GPPL variable's value and change memory (the `assigned`/`changed` pair of the interpreter).
template <class T>
struct Modal {
  T value{};
  bool assigned = false, changed = false;
  void assign(T v, char flag = 0) {
    changed = flag == 'T' || (flag != 'F' && (!assigned || v != value));
    assigned = true;
    value = v;
  }
};

enum class Kind {
  start_of_file, def_tool, machine_plane, start_program, start_of_job, change_tool, call_proc,
  end_program, proc, end_of_job, end_proc, end_of_file, line, arc, none
};

constexpr std::pair<std::string_view, Kind> kCommands[] = {
    {"@start_of_file", Kind::start_of_file}, {"@def_tool", Kind::def_tool},       {"@machine_plane", Kind::machine_plane},
    {"@start_program", Kind::start_program}, {"@start_of_job", Kind::start_of_job}, {"@change_tool", Kind::change_tool},
    {"@call_proc", Kind::call_proc},         {"@end_program", Kind::end_program}, {"@proc", Kind::proc},
    {"@end_of_job", Kind::end_of_job},       {"@end_proc", Kind::end_proc},       {"@end_of_file", Kind::end_of_file},
};

// The parameters of the commands other than motions that the post reads.
enum Key : int {
  program_number, g_file_name, home_number, tool_number, tool_offset, machine_plane, job_name, xnext, ynext, znext,
  spin, tool_direction, label, proc_count, message, key_count
};
constexpr std::string_view kKeyNames[key_count] = {
    "program_number", "g_file_name", "home_number", "tool_number", "tool_offset", "machine_plane", "job_name", "xnext",
    "ynext",          "znext",       "spin",        "tool_direction", "label",   "proc_count",    "message"};

// The parameters of @line and @arc the post reads; the others are skipped.
enum MotionKey : int { m_xpos, m_ypos, m_zpos, m_feed, m_radius, m_arc_size, m_xcenter_rel, m_ycenter_rel,
                       m_arc_direction, m_arc_plane, motion_key_count, m_other = motion_key_count };

[[gnu::always_inline]] inline int motion_key(const char* s, std::size_t n) {
  switch (n) {
    case 4:
      if (s[1] == 'p' && s[2] == 'o' && s[3] == 's') {
        if (s[0] == 'x') return m_xpos;
        if (s[0] == 'y') return m_ypos;
        if (s[0] == 'z') return m_zpos;
      }
      return std::memcmp(s, "feed", 4) == 0 ? m_feed : m_other;
    case 6: return std::memcmp(s, "radius", 6) == 0 ? m_radius : m_other;
    case 8: return std::memcmp(s, "arc_size", 8) == 0 ? m_arc_size : m_other;
    case 9: return std::memcmp(s, "arc_plane", 9) == 0 ? m_arc_plane : m_other;
    case 11:
      if (std::memcmp(s + 1, "center_rel", 10) == 0) {
        if (s[0] == 'x') return m_xcenter_rel;
        if (s[0] == 'y') return m_ycenter_rel;
      }
      return m_other;
    case 13: return std::memcmp(s, "arc_direction", 13) == 0 ? m_arc_direction : m_other;
    default: return m_other;
  }
}

inline int other_key(const char* s, std::size_t n) {
  for (int k = 0; k < key_count; ++k)
    if (kKeyNames[k].size() == n && std::memcmp(kKeyNames[k].data(), s, n) == 0) return k;
  return key_count;
}

class Post {
public:
  explicit Post(Out& out) : out_(out) {}

  // Posts the commands in [p, end): whole commands, end[-1] is '\n'. `offset`: of p in the trace.
  void commands(const char* p, const char* end, std::uint64_t offset);
  // At the end of the trace.
  void finish() const;
  std::uint64_t commands_read() const { return commands_; }

private:
  // Reading.
  std::uint64_t at(const char* p) const { return offset_ + static_cast<std::uint64_t>(p - base_); }
  const char* continuation(const char* q, const char* end, const char*& next) const;
  template <int Count, int (*KeyOf)(const char*, std::size_t)>
  const char* scan_pairs(const char* q, const char* end, Values<Count>& values) const;
  Number number(const char* value, const char* name) const;
  std::int64_t integer(const char* value, const char* name) const;
  std::string_view text(const char* value) const;  // a string (quotes removed) or a bare word
  const char* require(const char* value, const char* name, const char* command) const;

  // The commands.
  const char* motion(bool arc, const char* q, const char* end);
  const char* other(Kind kind, const char* q, const char* end);
  void start_of_file(const char* const* v);
  void def_tool(const char* const* v);
  void start_program();
  void start_of_job(std::string_view name);
  void end_program();
  void change_tool(const char* const* v);
  void call_proc(std::int64_t label, std::int64_t count, const std::string_view* message);
  void proc(std::int64_t label);
  void open_flat_job();

  // GPPL's output: `nb` opens a line with the block number; every item then starts with its blank.
  void nb() {
    out_.line();
    *out_.w++ = 'N';
    out_.w = put_uint(out_.w, static_cast<std::uint64_t>(blknum_));
    blknum_ += 10;
  }
  void reset_change_memory() {  // at @proc, and after @call_proc
    xpos_.assigned = ypos_.assigned = zpos_.assigned = gcode_.assigned = feed_.assigned = false;
  }
  std::int64_t axis(const Number& n, int axis);

  Out& out_;
  const char* base_ = nullptr;
  std::uint64_t offset_ = 0;
  std::uint64_t command_offset_ = 0;  // of the command being posted, for messages
  std::uint64_t commands_ = 0;

  // The post's variables.
  Modal<std::int64_t> xpos_, ypos_, zpos_, gcode_;  // coordinates in thousandths
  Modal<double> feed_;
  Number feed_text_;  // the feed as the trace gave it, for printing
  std::int64_t blknum_ = 10;
  std::int64_t home_number_ = 0;
  int plane_code_ = 17;
  int spindle_m_ = 0;
  bool coolant_on_ = false;

  // The PRP's precision filter: where each axis was last sent, in thousandths.
  std::int64_t sent_[3] = {0, 0, 0};
  bool sent_known_[3] = {false, false, false};
  Remembered remembered_[motion_key_count];  // the motion parameters' last texts

  // Program structure: procedures as they come, or one flat job made into procedure 1.
  enum class Shape { unknown, procedures, flat } shape_ = Shape::unknown;
  bool flat_call_pending_ = false;  // a flat job's @start_of_job was read; its body not opened yet
  bool flat_job_seen_ = false;
  std::string job_name_;
  Kind previous_ = Kind::none;
};

// q: the '\n' ending a line of the command. Returns the first byte after `..>` when the command
// goes on with a continuation line; else nullptr, and `next` is the start of the next command's
// line (or end). Output lines (`> text`), `;` comments and blank lines belong to no pair.
const char* Post::continuation(const char* q, const char* end, const char*& next) const {
  for (;;) {
    const char* r = q + 1;
    if (r >= end || *r == '(' || *r == '@') {
      next = r;
      return nullptr;
    }
    const char* const s = skip_blanks(r);
    if (s[0] == '.' && s[1] == '.' && s[2] == '>') return s + 3;
    if (*s == '>' || *s == ';' || *s == '\n') {
      q = static_cast<const char*>(std::memchr(s, '\n', static_cast<std::size_t>(end - s)));
      continue;
    }
    refuse(at(s), "a line that is no command header, `..>` continuation, `>` output or comment");
  }
}

// Scans a command's name:value pairs from q (after `==>`) over its continuation lines;
// values.at[k] points at the value of the first pair whose name KeyOf gives k (nullptr: none),
// values.size[k] is its length. Returns where the next command starts.
template <int Count, int (*KeyOf)(const char*, std::size_t)>
const char* Post::scan_pairs(const char* q, const char* end, Values<Count>& values) const {
  for (auto& v : values.at) v = nullptr;
  Window w;
  w.load(q);
  unsigned i = 0;  // where the next pair may start: w.base + i, i < 64
  for (;;) {
    const std::uint64_t solid = ~w.blank >> i;
    if (solid == 0) {  // blanks up to the end of the window
      w.load(w.base + 64);
      i = 0;
      continue;
    }
    i += static_cast<unsigned>(std::countr_zero(solid));
    if ((w.newline >> i) & 1) {  // the end of the line: the command goes on, or the next one starts
      if (i < 60 && w.base + i + 1 < end) {  // `..>` after blanks, inside the window: the next pairs right away
        const std::uint64_t next_solid = ~w.blank >> (i + 1);
        const unsigned j = i + 1 + static_cast<unsigned>(std::countr_zero(next_solid));
        if (next_solid != 0 && j > i + 1 && j + 3 <= 64 && w.base[j] == '.' && w.base[j + 1] == '.' && w.base[j + 2] == '>') {
          i = j + 3;
          continue;
        }
      }
      const char* next = nullptr;
      const char* const more = continuation(w.base + i, end, next);
      if (!more) return next;
      if (more - w.base >= 64) w.load(more);
      i = static_cast<unsigned>(more - w.base);
      continue;
    }
    // A pair from i: name, ':', value up to a blank or the line end, all in the window when the
    // masks show its colon and its end; else the window moves to the pair (once).
    const char* const name = w.base + i;
    const std::uint64_t colons = w.colon >> i, stops = (w.blank | w.newline) >> i;
    const unsigned c = colons ? static_cast<unsigned>(std::countr_zero(colons)) : 64;
    const unsigned value_at = i + c + 1;
    const std::uint64_t value_stops = value_at < 64 ? (w.blank | w.newline) >> value_at : 0;
    if (colons != 0 && (stops == 0 || static_cast<unsigned>(std::countr_zero(stops)) > c) && value_stops != 0 &&
        name[c + 1] != '\'' && name[c + 1] != '"') {
      if (c == 0) refuse(at(name), "expected name:value");
      const int k = KeyOf(name, c);
      const unsigned value_size = static_cast<unsigned>(std::countr_zero(value_stops));
      if (k < Count && values.at[k] == nullptr) {
        values.at[k] = name + c + 1;
        values.size[k] = value_size;
      }
      i = value_at + value_size;
      continue;
    }
    if (i > 0 && colons != 0 && value_at < 64 && name[c + 1] != '\'' && name[c + 1] != '"') {
      w.load(name);  // the pair goes on past the window: take it from its start
      i = 0;
      continue;
    }
    // A string value, a pair longer than a window, or no pair at all: word by word.
    const char* p = name_end(name);
    if (*p != ':' || p == name) refuse(at(name), "expected name:value");
    const int k = KeyOf(name, static_cast<std::size_t>(p - name));
    const char* const value = ++p;
    if (*p == '\'' || *p == '"') {
      const char quote = *p++;
      while (*p != quote && *p != '\n') ++p;
      if (*p != quote) refuse(at(name), "a string without its closing quote");
      ++p;
    }
    p = value_end(p);
    if (k < Count && values.at[k] == nullptr) {
      values.at[k] = value;
      values.size[k] = static_cast<std::uint32_t>(p - value);
    }
    w.load(p);
    i = 0;
  }
}

[[gnu::always_inline]] inline Number Post::number(const char* value, const char* name) const {
  Number n;
  if (!parse_number(value, n)) [[unlikely]]
    refuse(at(value), std::string("expected a number for ") + name);
  return n;
}

std::int64_t Post::integer(const char* value, const char* name) const {
  Number n = number(value, name);
  if (!n.exact || n.decimals != 0 || n.flag != 0) refuse(at(value), std::string("expected an integer for ") + name);
  return n.negative ? -static_cast<std::int64_t>(n.mantissa) : static_cast<std::int64_t>(n.mantissa);
}

std::string_view Post::text(const char* value) const {
  if (*value == '\'' || *value == '"') {
    const char* close = value + 1;
    while (*close != *value) ++close;  // scan_pairs found it
    return {value + 1, static_cast<std::size_t>(close - value - 1)};
  }
  const char* e = value;
  while (*e != ' ' && *e != '\n') ++e;
  return {value, static_cast<std::size_t>(e - value)};
}

inline const char* Post::require(const char* value, const char* name, const char* command) const {
  if (!value) [[unlikely]]
    refuse(command_offset_, std::string(command) + " without " + name);
  return value;
}

void Post::commands(const char* p, const char* end, std::uint64_t offset) {
  base_ = p;
  offset_ = offset;
  while (p < end) {
    if (*p != '(' && *p != '@') {  // blank lines and comments before a command
      const char* s = p;
      while (*s == ' ' || *s == '\t') ++s;
      if (*s != '\n' && *s != ';') refuse(at(p), "expected a command header");
      p = static_cast<const char*>(std::memchr(s, '\n', static_cast<std::size_t>(end - s))) + 1;
      continue;
    }
    const char* q = p;
    if (*q == '(') {
      if (q[1] != '1' || q[2] != ')') refuse(at(p), "a command depth other than (1)");
      q += 3;
    }
    if (*q != '@') refuse(at(q), "expected @ and a command name");
    const char* const name = q++;
    while (is_name_char(*q)) ++q;
    const auto length = static_cast<std::size_t>(q - name);
    q = skip_blanks(q);
    if (q[0] == '=' && q[1] == '=' && q[2] == '>') q += 3;
    else if (*q != '\n') refuse(at(q), "expected ==> after the command name");
    ++commands_;
    command_offset_ = at(p);
    if (length == 5 && std::memcmp(name, "@line", 5) == 0) {
      p = motion(false, q, end);
    } else if (length == 4 && std::memcmp(name, "@arc", 4) == 0) {
      p = motion(true, q, end);
    } else {
      Kind kind = Kind::none;
      for (const auto& [command, k] : kCommands)
        if (command.size() == length && std::memcmp(command.data(), name, length) == 0) kind = k;
      if (kind == Kind::none) refuse(at(name), "the command " + std::string(name, length));
      p = other(kind, q, end);
    }
  }
}

void Post::finish() const {
  if (previous_ != Kind::end_of_file) refuse(command_offset_, "the trace does not end with @end_of_file");
}

// ---- @line and @arc

// An axis through the precision filter, with its rule that "an axis that moves less than
// zero_value keeps its previous value" (compared in doubles, as the engine does: a 0.001 step can
// compare below 0.001). Only a rounded move of one thousandth can be held back: when the rounded
// value equals the last one the rule changes nothing, and two thousandths or more apart the move
// is more than 0.0015.
inline std::int64_t Post::axis(const Number& n, int i) {
  std::int64_t u = filtered_milli(n, command_offset_);
  if (sent_known_[i] && (u - sent_[i] == 1 || u - sent_[i] == -1)) {
    const double x = zero_snapped(to_double(n));
    const double last = static_cast<double>(sent_[i]) / 1000.0;  // the double the filter sent
    if (x != last && std::abs(x - last) < kZeroValue) u = sent_[i];
  }
  sent_[i] = u;
  sent_known_[i] = true;
  return u;
}

// @line:  gcode = 1; call @forced_g; {nb, ['G'gcode], [' X'xpos], [' Y'ypos], [' Z'zpos], [' F'feed]}
// @arc:   gcode = 3 or 2 (CCW or not), changed; call @arc_plane; call @forced_g;
//         {nb, 'G'gcode, [' X'xpos], [' Y'ypos], [' Z'zpos]}, then I J (K) of a full circle, else
//         ' R' radius (negative beyond 180 degrees); then {[' F'feed]}.
const char* Post::motion(bool arc, const char* q, const char* end) {
  if (flat_call_pending_) open_flat_job();
  if (shape_ == Shape::flat && previous_ == Kind::end_of_job) refuse(command_offset_, "a motion after a flat job's @end_of_job");
  previous_ = arc ? Kind::arc : Kind::line;
  Values<motion_key_count> values;
  const char* const next = scan_pairs<motion_key_count, motion_key>(q, end, values);
  const char* const* const v = values.at;
  const char* const what = arc ? "@arc" : "@line";
  static constexpr const char* kAxes[3] = {"xpos", "ypos", "zpos"};
  Modal<std::int64_t>* const axes[3] = {&xpos_, &ypos_, &zpos_};
  for (int i = 0; i < 3; ++i) {
    const char* const text = require(v[m_xpos + i], kAxes[i], what);
    Remembered& r = remembered_[m_xpos + i];
    if (!r.same(text, values.size[m_xpos + i])) {
      const Number n = number(text, kAxes[i]);
      r.milli = axis(n, i);
      r.flag = n.flag;
      r.keep(text, values.size[m_xpos + i]);
    }
    axes[i]->assign(r.milli, r.flag);
  }
  {
    const char* const text = require(v[m_feed], "feed", what);
    Remembered& r = remembered_[m_feed];
    if (!r.same(text, values.size[m_feed])) {
      r.parsed = number(text, "feed");
      r.number = to_double(r.parsed);
      r.keep(text, values.size[m_feed]);
    }
    feed_.assign(r.number, r.parsed.flag);
    feed_text_ = r.parsed;
  }

  out_.room(kLineRoom);
  if (!arc) {
    gcode_.assign(1);
    if (blknum_ > kLastBlockNumber) blknum_ = 10;  // @forced_g
    nb();
    char* w = out_.w;
    const char* const opened = w;
    if (gcode_.changed) w = put(w, " G1");
    if (xpos_.changed) w = put_milli(put(w, " X"), xpos_.value);
    if (ypos_.changed) w = put_milli(put(w, " Y"), ypos_.value);
    if (zpos_.changed) w = put_milli(put(w, " Z"), zpos_.value);
    if (feed_.changed) w = put_tenths(put(w, " F"), display_units(feed_text_, 1, command_offset_));
    if (w == opened) *w++ = ' ';  // {nb} with nothing after it keeps its blank
    out_.w = w;
    return next;
  }

  Remembered& radius = remembered_[m_radius];
  if (const char* text = require(v[m_radius], "radius", what); !radius.same(text, values.size[m_radius])) {
    radius.milli = filtered_milli(number(text, "radius"), command_offset_);
    radius.keep(text, values.size[m_radius]);
  }
  Remembered& size = remembered_[m_arc_size];
  if (const char* text = require(v[m_arc_size], "arc_size", what); !size.same(text, values.size[m_arc_size])) {
    size.number = to_double(number(text, "arc_size"));
    size.keep(text, values.size[m_arc_size]);
  }
  const std::string_view direction = text(require(v[m_arc_direction], "arc_direction", what));
  const std::string_view plane = text(require(v[m_arc_plane], "arc_plane", what));
  const std::int64_t r = radius.milli;
  const double sweep = size.number;
  // The PRP's arc filter passes these arcs as they are; the ones it would change are not ours.
  if (r > kMaxArcRadius || !(sweep >= 0.01) || static_cast<double>(r) * sweep * (3.14159 / 180.0) < 10.0)
    refuse(command_offset_, "an arc the PRP would linearise (radius above 2000 mm, or a sweep or length that small)");

  gcode_.assign(same_word(direction, "CCW") ? 3 : 2);
  gcode_.changed = true;
  const int wanted = same_word(plane, "XY") ? 17 : same_word(plane, "ZX") ? 18 : 19;  // @arc_plane
  if (wanted != plane_code_) {
    plane_code_ = wanted;
    nb();
    out_.w = put_uint(put(out_.w, " G"), static_cast<std::uint64_t>(plane_code_));
  }
  if (blknum_ > kLastBlockNumber) blknum_ = 10;  // @forced_g
  nb();
  char* w = out_.w;
  w = put_uint(put(w, " G"), static_cast<std::uint64_t>(gcode_.value));
  if (xpos_.changed) w = put_milli(put(w, " X"), xpos_.value);
  if (ypos_.changed) w = put_milli(put(w, " Y"), ypos_.value);
  if (zpos_.changed) w = put_milli(put(w, " Z"), zpos_.value);
  if (sweep >= 360.0) {
    // A full circle: the centre's offsets along the plane's two axes.
    const std::int64_t i = filtered_milli(number(require(v[m_xcenter_rel], "xcenter_rel", what), "xcenter_rel"), command_offset_);
    const std::int64_t j = filtered_milli(number(require(v[m_ycenter_rel], "ycenter_rel", what), "ycenter_rel"), command_offset_);
    if (plane_code_ == 17) w = put_milli(put(put_milli(put(w, " I"), i), " J"), j);
    else if (plane_code_ == 18) w = put_milli(put(put_milli(put(w, " I"), j), " K"), i);
    else w = put_milli(put(put_milli(put(w, " J"), i), " K"), j);
  } else {
    w = put_milli(put(w, " R"), sweep > 180.0 ? -r : r);
  }
  if (feed_.changed) w = put_tenths(put(w, " F"), display_units(feed_text_, 1, command_offset_));
  out_.w = w;
  return next;
}

// ---- the other commands

const char* Post::other(Kind kind, const char* q, const char* end) {
  Values<key_count> values;
  const char* const next = scan_pairs<key_count, other_key>(q, end, values);
  const char* const* const v = values.at;
  if (flat_call_pending_ && kind != Kind::change_tool) open_flat_job();
  if (shape_ == Shape::flat && previous_ == Kind::end_of_job && kind != Kind::end_program)
    refuse(command_offset_, "a command between a flat job's @end_of_job and @end_program");
  out_.room(kLineRoom);
  switch (kind) {
    case Kind::start_of_file: start_of_file(v); break;
    case Kind::def_tool: def_tool(v); break;
    case Kind::machine_plane: {
      // if machine_plane eq XY: plane_code = 17 (ZX 18, YZ 19)
      const std::string_view plane = text(require(v[machine_plane], "machine_plane", "@machine_plane"));
      if (same_word(plane, "XY")) plane_code_ = 17;
      if (same_word(plane, "ZX")) plane_code_ = 18;
      if (same_word(plane, "YZ")) plane_code_ = 19;
      break;
    }
    case Kind::start_program: start_program(); break;
    case Kind::start_of_job: start_of_job(text(require(v[job_name], "job_name", "@start_of_job"))); break;
    case Kind::change_tool: change_tool(v); break;
    case Kind::call_proc: {
      if (shape_ == Shape::flat) refuse(command_offset_, "@call_proc in a flat job");
      shape_ = Shape::procedures;
      const std::string_view message_text = v[message] ? text(v[message]) : std::string_view{};
      out_.room(kLineRoom + message_text.size());
      call_proc(integer(require(v[label], "label", "@call_proc"), "label"),
                v[proc_count] ? integer(v[proc_count], "proc_count") : 1, v[message] ? &message_text : nullptr);
      break;
    }
    case Kind::end_program:
      if (shape_ == Shape::flat) {
        // Written after the call already (open_flat_job), where the restructured stream has it.
        if (previous_ != Kind::end_of_job) refuse(command_offset_, "a flat job's @end_program not right after @end_of_job");
      } else {
        end_program();
      }
      break;
    case Kind::proc:
      if (shape_ == Shape::flat) refuse(command_offset_, "@proc in a flat job");
      shape_ = Shape::procedures;
      proc(integer(require(v[label], "label", "@proc"), "label"));
      break;
    case Kind::end_of_job: break;  // @end_of_job: nothing
    case Kind::end_proc:
      nb();  // {nb, 'M99'}
      out_.w = put(out_.w, " M99");
      break;
    case Kind::end_of_file:
      if (shape_ == Shape::flat) {
        if (previous_ != Kind::end_program) refuse(command_offset_, "a flat job's @end_of_file not right after @end_program");
        nb();  // the body's @end_proc
        out_.w = put(out_.w, " M99");
      }
      out_.line();  // {nl, '%'}
      *out_.w++ = '%';
      break;
    case Kind::line:
    case Kind::arc:
    case Kind::none: break;
  }
  previous_ = kind;
  return next;
}

// {'%'}  {nl, 'O'program_number, ' (', g_file_name, ')'}
void Post::start_of_file(const char* const* v) {
  const std::string_view name = text(require(v[g_file_name], "g_file_name", "@start_of_file"));
  out_.room(kLineRoom + name.size());
  out_.line();
  *out_.w++ = '%';
  out_.line();
  *out_.w++ = 'O';
  out_.w = put_int(out_.w, integer(require(v[program_number], "program_number", "@start_of_file"), "program_number"));
  out_.w = put(out_.w, " (");
  out_.w = put(out_.w, name);
  *out_.w++ = ')';
  if (v[home_number]) home_number_ = integer(v[home_number], "home_number");
}

// tool_dia = 2 * tool_offset;  {nb, '(T', tool_number, ' D'tool_dia:tool_dia_f, ')'}  ('5.3/1')
void Post::def_tool(const char* const* v) {
  Number dia = number(require(v[tool_offset], "tool_offset", "@def_tool"), "tool_offset");
  if (dia.exact && dia.mantissa < kIntPow10[15] / 2) {
    dia.mantissa *= 2;  // still at most 15 digits: the doubled text is the doubled double's
  } else {
    dia.general = 2 * to_double(dia);
    dia.exact = false;
  }
  nb();
  out_.w = put(out_.w, " (T");
  out_.w = put_int(out_.w, integer(require(v[tool_number], "tool_number", "@def_tool"), "tool_number"));
  out_.w = put_milli_one_decimal(put(out_.w, " D"), display_units(dia, 3, command_offset_));
  *out_.w++ = ')';
}

// {nb, 'G', plane_code} {' G21'} {' G40 G49 G80 G90'}  call @home_number
// @home_number: if home_number lt 1: home_number = 1;  {nb, 'G', (53 + home_number):integer_def_f}
void Post::start_program() {
  nb();
  out_.w = put_uint(put(out_.w, " G"), static_cast<std::uint64_t>(plane_code_));
  out_.w = put(out_.w, " G21 G40 G49 G80 G90");
  if (home_number_ < 1) home_number_ = 1;
  nb();
  out_.w = put_int(put(out_.w, " G"), 53 + home_number_);
}

// {nb, '(', job_name, ')'}. The first job of a stream without procedures is a flat job: it is
// written when its body opens (open_flat_job).
void Post::start_of_job(std::string_view name) {
  if (shape_ == Shape::unknown) shape_ = Shape::flat;
  if (shape_ == Shape::flat) {
    if (flat_job_seen_) refuse(command_offset_, "a second job in a flat trace");
    flat_job_seen_ = true;
    flat_call_pending_ = true;
    job_name_.assign(name);
    return;
  }
  out_.room(kLineRoom + name.size());
  nb();
  out_.w = put(out_.w, " (");
  out_.w = put(out_.w, name);
  *out_.w++ = ')';
}

// call @stop_coolant; if spindle_m gt 0: {nb, 'M5'};  spindle_m = 0
// {nb, 'G91 G28 Z0.'} {nb, 'G90'} {nb, 'M30'}
void Post::end_program() {
  if (coolant_on_) {
    nb();
    out_.w = put(out_.w, " M9");
    coolant_on_ = false;
  }
  if (spindle_m_ > 0) {
    nb();
    out_.w = put(out_.w, " M5");
  }
  spindle_m_ = 0;
  nb();
  out_.w = put(out_.w, " G91 G28 Z0.");
  nb();
  out_.w = put(out_.w, " G90");
  nb();
  out_.w = put(out_.w, " M30");
}

// @change_tool of fanuc.gpp: stop coolant and spindle, home Z, change the tool, rapid to the next
// point with the spindle on, length offset, coolant.
void Post::change_tool(const char* const* v) {
  const std::int64_t tool = integer(require(v[tool_number], "tool_number", "@change_tool"), "tool_number");
  const std::int64_t speed = integer(require(v[spin], "spin", "@change_tool"), "spin");
  Number next[3];
  const Key keys[3] = {xnext, ynext, znext};
  const char* const names[3] = {"xnext", "ynext", "znext"};
  for (int i = 0; i < 3; ++i) {
    next[i] = number(require(v[keys[i]], names[i], "@change_tool"), names[i]);
    // Not filtered by the PRP: the post holds the trace's double. Up to three decimals that is
    // the value in thousandths; more would need the double kept beside it.
    if (!next[i].exact || next[i].decimals > 3 || next[i].flag) refuse(command_offset_, "xnext/ynext/znext beyond 0.001 mm");
  }
  if (coolant_on_) {  // call @stop_coolant
    nb();
    out_.w = put(out_.w, " M9");
    coolant_on_ = false;
  }
  if (spindle_m_ > 0) {
    nb();
    out_.w = put(out_.w, " M5");
  }
  nb();
  out_.w = put(out_.w, " G91 G28 Z0.");
  nb();
  out_.w = put(out_.w, " G90");
  nb();
  out_.w = put(put_int(put(out_.w, " T"), tool), " M6");
  xpos_.assign(display_units(next[0], 3, command_offset_));  // xpos = xnext ...
  ypos_.assign(display_units(next[1], 3, command_offset_));
  zpos_.assign(display_units(next[2], 3, command_offset_));
  gcode_.assign(0);
  // call @start_tool: mcode = 4 if tool_direction eq CCW, else 3; spindle_m = mcode
  spindle_m_ = v[tool_direction] && same_word(text(v[tool_direction]), "CCW") ? 4 : 3;
  nb();  // {nb, 'G0 G90 X'xpos, ' Y'ypos, ' S', spin:integer_def_f, ' M'mcode}
  char* w = put_milli(put(out_.w, " G0 G90 X"), xpos_.value);
  w = put_milli(put(w, " Y"), ypos_.value);
  w = put_int(put(w, " S"), speed);
  out_.w = put_uint(put(w, " M"), static_cast<std::uint64_t>(spindle_m_));
  nb();  // {nb, 'G43 Z'zpos, ' H', tool_number}
  out_.w = put_int(put(put_milli(put(out_.w, " G43 Z"), zpos_.value), " H"), tool);
  gcode_.changed = xpos_.changed = ypos_.changed = zpos_.changed = false;
  feed_.changed = true;
  nb();
  out_.w = put(out_.w, " M8");
  coolant_on_ = true;
}

// {nb, 'M98 P'label}  if proc_count gt 1: {' L'proc_count}  {[' (', message, ')']}; the modal
// memory is reset after the call.
void Post::call_proc(std::int64_t label, std::int64_t count, const std::string_view* message) {
  nb();
  out_.w = put_int(put(out_.w, " M98 P"), label);
  if (count > 1) out_.w = put_int(put(out_.w, " L"), count);
  if (message) {
    out_.w = put(out_.w, " (");
    out_.w = put(out_.w, *message);
    *out_.w++ = ')';
  }
  reset_change_memory();
}

// The modal memory is reset before @proc; {nl, 'O'label}
void Post::proc(std::int64_t label) {
  reset_change_memory();
  out_.line();
  *out_.w++ = 'O';
  out_.w = put_int(out_.w, label);
}

// A flat job's body opens: what prp::ProcedureGeneration sends instead, for one job whose tool
// changes came first: @call_proc (label 1, the job's name as message) and the main program's
// @end_program, then @proc 1 and the job's @start_of_job.
void Post::open_flat_job() {
  flat_call_pending_ = false;
  out_.room(kLineRoom + 2 * job_name_.size());
  const std::string_view name = job_name_;
  call_proc(kFirstLabel, 1, &name);
  end_program();
  proc(kFirstLabel);
  nb();
  out_.w = put(out_.w, " (");
  out_.w = put(out_.w, name);
  *out_.w++ = ')';
}

// The last command that starts a line of its own in buf[0, size): the byte after a '\n' that is
// '(' or '@'. Everything before it is whole commands. 0: none.
std::size_t last_command_start(const char* buf, std::size_t size) {
  std::size_t end = size;
  while (end > 0) {
    const void* found = ::memrchr(buf, '\n', end);
    if (!found) return 0;
    const auto nl = static_cast<std::size_t>(static_cast<const char*>(found) - buf);
    if (nl + 1 < size && (buf[nl + 1] == '(' || buf[nl + 1] == '@')) return nl + 1;
    end = nl;
  }
  return 0;
}

struct Fd {
  int fd;
  explicit Fd(int f) : fd(f) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// Reads the trace in blocks and hands the post the whole commands of each.
void post_from(int fd, Post& post) {
  std::unique_ptr<char[]> buffer(new char[kReadBlock + kReadSlack]());
  char* const buf = buffer.get();
  std::size_t have = 0;      // bytes in buf: the cut-off command of the last block, then new ones
  std::uint64_t offset = 0;  // of buf[0] in the file
  bool eof = false;
  while (!eof) {
    while (have < kReadBlock) {
      const ssize_t n = ::read(fd, buf + have, kReadBlock - have);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) system_failure("cannot read the trace");
      if (n == 0) {
        eof = true;
        break;
      }
      have += static_cast<std::size_t>(n);
    }
    std::size_t cut = have;
    if (eof) {
      if (have > 0 && buf[have - 1] != '\n') buf[have++] = '\n';
      cut = have;
    } else {
      cut = last_command_start(buf, have);
      if (cut == 0) refuse(offset, "a command longer than the 1 MiB read block");
    }
    post.commands(buf, buf + cut, offset);
    std::memmove(buf, buf + cut, have - cut);
    offset += cut;
    have -= cut;
  }
  post.finish();
}

}  // namespace

Stats post_file(const std::string& trace_path, const std::string& nc_path) {
  Fd in(::open(trace_path.c_str(), O_RDONLY | O_CLOEXEC));
  if (in.fd < 0) system_failure("cannot open " + trace_path);
  ::posix_fadvise(in.fd, 0, 0, POSIX_FADV_SEQUENTIAL);
  const std::string part = nc_path + ".part";
  Fd nc(::open(part.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
  if (nc.fd < 0) system_failure("cannot write " + part);
  try {
    Out out(nc.fd);
    Post post(out);
    post_from(in.fd, post);
    out.flush();
    const int fd = nc.fd;
    nc.fd = -1;
    if (::close(fd) != 0) system_failure("cannot write " + part);
    if (std::rename(part.c_str(), nc_path.c_str()) != 0) system_failure("cannot rename " + part);
    return {post.commands_read(), out.lines(), out.bytes()};
  } catch (...) {
    ::unlink(part.c_str());
    throw;
  }
}

std::string post_text(std::string_view trace, Stats* stats) {
  std::string buffer(trace);
  if (buffer.empty() || buffer.back() != '\n') buffer += '\n';
  const std::size_t size = buffer.size();
  buffer.append(kReadSlack, '\0');
  std::string nc;
  Out out(&nc);
  Post post(out);
  post.commands(buffer.data(), buffer.data() + size, 0);
  post.finish();
  out.flush();
  if (stats) *stats = {post.commands_read(), out.lines(), out.bytes()};
  return nc;
}

}  // namespace bench::hand_post
