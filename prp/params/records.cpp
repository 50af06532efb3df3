// Repeatable records (spec 1.5) and the PRP external variables they declare (spec 3.16).
#include <algorithm>

#include <fmt/format.h>

#include "prp/params/grammar.hpp"
#include "toolpath/bounded_read.hpp"
#include "prp/params/loader.hpp"

namespace prp {
namespace {

constexpr std::size_t kMaxNameLength = 60;  // GPPL identifier limit

std::optional<VarType> type_keyword(std::string_view t) {
  if (t.size() > 2 && t.front() == '(' && t.back() == ')') t = t.substr(1, t.size() - 2);
  if (toolpath::iequals(t, "INTEGER")) return VarType::Integer;
  if (toolpath::iequals(t, "NUMERIC")) return VarType::Numeric;
  if (toolpath::iequals(t, "LOGICAL")) return VarType::Logical;
  if (toolpath::iequals(t, "STRING")) return VarType::String;
  return std::nullopt;
}

std::optional<bool> flag_word(std::string_view t) {
  if (toolpath::iequals(t, "Y")) return true;
  if (toolpath::iequals(t, "N")) return false;
  return std::nullopt;
}

bool declares_types(std::string_view key) {
  return key == "options" || key == "job_opt_type" || key == "turn_type" || key == "thread_type" ||
         key == "groove_type";
}

toolpath::Value initial_value(VarType type) {
  switch (type) {
    case VarType::Integer: return toolpath::Value::make_integer(0);
    case VarType::Numeric: return toolpath::Value::make_numeric(0.0);
    case VarType::Logical: return toolpath::Value::make_logical(false);
    case VarType::String: return toolpath::Value::make_string("");
  }
  return {};
}

}  // namespace

void Loader::record(std::string_view base, std::string_view lang, std::string_view key, std::string_view value,
                    std::size_t column) {
  const std::vector<Token> t = tokenize(value, column);
  const std::size_t end_column = column + value.size();
  Record r;
  r.key = std::string(base);
  r.lang = std::string(lang);
  r.raw = std::string(value);
  r.where = at(column);
  std::size_t name_token = 0;
  std::size_t first_param = 0;

  if (t.size() == 2 && type_keyword(t[1].text)) {
    if (!declares_types(base))
      return error(t[1].column, fmt::format("`{}` records declare cycles, not typed variables", key));
    r.form = Record::Form::Declaration;
    r.type = *type_keyword(t[1].text);
    first_param = t.size();
  } else if (base == "options") {
    return error(t.size() < 2 ? end_column : t[1].column,
                 "expected `name TYPE` (TYPE: INTEGER, LOGICAL, NUMERIC or STRING)");
  } else if (t.size() >= 2 && flag_word(t[1].text) && base != "wc_macro") {
    r.flag = flag_word(t[1].text);
    first_param = 2;
    if (base == "drill_type") {  // legacy form: the name is the base type
      auto b = drill_base(t[0].text);
      if (!b)
        return error(t[0].column, fmt::format("expected a drill base type (DRILLING, F_DRILL, PECK, TAPPING, "
                                              "BORING, R_BORING, F_BORING or None), found `{}`", toolpath::excerpt(t[0].text)));
      r.base = std::string(*b);
    }
  } else if (t.size() >= 3 && flag_word(t[2].text) && (base == "drill_type" || base == "wc_macro")) {
    r.flag = flag_word(t[2].text);
    first_param = 3;
    if (base == "drill_type") {
      auto b = drill_base(t[1].text);
      if (!b)
        return error(t[1].column, fmt::format("expected a drill base type (DRILLING, F_DRILL, PECK, TAPPING, "
                                              "BORING, R_BORING, F_BORING or None), found `{}`", toolpath::excerpt(t[1].text)));
      r.base = std::string(*b);
    } else {
      r.base = std::string(t[1].text);
    }
  } else if (base == "wc_pos_type" && !t.empty()) {
    first_param = 1;
  } else {
    const bool three = base == "drill_type" || base == "wc_macro";
    std::string shape = base == "drill_type" ? "`name base Y|N {param}`"
                        : base == "wc_macro" ? "`name word Y|N {param}`"
                                             : "`name Y|N {param}` or `name TYPE`";
    std::size_t at_token = three ? 2 : 1;
    if (t.size() <= at_token) return error(end_column, "expected " + shape);
    return error(t[at_token].column, fmt::format("expected Y or N, found `{}` (a record is {})",
                                                 t[at_token].text, shape));
  }

  // Names become GPPL identifiers.
  std::vector<std::size_t> names{name_token};
  for (std::size_t i = first_param; i < t.size(); ++i) names.push_back(i);
  for (std::size_t i : names) {
    if (t[i].text.size() > kMaxNameLength || !grammar::matches<grammar::identifier>(t[i].text))
      return error(t[i].column, fmt::format("`{}` is not a valid name (a letter, then letters, digits or '_', "
                                            "at most 60 characters)", t[i].text));
  }
  r.name = std::string(t[name_token].text);
  r.name_where = at(t[name_token].column);
  for (std::size_t i = first_param; i < t.size(); ++i) r.params.emplace_back(t[i].text);

  if (!add_record(r)) return;  // a name used twice
  // PRP external variables: a typed declaration has its type's initial value; cycle parameters
  // are numeric and inactive until a command sets them.
  if (r.form == Record::Form::Declaration) {
    declare(t[0].text, r.type, initial_value(r.type), r.key, at(t[0].column));
  } else {
    for (std::size_t i = first_param; i < t.size(); ++i)
      if (!declare(t[i].text, VarType::Numeric, std::nullopt, r.key, at(t[i].column))) break;
  }
}

bool Loader::add_record(Record r) {
  for (const Record& other : params_.records_) {
    if (other.key == r.key && other.lang == r.lang && other.form == r.form && toolpath::iequals(other.name, r.name)) {
      error_at(r.name_where, fmt::format("`{}{}{}` declares `{}` twice (first at line {})", r.key,
                                         r.lang.empty() ? "" : "_", r.lang, r.name, other.where.line));
      return false;
    }
  }
  params_.records_.push_back(std::move(r));
  return true;
}

bool Loader::declare(std::string_view name, VarType type, std::optional<toolpath::Value> initial, std::string_view by,
                     toolpath::SourcePosition where) {
  auto& all = params_.externals_;
  auto it = std::find_if(all.begin(), all.end(),
                         [&](const ExternalVariable& v) { return toolpath::iequals(v.name, name); });
  if (it == all.end()) {
    all.push_back({std::string(name), type, std::move(initial), std::string(by), std::move(where)});
    return true;
  }
  if (it->type != type) {
    error_at(std::move(where), fmt::format("`{}` is declared {} here but {} at line {}", name, type_name(type),
                                           type_name(it->type), it->where.line));
    return false;
  }
  return true;
}

}  // namespace prp
