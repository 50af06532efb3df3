// Scalar PRP values (spec 1.3): tokens, and the parser of every value kind, shared by file lines
// and the engine defaults.
#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "prp/params/grammar.hpp"
#include "toolpath/bounded_read.hpp"
#include "prp/params/loader.hpp"

namespace prp {
namespace {

constexpr std::int64_t kIntegerLimit = 999999999;  // spec 1.3
constexpr double kNumberLimit = 1e300;

bool is_blank(char c) { return c == ' ' || c == '\t'; }

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
      if (!v) return error(tokens[0].column, fmt::format("expected Y or N, found `{}`", toolpath::excerpt(tokens[0].text))), false;
      out.logical = *v;
      for (std::size_t i = 1; i < tokens.size(); ++i) out.extra.emplace_back(tokens[i].text);
      return true;
    }

    case ValueKind::Integer: {
      if (tokens.empty()) return error(column, "expected an integer"), false;
      const Token& t = tokens[0];
      if (!grammar::matches<grammar::integer>(t.text))
        return error(t.column, fmt::format("expected an integer, found `{}`", toolpath::excerpt(t.text))), false;
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
        std::string message = fmt::format("expected {}, found `{}`", join_choices(info.choices), toolpath::excerpt(t.text));
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
          return error(t.column, expected + fmt::format(", found `{}`", toolpath::excerpt(t.text))), false;
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

}  // namespace prp
