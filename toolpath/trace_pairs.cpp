// The inline layout's `name:value` pairs (after `==>` and `..>`), the reader's hot loop: a job is
// mostly numbers in pairs. The general rule (trace-format.md): an unquoted value runs to the
// blanks before the next `name:`, or to the end of the line, and is parsed by parse_value. The
// fast path below stores the common cases, a number or a bare word followed by blanks and the
// next `name:`, with one scan; tests/toolpath/trace_reader_inline_test.cpp holds it to the
// general rule.
#include <cassert>
#include <cstdint>
#include <cstring>
#include <string>

#include "toolpath/trace_reader.hpp"
#include "toolpath/trace_syntax.hpp"

namespace toolpath {

using namespace trace_syntax;

namespace {

// Where an unquoted inline value that starts at `v` ends: at the blanks before the next
// `name:`, else at the end of the line. It may hold blanks.
std::size_t value_end(std::string_view text, std::size_t v) {
  for (std::size_t k = v; k < text.size(); ++k) {
    if (is_blank(text[k])) {
      const std::size_t m = skip_blanks(text, k);
      if (pair_name_length(text.substr(m)) > 0) return k;
      k = m - 1;
    }
  }
  return text.size();
}

// A `name:` found in the text: its length (0: none), and whether it is the name the next parameter
// slot already holds (then the slot is taken as it is: no copy, no key lookup).
struct PairName {
  std::size_t length = 0;
  bool in_slot = false;
};

// Case-sensitive equality of `n` bytes, `n` the length of a parameter name: words of 8 or 4
// bytes, the last one overlapping the one before.
[[gnu::always_inline]] inline bool same_name_bytes(const char* a, const char* b, std::size_t n) {
  auto word8 = [](const char* s) { std::uint64_t w; std::memcpy(&w, s, 8); return w; };
  auto word4 = [](const char* s) { std::uint32_t w; std::memcpy(&w, s, 4); return w; };
  if (n >= 8) return n <= 16 ? word8(a) == word8(b) && word8(a + n - 8) == word8(b + n - 8) : std::memcmp(a, b, n) == 0;
  if (n >= 4) return word4(a) == word4(b) && word4(a + n - 4) == word4(b + n - 4);
  for (std::size_t i = 0; i < n; ++i)
    if (a[i] != b[i]) return false;
  return true;
}

// The parameter slots of the command being read: [first, last), refreshed when a slot is added.
struct Slots {
  const Parameter* first;
  const Parameter* last;
  explicit Slots(const Command& c) : first(c.parameters.data()), last(first + c.parameters.size()) {}
};

// The `name:` at `at` in `text`, for parameter slot `slot`. A recycled command mostly holds the
// names of the same command in order (ParameterShelf), so the slot's name is tried first: a keyed
// name is a known identifier, and followed by `:` it is the whole name there.
[[gnu::always_inline]] inline PairName name_at(const Slots& slots, std::size_t slot, std::string_view text, std::size_t at) {
  if (const Parameter* p = slots.first + slot; p < slots.last) {
    const std::size_t n = p->name.size();
    if (p->key != ParamKey::none && at + n < text.size() && text[at + n] == ':' &&
        same_name_bytes(text.data() + at, p->name.data(), n))
      return {n, true};
  }
  return {pair_name_length(text.substr(at)), false};
}

// The length of `name :` (blanks before the colon, then a blank or the end of the line) at the
// start of `s`, else 0: how a user parameter opens. `Note: Ask` (no blank before the colon) is text.
std::size_t user_pair_name_length(std::string_view s) {
  const std::size_t n = ident_length(s);
  if (n == 0 || n >= s.size() || !is_blank(s[n])) return 0;
  const std::size_t colon = skip_blanks(s, n);
  if (colon >= s.size() || s[colon] != ':') return 0;
  return colon + 1 == s.size() || is_blank(s[colon + 1]) ? colon + 1 : 0;
}

// Where a user parameter's value that starts at `v` ends: at the blanks before the next
// `name :`, else at the end of the line. It may hold blanks and colons.
std::size_t user_value_end(std::string_view text, std::size_t v) {
  for (std::size_t k = v; k < text.size(); ++k) {
    if (!is_blank(text[k])) continue;
    const std::size_t m = skip_blanks(text, k);
    if (user_pair_name_length(text.substr(m)) > 0) return k;
    k = m - 1;
  }
  return text.size();
}

// The pair at `at` when its name is the one parameter slot `p` holds (then the name is taken as
// it is: no copy, no key lookup): where its value starts, else nullptr. A keyed name is a known
// identifier, so followed by `:` it is the whole name there.
[[gnu::always_inline]] inline const char* slot_value(const Parameter& p, const char* at, const char* end) {
  const std::size_t n = p.name.size();
  if (p.key == ParamKey::none || at + n >= end || at[n] != ':' || !same_name_bytes(at, p.name.data(), n)) return nullptr;
  return at + n + 1;
}

// Where the text of a line ends, for the common run below. The general rule cut the line at its
// '\n' and knows the end; the reader's fast path does not, and takes a '\n' (or "\r\n", as
// read_line strips the '\r') where a value or the blanks after it end for the line end: no name,
// number, word or blank the run reads holds one, so the run never steps over it.
// The fast path remembers numbers and screens values (KeyMemo); the general rule reads every
// number afresh, and a line it reads leaves the command unscreened.
struct KnownEnd {
  static constexpr bool kRemembers = false;
  const char* end;
  bool at(const char* k) const { return k == end; }
  const char* bound() const { return end; }  // the names compared lie below it
};
struct NewlineEnd {
  static constexpr bool kRemembers = true;
  const char* chunk_end;  // the string's '\0' there stops every scan
  bool at(const char* k) const { return *k == '\n' || (*k == '\r' && k[1] == '\n'); }
  const char* bound() const { return chunk_end; }
};

// The common run of pairs, from `q` on: each named as the next slot of `out` already is, its
// value a number (with its change flag) that needs no from_chars, or a bare word, then blanks and
// the next such pair, or the end of the line. They are stored without the general loop's state.
// A value is stored as soon as it is read, before what follows it is looked at: when that is
// not the end of the line or the next slot's pair, the run stops at the pair, not counted, and
// the general loop reads it again from its name and stores it over (or throws). Returns where the
// run stopped: the end of the line (end.at() holds) when it read everything; `used` counts the
// slots filled. A value's column is column_base plus its address (below 2^32: see kMaxLine).
// When End is the fast path's: `memos` holds the numbers last read and the screens, one per key
// (KeyMemo), and `screening` collects the screens' verdicts on the values stored.
struct Screening {
  std::uint32_t need = 0;
  bool passed = true;
};
template <class End>
[[gnu::always_inline]] inline const char* run_pairs(Command& out, std::size_t& used, const char* q, End end,
                                                    std::uintptr_t column_base, std::uint32_t line, KeyMemo* memos,
                                                    Screening& screening) {
  Parameter* p = out.parameters.data() + used;
  Parameter* const last = out.parameters.data() + out.parameters.size();
  const char* v = p < last ? slot_value(*p, q, end.bound()) : nullptr;
  if (!v) return q;
  for (;;) {
    // Here `v` is where the value of the pair at `q`, for slot `p`, starts.
    p->line = line;
    p->column = static_cast<std::uint32_t>(column_base + reinterpret_cast<std::uintptr_t>(v));
    const char* k;  // where the value ends
    KeyMemo* memo = nullptr;
    bool recalled = false;
    if constexpr (End::kRemembers) {
      memo = memos + static_cast<std::size_t>(p->key);
      screening.need |= memo->screen.need;
      if (memo->holds(v, end.bound())) {
        k = memo->recall(v, p->value);
        screening.passed &= memo->passed;
        recalled = true;
      }
    }
    if (recalled) {
    } else if (const NumberScan number = scan_terminated_number(v); number.length > 0) {
      k = v + number.length;
      const ChangeFlag flag = flag_letter(*k);
      k += flag != ChangeFlag::None;
      if (!store_exact_number(p->value, number, flag)) break;
      if constexpr (End::kRemembers) {
        const bool passes = memo->screen.passes(p->value);
        screening.passed &= passes;
        memo->keep(v, k, end.bound(), p->value, passes);
      }
    } else if (is_ident_start(*v)) {
      k = v + 1;
      while (is_ident_char(*k)) ++k;
      store_word(p->value, {v, static_cast<std::size_t>(k - v)});
      if constexpr (End::kRemembers) screening.passed &= memo->screen.passes(p->value);
    } else {
      break;
    }
    // Then the end of the line, or blanks and the next slot's pair. The byte after the line is not
    // a blank: the blanks end by then.
    if (!end.at(k)) {
      if (*k != ' ' && *k != '\t') break;  // is_blank, without the table's address in a register
      do ++k;
      while (*k == ' ' || *k == '\t');
      if (!end.at(k)) {
        if (p + 1 == last || !(v = slot_value(p[1], k, end.bound()))) break;
        ++p;
        q = k;
        continue;
      }
    }
    ++p;
    q = k;
    break;
  }
  used = static_cast<std::size_t>(p - out.parameters.data());
  return q;
}

// run_pairs on the text of a line from offset `at` (its byte in column `column`): the offset
// where it stopped, text.size() when it read everything.
[[gnu::always_inline]] inline std::size_t common_pairs(Command& out, std::size_t& used, std::string_view text, std::size_t at,
                                                       std::size_t column, std::uint32_t line) {
  const char* const start = text.data();
  const std::uintptr_t column_base = column - reinterpret_cast<std::uintptr_t>(start);
  Screening none;
  return static_cast<std::size_t>(
      run_pairs(out, used, start + at, KnownEnd{start + text.size()}, column_base, line, nullptr, none) - start);
}

}  // namespace

// The job's and the machine's user parameters, as SolidCAM writes them on `..>` lines of
// @start_of_file and @start_of_job: `name : value` pairs separated by blanks, the value unquoted
// and possibly empty or holding blanks and colons (`sWCM_MSG : Note: Ask your supervisor!`).
// Values are typed as anywhere else (parse_value_into); the post's variable converts them.
void TraceReader::parse_user_pairs(Command& out, std::string_view text, std::size_t i, std::size_t column) {
  while (i < text.size()) {
    const std::size_t n = user_pair_name_length(text.substr(i));
    if (n == 0) fail(column + i, "expected `name : value`");
    Parameter& param = add_parameter(out, used_parameters_, text.substr(i, ident_length(text.substr(i))));
    std::size_t v = skip_blanks(text, i + n);
    // An empty value: the next pair (or the end of the line) follows at once.
    const std::size_t end = user_pair_name_length(text.substr(v)) > 0 ? v : user_value_end(text, v);
    mark_position(param, line_number_, column + v);
    parse_value_into(param.value, text.substr(v, end - v), Place{file_, line_number_, column + v});
    i = skip_blanks(text, end);
  }
}

namespace trace_syntax {

Parameter& new_slot(Command& out, std::size_t& used, std::string_view name) {
  if (used == out.parameters.size()) out.parameters.emplace_back();
  Parameter& p = out.parameters[used++];
  p.rename(name);
  return p;
}

}  // namespace trace_syntax

// The text after `==>` or `..>`: blank-separated `name:value` pairs, or free text kept as
// `otherwise`. `text` runs to the end of line_, so the byte after it is '\n', '\r' or '\0'
// (read_line): the scans below may look at it.
void TraceReader::parse_pairs(Command& out, std::string_view text, std::size_t column, TraceLine::Kind otherwise) {
  assert(text.data() + text.size() == line_.data() + line_.size());
  screen_passed_ = false;
  const std::size_t i = skip_blanks(text, 0);
  if (i == text.size()) return;
  // Most lines are one common run to their end; the general loop takes what is left.
  std::size_t used = used_parameters_;
  const std::size_t stopped = common_pairs(out, used, text, i, column, line32_);
  used_parameters_ = used;
  if (stopped != text.size()) parse_other_pairs(out, text, stopped, column, otherwise);
}

// The fast path's lines: the pairs from `p`, in the line that starts at `line` in the chunk, to the
// end of that line, then every `..>` continuation after it, each line taken (counted, and the
// reader moved past it) when the common run reads its pairs whole (or it has none). Returns the
// number of lines taken: the first line not taken is left to the general rule, which reads it
// again from its start and stores over what the run stored.
std::size_t TraceReader::fast_lines(Command& out, const char* p, const char* line) {
  const NewlineEnd end{buffer_.data() + buffer_.size()};
  std::size_t taken = 0;
  std::size_t used = used_parameters_;
  // Also the pairs of a line not taken: the general rule reads it, and the command is unscreened.
  Screening screening;
  const auto done = [&] {
    screen_need_ |= screening.need;
    screen_passed_ &= screening.passed;
    return taken;
  };
  for (;;) {
    p = skip_terminated_blanks(p, end.chunk_end);
    if (!end.at(p)) {
      p = run_pairs(out, used, p, end, 1 - reinterpret_cast<std::uintptr_t>(line), next_line32(), memos_.get(), screening);
      if (!end.at(p)) return done();
    }
    used_parameters_ = used;
    line = p + (*p == '\r' ? 2 : 1);
    take_line(line);
    ++taken;
    p = skip_terminated_blanks(line, end.chunk_end);
    if (p[0] != '.' || p[1] != '.' || p[2] != '>') return done();  // each read only after the one before matched
    p += 3;
  }
}

// The pairs from `i` on, where the common run stopped (at the first pair when it took none).
[[gnu::noinline]] void TraceReader::parse_other_pairs(Command& out, std::string_view text, std::size_t i, std::size_t column,
                                    TraceLine::Kind otherwise) {
  // The slots used so far, in a register while the pairs are read (the stores into the values
  // could alias a member); written back to used_parameters_ before each return.
  std::size_t used = used_parameters_;
  std::size_t stopped = i;  // the common run stopped here: not tried again
  Slots slots(out);
  PairName name = name_at(slots, used, text, i);
  if (name.length == 0) {  // no pair yet (the run stops only before a `name:`)
    if (user_pair_name_length(text.substr(i)) > 0) return parse_user_pairs(out, text, i, column);
    // SolidCAM's words for a command without parameters (`(1)@end_of_file     ==> no parameters`).
    if (otherwise == TraceLine::Kind::Partial && trim_right(text.substr(i)) == "no parameters") return;
    // Free text: the whole remainder without the one separating blank.
    std::string_view kept = text.substr(text.front() == ' ' ? 1 : 0);
    out.trace.push_back({otherwise, std::string(otherwise == TraceLine::Kind::Partial ? kept : trim_right(kept))});
    return;
  }
  // Where the next pair starts when the value's first token, ending at `k`, is followed by blanks
  // and the next `name:` (then in `next`) or by the end of the line (text.size()); npos otherwise.
  PairName next;
  auto next_pair_after = [&](std::size_t k) __attribute__((always_inline)) {
    if (k == text.size()) return k;
    if (!is_blank(text[k])) return std::string_view::npos;
    std::size_t m = k + 1;
    if (is_blank(text.data()[m])) m = skip_blanks(text, m);
    if (m == text.size()) return m;
    next = name_at(slots, used, text, m);
    return next.length > 0 ? m : std::string_view::npos;
  };
  for (;;) {
    // Here `name` is the `name:` at i.
    if (name.in_slot && i != stopped) {
      const std::size_t from = i;
      stopped = i = common_pairs(out, used, text, i, column, line32_);
      if (i == text.size()) return void(used_parameters_ = used);
      if (i != from) name = name_at(slots, used, text, i);
    }
    Parameter* param_slot;
    if (name.in_slot) {
      param_slot = &out.parameters[used++];
    } else {
      std::size_t count = used;  // its address goes to new_slot, not used's
      param_slot = &add_parameter(out, count, text.substr(i, name.length));
      used = count;
      slots = Slots(out);  // it may have added a slot
    }
    Parameter& param = *param_slot;
    const std::size_t v = i + name.length + 1;
    param.line = line32_;
    param.column = static_cast<std::uint32_t>(column + v);  // below 2^32: see kMaxLine
    const char first = text.data()[v];  // the terminator when the value is empty
    std::size_t end;
    if (first == '\'' || first == '"') {
      // A quoted value ends at its quote followed by a blank or the end of the line.
      std::size_t k = v + 1;
      for (;; ++k) {
        k = text.find(first, k);
        if (k == std::string_view::npos)
          fail(column + text.size(), std::string("expected closing ") + first + " of the string");
        if (k + 1 == text.size() || is_blank(text[k + 1])) break;
      }
      end = k + 1;
    } else if (const NumberScan number = scan_terminated_number(text.data() + v); number.length > 0) {
      // The common case, a number (with its change flag) then blanks and the next `name:` or the
      // end of the line: stored at once. Anything else after the digits takes the general path.
      std::size_t k = v + number.length;
      const ChangeFlag flag = flag_letter(text.data()[k]);
      if (flag != ChangeFlag::None) ++k;
      if (const std::size_t m = next_pair_after(k); m != std::string_view::npos) {
        if (!store_exact_number(param.value, number, flag))
          store_number(param.value, number, text.substr(v, number.length), flag, Place{file_, line_number_, column + v});
        if (m == text.size()) return void(used_parameters_ = used);
        i = m;
        name = next;
        continue;
      }
      end = value_end(text, v);
    } else if (is_ident_start(first)) {
      // A bare word (an enumeration, TRUE, FALSE) then the same: stored at once as well.
      std::size_t k = v + 1;
      while (is_ident_char(text.data()[k])) ++k;
      if (const std::size_t m = next_pair_after(k); m != std::string_view::npos) {
        store_word(param.value, text.substr(v, k - v));
        if (m == text.size()) return void(used_parameters_ = used);
        i = m;
        name = next;
        continue;
      }
      end = value_end(text, v);
    } else {
      end = value_end(text, v);
    }
    parse_value_into(param.value, text.substr(v, end - v), Place{file_, line_number_, column + v});
    i = skip_blanks(text, end);
    if (i == text.size()) return void(used_parameters_ = used);
    name = name_at(slots, used, text, i);
    if (name.length == 0) fail(column + i, "expected `name:value`");
  }
}

}  // namespace toolpath
