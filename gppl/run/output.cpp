// The generate statement and the output line model: spec 6.2 (nb, nl, skipline one-shot, flush,
// remove_blanks, end_block_text, directives), 6.3 (block numbers and the separator rule),
// 6.4 (format selection), 6.5 (modal groups, gcode_space), 6.6 (col, colrel).
#include <fmt/format.h>

#include "gppl/run/machine.hpp"

namespace gppl {

namespace {

// `!!verb file=X!!` lines are executed by the host, never written (6.7): no blank removal or
// end-of-block text for them.
bool is_directive(std::string_view line) {
  std::size_t first = 0, end = line.size();  // a loop: find_first_not_of costs a memchr per character
  while (first < end && line[first] == ' ') ++first;
  if (first == end || line[first] != '!') return false;
  while (line[end - 1] == ' ') --end;
  return end - first >= 4 && line[first + 1] == '!' && line[end - 1] == '!' && line[end - 2] == '!';
}

// A number (integer, numeric or logical) into `out`; the printer's error 410 gets the item's position.
[[gnu::always_inline]] inline void write_number(const Program& program, const GenItem& item, const DisplayFormat& f, const Value& v,
                                                OutputLine& out) {
  try {
    out.commit(write_formatted(out.room(formatted_room), f, v));
  } catch (const Error& e) {
    throw Error(e.number(), program.position(item.pos), e.text());
  }
}

constexpr std::string_view kIntegerDefault = "5.0(p)";
constexpr std::string_view kNumericDefault = "5.3";

}  // namespace

void Interpreter::State::open_line(bool after_break) {
  line.clear();
  line_open = true;
  separator_pending = false;
  origin.after_break = after_break;
  if (!frames.empty()) origin.procedure = program.procedures[frames.back().procedure].name;
  else origin.procedure = {};
  origin.source_line = current ? int(current->pos.line) : 0;
  origin.source_file = current ? std::string_view(program.files[current->pos.file]) : std::string_view();
}

void Interpreter::State::append_opening(std::string_view text) {
  if (!line_open) open_line();
  if (separator_pending && !text.empty()) {
    if (text.front() != ' ') line.push_back(' ');
    separator_pending = false;
  }
  line.append(text);
}

void Interpreter::State::flush() {
  if (!line_open) return;
  line_open = false;
  // The blank after a block number is written even when nothing follows it: SolidCAM's `{nb}`
  // alone gives `N210370 ` (docs/gppl-language.md, "Block numbers").
  if (separator_pending) line.push_back(' ');
  separator_pending = false;
  if (!is_directive(line)) {
    if (globals[program.slots.remove_blanks].value.logical) line.remove_all(' ');
    const std::string& end_text = globals[program.slots.end_block_text].value.text;
    if (!end_text.empty()) line.append(end_text);  // usually there is none
  }
  sink.write_line(line, origin);
  if (trace != nullptr) trace_output(line);
}

void Interpreter::State::new_block(SourcePos pos) {
  Cell& skip = globals[program.slots.skipline];
  if (!skip.value.logical) {
    // One-shot: this nb continues the current line, the next one starts a block again (6.2).
    assign(skip, Value::of_logical(true), ChangeOverride::Compute, nullptr);
    return;
  }
  flush();
  open_line(true);
  if (!globals[program.slots.blknum_exist].value.logical || !globals[program.slots.blknum_gen].value.logical) return;
  Cell& number = globals[program.slots.blknum];
  const std::int64_t n = number.value.integer;
  const std::int64_t max = globals[program.slots.blknum_max].value.integer;
  if (n > max) fail_at(pos, ErrorCode::BlockNumberTooBig, {}, fmt::format("blknum {} is above blknum_max {}: raise blknum_max in @init_post, "
                                                                              "or set blknum back when it gets there", n, max));
  line.append(globals[program.slots.blknum_letter].value.text);
  const std::string& spec = globals[program.slots.blknum_f].value.text;
  const DisplayFormat& f = cached(format_sites[program.format_sites + 2],
                                  spec.empty() ? std::string_view(globals[program.slots.integer_def_f].value.text) : spec, pos);
  try {
    line.commit(write_formatted(line.room(formatted_room), f, n));
  } catch (const Error& e) {
    throw Error(e.number(), program.position(pos), e.text());
  }
  if (program.uses_line_functions) sink.block_numbered(n);
  const std::int64_t next = n + globals[program.slots.blknum_delta].value.integer;
  if (number.typed && number.value.type == Type::Integer) {  // assign() without a Value to carry it
    number.value.integer = next;
    mark_assigned(number, next != n, ChangeOverride::Compute);
  } else {
    assign(number, Value::of_integer(next), ChangeOverride::Compute, nullptr);
  }
  separator_pending = true;
}

void Interpreter::State::new_line() {
  flush();
  open_line(true);
  Cell& skip = globals[program.slots.skipline];
  if (!skip.value.logical) assign(skip, Value::of_logical(true), ChangeOverride::Compute, nullptr);
}

const DisplayFormat& Interpreter::State::parse_format(FormatCache& cache, std::string_view spec, SourcePos pos) {
  try {
    cache.format.emplace(parse_display_format(spec));
  } catch (const Error& e) {
    cache.format.reset();
    throw Error(e.number(), program.position(pos), fmt::format("{} in display format '{}'", e.text(), spec));
  }
  cache.spec.assign(spec);
  return *cache.format;
}

const DisplayFormat& Interpreter::State::format_for(const GenItem& item, const Value& v) {
  FormatCache& site = format_sites[item.site];
  switch (item.format_kind) {
    case FormatKind::Constant: {  // its text never changes: parsed once
      FormatCache& constant = constant_formats[item.format];
      return constant.format ? *constant.format : parse_format(constant, program.format_specs[item.format], item.pos);
    }
    case FormatKind::Dynamic: {
      Value& spec = push_scratch();
      eval(item.format, spec);
      if (spec.type != Type::String)
        fail_at(item.pos, ErrorCode::NotString, {}, "a display format must be a string");
      if (!spec.text.empty()) {
        const DisplayFormat& f = cached(site, spec.text, item.pos);
        pop_scratch();
        return f;
      }
      pop_scratch();
      break;
    }
    case FormatKind::Default:
      if (item.name_format != kNone) {
        const std::string& spec = cell(program.refs[item.name_format]).value.text;
        if (!spec.empty()) return cached(site, spec, item.pos);
      }
      break;
  }
  // Rules 3 and 4 of 6.4: integer_def_f for integers and logicals, numeric_def_f for numerics.
  const bool numeric = v.type == Type::Numeric;
  const std::string& spec = globals[numeric ? program.slots.numeric_def_f : program.slots.integer_def_f].value.text;
  return cached(format_sites[program.format_sites + (numeric ? 1 : 0)],
                spec.empty() ? (numeric ? kNumericDefault : kIntegerDefault) : std::string_view(spec), item.pos);
}

void Interpreter::State::render(const GenItem& item, OutputLine& out) {
  if (item.kind == ItemKind::Text) {
    out.append(program.constants[item.a].text);
    return;
  }
  if (item.ref != kNone) {  // a variable: no scratch value, and its format is usually known already
    const Value& value = item_cell(item).value;
    if (value.type == Type::String) {
      out.append(value.text);  // strings print verbatim; a format is ignored (6.4)
      return;
    }
    const DisplayFormat* f = known_format(item, value);
    write_number(program, item, f ? *f : format_for(item, value), value, out);
    return;
  }
  Value& v = push_scratch();
  eval(item.a, v);
  if (v.type == Type::String) {
    out.append(v.text);
  } else {
    try {
      write_number(program, item, format_for(item, v), v, out);
    } catch (...) {
      pop_scratch();
      throw;
    }
  }
  pop_scratch();
}

// The usual value item, a global number in a format already parsed, straight into the open line
// (no render() call); false, having done nothing, for any other.
[[gnu::always_inline]] inline bool Interpreter::State::write_known_value(const GenItem& item, bool clear_change) {
  if (!line_open || item.global_cell == kNone) return false;
  Cell& c = globals[item.global_cell];
  const DisplayFormat* f = c.value.type != Type::String ? known_format(item, c.value) : nullptr;
  if (!f) return false;
  const std::size_t at = line.size();
  write_number(program, item, *f, c.value, line);
  if (separator_pending && line.size() > at) {  // the separator blank goes in front if the text needs one
    if (line[at] != ' ') line.insert(at, ' ');
    separator_pending = false;
  }
  if (clear_change) c.changed = false;
  return true;
}

void Interpreter::State::generate(std::uint32_t first, std::uint32_t count) {
  const bool clear_change = globals[program.slots.clear_change_after_gen].value.logical;
  const GenItem* const items = program.items.data();  // read once: the line's stores may alias it
  for (std::uint32_t i = first; i < first + count; ++i) {
    const GenItem& item = items[i];
    switch (item.kind) {
      case ItemKind::NewBlock: new_block(item.pos); break;
      case ItemKind::NewLine: new_line(); break;
      case ItemKind::Col:
      case ItemKind::ColRel: {
        Value& v = push_scratch();
        eval(item.a, v);
        const std::int64_t n = to_integer(v);
        pop_scratch();
        if (!line_open) open_line();
        const std::int64_t blanks = item.kind == ItemKind::ColRel ? n : n - 1 - std::int64_t(line.size());
        if (blanks > 0) {
          if (blanks > 10000) fail_at(item.pos, ErrorCode::OutOfRange, {}, fmt::format("column {} is too far", n));
          piece.clear();
          piece.append_fill(std::size_t(blanks), ' ');
          append(piece);
        }
        break;
      }
      case ItemKind::Text: append(program.constants[item.a].text); break;
      case ItemKind::Value: {
        if (write_known_value(item, clear_change)) break;
        if (line_open) {
          // Straight into the line; the separator blank goes in front afterwards if the text needs one.
          const std::size_t at = line.size();
          try {
            render(item, line);
          } catch (...) {
            line.shrink(at);
            throw;
          }
          if (separator_pending && line.size() > at) {
            if (line[at] != ' ') line.insert(at, ' ');
            separator_pending = false;
          }
        } else {
          piece.clear();
          render(item, piece);
          append(piece);
        }
        if (clear_change && item.ref != kNone) item_cell(item).changed = false;
        break;
      }
      case ItemKind::LineFunction:
        line_function_text.clear();
        render_line_function(item, line_function_text);
        append(line_function_text);
        break;
      case ItemKind::Group: {
        // Its members follow it: a group that prints simply goes on with them (nested groups too).
        if (group_required(item)) {
          if (item.text_value_pair) {  // [' X'xpos]: both members here, as their own cases would
            append(program.constants[items[i + 1].a].text);
            if (write_known_value(items[i + 2], clear_change)) i += 2;
            else ++i;  // the value goes the general way
          }
          break;
        }
        const std::uint32_t members = item.a;
        if (item.has_gcode && globals[program.slots.gcode_space].value.logical) {
          // gcode_space: the suppressed G field becomes as many blanks as it would have printed (6.5).
          piece.clear();
          for (std::uint32_t k = i + 1; k <= i + members; ++k) {
            const GenItem& m = items[k];
            if (m.kind == ItemKind::Text || m.kind == ItemKind::Value) render(m, piece);
          }
          if (!line_open) open_line();
          if (separator_pending) line.push_back(' ');
          separator_pending = false;
          line.append_fill(piece.size(), ' ');
        }
        i += members;
        break;
      }
    }
  }
}

}  // namespace gppl
