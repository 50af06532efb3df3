#include "prp/loader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "prp/grammar.hpp"

namespace prp {
namespace {

constexpr std::int64_t kIntegerLimit = 999999999;  // spec 1.3
constexpr double kNumberLimit = 1e300;

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

std::string join_choices(std::span<const std::string_view> choices) {
  std::string r;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (i) r += i + 1 == choices.size() ? " or " : ", ";
    r += choices[i];
  }
  return r;
}

std::optional<bool> parse_logical(std::string_view t) {
  if (toolpath::iequals(t, "Y") || t == "1" || toolpath::iequals(t, "TRUE")) return true;
  if (toolpath::iequals(t, "N") || t == "0" || toolpath::iequals(t, "FALSE")) return false;
  return std::nullopt;
}

}  // namespace

std::vector<Token> tokenize(std::string_view value, std::size_t column, bool split_commas) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < value.size()) {
    if (is_blank(value[i])) {
      ++i;
      continue;
    }
    if (split_commas && value[i] == ',') {
      tokens.push_back({value.substr(i, 1), column + i});
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < value.size() && !is_blank(value[j]) && !(split_commas && value[j] == ',')) ++j;
    tokens.push_back({value.substr(i, j - i), column + i});
    i = j;
  }
  return tokens;
}

Loader::Loader(std::string file_name, Units units) {
  params_.file_ = std::move(file_name);
  params_.units_ = units;
}

toolpath::SourcePosition Loader::at(std::size_t column, std::size_t line) const {
  return {params_.file_, line ? line : line_, column};
}

void Loader::error(std::size_t column, std::string message, std::size_t line) {
  errors_.push_back({at(column, line), std::move(message)});
}

void Loader::warning(std::size_t column, std::string message, std::size_t line) {
  params_.warnings_.push_back({at(column, line), std::move(message)});
}

MachineParameters Loader::run(std::string_view text) {
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
  if (auto base = record_base(key, lang)) {
    record(*base, lang, key, value, column);
    return;
  }
  const std::string lkey = lower(key);
  const KeyInfo* info = find_key(key);
  if (!info) {
    warning(key_column, fmt::format("unknown key `{}`: kept as text for the post", key));
    UnknownKey u{std::string(key), std::string(original.substr(value_begin, value_end - value_begin)),
                 at(column)};
    auto it = std::find_if(params_.unknown_.begin(), params_.unknown_.end(),
                           [&](const UnknownKey& k) { return toolpath::iequals(k.key, key); });
    if (it != params_.unknown_.end()) *it = std::move(u);
    else params_.unknown_.push_back(std::move(u));
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

bool Loader::parse_scalar(const KeyInfo& info, std::string_view value, std::size_t column, Parameter& out) {
  const bool numeric = info.kind == ValueKind::Number || info.kind == ValueKind::Point;
  const std::vector<Token> tokens = tokenize(value, column, numeric);
  const std::size_t end_column = column + value.size();

  switch (info.kind) {
    case ValueKind::String:
      out.text = std::string(value);
      return true;

    case ValueKind::Logical: {
      if (tokens.empty()) return error(column, "expected Y or N"), false;
      auto v = parse_logical(tokens[0].text);
      if (!v) return error(tokens[0].column, fmt::format("expected Y or N, found `{}`", tokens[0].text)), false;
      out.logical = *v;
      for (std::size_t i = 1; i < tokens.size(); ++i) out.extra.emplace_back(tokens[i].text);
      return true;
    }

    case ValueKind::Integer: {
      if (tokens.empty()) return error(column, "expected an integer"), false;
      const Token& t = tokens[0];
      if (!grammar::matches<grammar::integer>(t.text))
        return error(t.column, fmt::format("expected an integer, found `{}`", t.text)), false;
      std::string_view digits = t.text[0] == '+' ? t.text.substr(1) : t.text;
      std::int64_t v = 0;
      auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
      if (ec != std::errc{} || ptr != digits.data() + digits.size() || v > kIntegerLimit || v < -kIntegerLimit)
        return error(t.column, "integer out of range (-999999999 .. 999999999)"), false;
      out.integer = v;
      if (tokens.size() > 1) warning(tokens[1].column, "extra text after the value is ignored");
      return true;
    }

    case ValueKind::Enumeration: {
      if (tokens.empty()) return error(column, "expected " + join_choices(info.choices)), false;
      const Token& t = tokens[0];
      out.text = std::string(t.text);
      bool known = std::any_of(info.choices.begin(), info.choices.end(),
                               [&](std::string_view c) { return toolpath::iequals(c, t.text); });
      if (!known) {
        std::string message = fmt::format("expected {}, found `{}`", join_choices(info.choices), t.text);
        if (!info.unknown_choice_is_warning) return error(t.column, message), false;
        warning(t.column, message + " (kept)");
      }
      if (tokens.size() > 1) warning(tokens[1].column, "extra text after the value is ignored");
      return true;
    }

    case ValueKind::Number:
    case ValueKind::Point: {
      const std::size_t per_half = info.kind == ValueKind::Number ? 1 : 3;
      const std::string expected = per_half == 1 ? "expected a number, or number ',' number"
                                                 : "expected 3 numbers, optionally ',' and 3 more";
      std::array<double, 6> v{};
      std::size_t count = 0;  // numbers read
      bool comma = false;
      for (const Token& t : tokens) {
        if (t.text == ",") {
          if (comma || count != per_half) return error(t.column, expected), false;
          comma = true;
          continue;
        }
        if (count == (comma ? 2 * per_half : per_half) || !grammar::matches<grammar::number>(t.text))
          return error(t.column, expected + fmt::format(", found `{}`", t.text)), false;
        double d = 0;
        auto [ptr, ec] = std::from_chars(t.text.data() + (t.text[0] == '+'), t.text.data() + t.text.size(), d);
        if (ec != std::errc{} || std::abs(d) > kNumberLimit)
          return error(t.column, "number out of range (-1E300 .. 1E300)"), false;
        (void)ptr;
        v[count++] = d;
      }
      if (count != (comma ? 2 * per_half : per_half)) return error(end_column, expected), false;
      for (std::size_t i = 0; i < per_half; ++i) {
        out.metric[i] = v[i];
        out.inch[i] = comma ? v[per_half + i] : v[i];
      }
      out.has_inch_half = comma;
      if (comma) {
        for (std::size_t i = 0; i < per_half; ++i) {
          double expect = out.metric[i] / 25.4;
          if (std::abs(out.inch[i] - expect) > 0.0001 + 0.01 * std::abs(expect)) {
            warning(column, fmt::format("the inch value {} is not the metric value {} / 25.4 (a decimal "
                                        "comma written by mistake?)", out.inch[i], out.metric[i]));
            break;
          }
        }
      }
      return true;
    }

    case ValueKind::Record:
      break;
  }
  return false;
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
  if (const Parameter* p = get("arc_max_angle"); p) {
    for (double a : {p->metric[0], p->inch[0]})
      if (!(a > 0 && a <= 180)) {
        error(p->where.column, "arc_max_angle must be in (0, 180] degrees", p->where.line);
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
  std::ifstream in(path, std::ios::binary);
  if (!in) throw toolpath::InputError({path, 0, 0}, "cannot open the PRP file");
  // PRP files are a few kilobytes: a huge one is a wrong file, and would only take memory.
  in.seekg(0, std::ios::end);
  if (const auto size = in.tellg(); size > std::streamoff{64} << 20)
    throw toolpath::InputError({path, 0, 0}, "larger than 64 MiB: not a PRP file?");
  in.seekg(0);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return load_source(buffer.str(), path, units);
}

}  // namespace prp
