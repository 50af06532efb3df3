// One value of a `.trace` pair: the general rule (trace-format.md), used for every value the
// reader's inline fast path does not store itself.
#include <charconv>
#include <string>

#include "toolpath/bounded_read.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/short_text.hpp"
#include "toolpath/trace_syntax.hpp"

namespace toolpath {
namespace trace_syntax {

void store_number(Value& out, const NumberScan& n, std::string_view digits, ChangeFlag flag, const Place& where) {
  if (store_exact_number(out, n, flag)) return;
  const char* first = digits.data() + (digits.front() == '+' ? 1 : 0);
  const char* last = digits.data() + digits.size();
  out.flag = flag;
  if (!n.numeric) {
    out.kind = ValueKind::Integer;
    auto [ptr, ec] = std::from_chars(first, last, out.integer);
    if (ec != std::errc() || ptr != last) where.fail(0, "integer out of range: " + excerpt(digits));
    return;
  }
  out.kind = ValueKind::Numeric;
  auto [ptr, ec] = std::from_chars(first, last, out.numeric);
  if (ec != std::errc() || ptr != last) where.fail(0, "number out of range: " + excerpt(digits));
}

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
  // A bare word is TRUE, FALSE or an enumeration; anything else is free text (user parameters may
  // hold unquoted words with blanks: `Salamat Abzar Check Shavad!!`).
  if (ident_length(text) == text.size()) return store_word(out, text);
  out.kind = ValueKind::String;
  out.text.assign(text);
}

}  // namespace trace_syntax

Value parse_value(std::string_view text, const SourcePosition& where) {
  Value v;
  trace_syntax::parse_value_into(v, text, trace_syntax::Place{where.file, where.line, where.column});
  return v;
}

}  // namespace toolpath
