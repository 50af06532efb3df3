#include "prp/params/loader.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "prp/params/grammar.hpp"
#include "toolpath/bounded_read.hpp"

namespace prp {
namespace {

// Non-breaking spaces (UTF-8 C2 A0, or a lone A0 byte of a Windows code page) become blanks, byte
// for byte, so columns and offsets stay those of the original line.
std::string blank_nbsp(std::string_view line) {
  std::string out(line);
  for (std::size_t i = 0; i < out.size(); ++i) {
    auto c = static_cast<unsigned char>(out[i]);
    if (c == 0xC2 && i + 1 < out.size() && static_cast<unsigned char>(out[i + 1]) == 0xA0) {
      out[i] = out[i + 1] = ' ';
      ++i;
    } else if (c == 0xA0 && (i == 0 || static_cast<unsigned char>(line[i - 1]) < 0x80)) {
      out[i] = ' ';
    }
  }
  return out;
}

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

}  // namespace

Loader::Loader(std::string file_name, Units units) {
  params_.file_ = std::move(file_name);
  params_.units_ = units;
}

toolpath::SourcePosition Loader::at(std::size_t column, std::size_t line) const {
  return {params_.file_, line ? line : line_, column};
}

void Loader::error(std::size_t column, std::string message, std::size_t line) {
  errors_.push_back({at(column, line), toolpath::Severity::Error, std::move(message)});
}

void Loader::warning(std::size_t column, std::string message, std::size_t line) {
  params_.warnings_.push_back({at(column, line), toolpath::Severity::Warning, std::move(message)});
}

MachineParameters Loader::run(std::string_view text) {
  // A SolidCAM machine ID file (VMID) is XML: recognised by content, whatever its extension.
  std::string_view start = text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text;
  const std::size_t first = start.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && start[first] == '<') return run_vmid(text);

  std::size_t number = 0;
  std::size_t last_length = 0;
  while (!text.empty() || number == 0) {
    std::size_t end = text.find('\n');
    std::string_view raw = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    ++number;
    last_length = raw.size();
    line(raw, number);
    if (text.empty()) break;
  }
  line_ = number;
  if (state_ == State::BeforeHeader)
    error(1, "expected `@pre_processor`: the file has no parameter section", 1);
  else if (state_ == State::Body)
    error(last_length + 1, "expected `endp` before the end of the file (is the file truncated?)");

  return finish();
}

MachineParameters Loader::finish() {
  check_ranges();
  fill_defaults();
  if (!errors_.empty()) {
    std::stable_sort(errors_.begin(), errors_.end(), [](const Diagnostic& a, const Diagnostic& b) {
      return a.where.line != b.where.line ? a.where.line < b.where.line : a.where.column < b.where.column;
    });
    throw LoadError(std::move(errors_));
  }
  return std::move(params_);
}

void Loader::error_at(toolpath::SourcePosition where, std::string message) {
  errors_.push_back({std::move(where), toolpath::Severity::Error, std::move(message)});
}

void Loader::warning_at(toolpath::SourcePosition where, std::string message) {
  params_.warnings_.push_back({std::move(where), toolpath::Severity::Warning, std::move(message)});
}

bool Loader::add_parameter(Parameter p) {
  const std::string lkey = lower(p.key);
  if (params_.index_.count(lkey)) return false;
  params_.index_.emplace(lkey, params_.parameters_.size());
  params_.parameters_.push_back(std::move(p));
  return true;
}

void Loader::line(std::string_view original, std::size_t number) {
  namespace pegtl = tao::pegtl;
  line_ = number;
  const std::string text = blank_nbsp(original);
  if (grammar::matches<grammar::empty_line>(text)) return;

  const std::size_t first = text.find_first_not_of(" \t") + 1;
  if (state_ == State::AfterEnd) {
    warning(first, "text after `endp` is ignored");
    return;
  }
  if (state_ == State::BeforeHeader) {
    pegtl::memory_input in(text, "");
    if (pegtl::parse<grammar::header>(in)) {
      state_ = State::Body;
      std::string_view rest = std::string_view(text).substr(text.find('@') + 14);
      std::size_t r = rest.find_first_not_of(" \t");
      if (r != std::string_view::npos && rest[r] != ';')
        warning(text.size() - rest.size() + r + 1, "text after `@pre_processor` is ignored");
      return;
    }
    error(first, "expected `@pre_processor` before the first statement");
    state_ = State::Body;  // read on, to report every other problem too
  }
  if (grammar::matches<grammar::end_line>(text)) {
    state_ = State::AfterEnd;
    return;
  }

  // key = value ; comment
  std::size_t key_begin = first - 1;
  std::size_t key_end = key_begin;
  while (key_end < text.size() && (std::isalnum(static_cast<unsigned char>(text[key_end])) || text[key_end] == '_'))
    ++key_end;
  std::size_t eq = key_end;
  while (eq < text.size() && is_blank(text[eq])) ++eq;
  if (key_end == key_begin || std::isdigit(static_cast<unsigned char>(text[key_begin])) ||
      eq >= text.size() || text[eq] != '=' || !grammar::matches<grammar::assignment>(text)) {
    if (grammar::matches<grammar::header>(text))
      error(first, "`@pre_processor` appears twice");
    else
      error(first, "expected `key = value` (a key starts with a letter or '_')");
    return;
  }
  std::size_t value_end = std::min(text.find(';', eq), text.size());
  std::size_t value_begin = eq + 1;
  while (value_begin < value_end && is_blank(text[value_begin])) ++value_begin;
  while (value_end > value_begin && is_blank(text[value_end - 1])) --value_end;
  assignment(original, std::string_view(original).substr(key_begin, key_end - key_begin), key_begin + 1,
             value_begin, value_end);
}

void Loader::assignment(std::string_view original, std::string_view key, std::size_t key_column,
                        std::size_t value_begin, std::size_t value_end) {
  // Values are read from the nbsp-free copy; strings keep their original bytes.
  const std::string clean = blank_nbsp(original);
  std::string_view value = std::string_view(clean).substr(value_begin, value_end - value_begin);
  const std::size_t column = value_begin + 1;

  std::string_view lang;
  // Real posts leave keys empty (`_4th_axes_around =`): not set, the engine default applies.
  const KeyInfo* known = find_key(key);
  if (value.empty() && (!known || known->kind != ValueKind::String)) {
    if (!known && !record_base(key, lang)) remember_unknown(original, key, key_column, value_begin, value_end);
    return;
  }
  if (auto base = record_base(key, lang)) {
    record(*base, lang, key, value, column);
    return;
  }
  const std::string lkey = lower(key);
  const KeyInfo* info = find_key(key);
  if (!info) {
    remember_unknown(original, key, key_column, value_begin, value_end);
    return;
  }
  Parameter p;
  p.key = std::string(key);
  p.kind = info->kind;
  p.raw = std::string(original.substr(value_begin, value_end - value_begin));
  p.where = at(column);
  if (!parse_scalar(*info, value, column, p)) return;  // the key keeps its default
  if (info->kind == ValueKind::String) p.text = p.raw;

  if (auto it = params_.index_.find(lkey); it != params_.index_.end()) {
    Parameter& old = params_.parameters_[it->second];
    warning(key_column, fmt::format("`{}` is set again (first at line {}): the last value wins", key,
                                    old.where.line));
    old = std::move(p);
    return;
  }
  params_.index_.emplace(lkey, params_.parameters_.size());
  params_.parameters_.push_back(std::move(p));
}

void Loader::remember_unknown(std::string_view original, std::string_view key, std::size_t key_column,
                              std::size_t value_begin, std::size_t value_end) {
  UnknownKey u{std::string(key), std::string(original.substr(value_begin, value_end - value_begin)),
               at(value_begin + 1)};
  auto it = std::find_if(params_.unknown_.begin(), params_.unknown_.end(),
                         [&](const UnknownKey& k) { return toolpath::iequals(k.key, key); });
  if (it != params_.unknown_.end()) {
    *it = std::move(u);  // the last value wins, as for known keys; warned about once
    return;
  }
  warning(key_column, fmt::format("unknown key `{}`: kept as text for the post", toolpath::excerpt(key)));
  params_.unknown_.push_back(std::move(u));
}

void Loader::check_ranges() {
  auto get = [&](std::string_view key) -> const Parameter* { return params_.find(key); };
  auto later = [](const Parameter* a, const Parameter* b) { return a->where.line >= b->where.line ? a : b; };

  for (std::string_view prefix : {"prog_num", "proc_num"}) {
    const Parameter* lo = get(std::string(prefix) + "_min");
    const Parameter* hi = get(std::string(prefix) + "_max");
    const Parameter* df = get(std::string(prefix) + "_dflt");
    if (lo && hi && lo->integer > hi->integer) {
      const Parameter* at_ = later(lo, hi);
      error(at_->where.column, fmt::format("{}_min {} is above {}_max {}", prefix, lo->integer, prefix, hi->integer),
            at_->where.line);
    }
    if (df && lo && df->integer < lo->integer) {
      const Parameter* at_ = later(df, lo);
      error(at_->where.column, fmt::format("{}_dflt {} is below {}_min {}", prefix, df->integer, prefix, lo->integer),
            at_->where.line);
    }
    if (df && hi && df->integer > hi->integer) {
      const Parameter* at_ = later(df, hi);
      error(at_->where.column, fmt::format("{}_dflt {} is above {}_max {}", prefix, df->integer, prefix, hi->integer),
            at_->where.line);
    }
  }
  if (const Parameter* p = get("arc_max_chord"); p && (p->metric[0] <= 0 || p->inch[0] <= 0))
    error(p->where.column, "arc_max_chord must be greater than 0", p->where.line);
  if (const Parameter* p = get("arc_max_deviation"); p && !(p->metric[0] > 0 && p->inch[0] > 0))
    error(p->where.column, "arc_max_deviation must be greater than 0", p->where.line);
  if (const Parameter* p = get("arc_max_angle"); p) {
    for (double a : {p->metric[0], p->inch[0]})
      if (!(a > 0 && a <= 360)) {  // 360: whole circles allowed (SolidCAM's VMIDs write MaxArcAngle="360")
        error(p->where.column, "arc_max_angle must be in (0, 360] degrees", p->where.line);
        break;
      }
  }
  for (std::string_view key : {"eps_angle", "eps_line", "zero_value", "arc_min_length"}) {
    if (const Parameter* p = get(key); p && (p->metric[0] < 0 || p->inch[0] < 0))
      error(p->where.column, fmt::format("{} must not be negative", key), p->where.line);
  }
}

void Loader::fill_defaults() {
  // Engine defaults (spec 3.0) go through the same value parser as file text, silently (the
  // stated inch defaults are rounded, not converted: 1 mm / 0.05 inch).
  const std::size_t warnings = params_.warnings_.size();
  for (const KeyInfo& info : all_keys()) {
    if (info.default_text.empty() || info.kind == ValueKind::Record) continue;
    Parameter p;
    p.key = std::string(info.name);
    p.kind = info.kind;
    p.raw = std::string(info.default_text);
    p.where = toolpath::SourcePosition{params_.file_, 0, 0};
    parse_scalar(info, info.default_text, 1, p);
    params_.default_index_.emplace(lower(info.name), params_.defaults_.size());
    params_.defaults_.push_back(std::move(p));
  }
  params_.warnings_.resize(warnings);
}

MachineParameters load_source(std::string_view text, const std::string& file_name, Units units) {
  return Loader(file_name, units).run(text);
}

MachineParameters defaults(Units units) {
  return load_source("@pre_processor\nendp\n", "(engine defaults)", units);
}

MachineParameters load_file(const std::string& path, Units units) {
  // PRP, .MAC and VMID files are a few kilobytes: a huge one is a wrong file, and would only take
  // memory. Read in chunks: a device (/dev/zero) reports no size to check first.
  const std::string text =
      toolpath::read_file_bounded(path, std::size_t{64} << 20, "larger than 64 MiB: not a PRP file?", "cannot open the PRP file");
  return load_source(text, path, units);
}

}  // namespace prp
