#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "prp/params/catalogue.hpp"
#include "prp/prp.hpp"

namespace prp {
namespace {

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

std::string join_errors(const std::vector<Diagnostic>& errors) {
  std::string all;
  for (const auto& e : errors) {
    if (!all.empty()) all += '\n';
    all += e.text();
  }
  return all;
}

}  // namespace

std::string_view kind_name(ValueKind kind) {
  switch (kind) {
    case ValueKind::Integer: return "integer";
    case ValueKind::Number: return "number";
    case ValueKind::Point: return "point";
    case ValueKind::Logical: return "logical";
    case ValueKind::Enumeration: return "enumeration";
    case ValueKind::String: return "string";
    case ValueKind::Record: return "record";
  }
  return "?";
}

std::string_view type_name(VarType type) {
  switch (type) {
    case VarType::Integer: return "INTEGER";
    case VarType::Numeric: return "NUMERIC";
    case VarType::Logical: return "LOGICAL";
    case VarType::String: return "STRING";
  }
  return "?";
}

LoadError::LoadError(std::vector<Diagnostic> errors)
    : std::runtime_error(join_errors(errors)), errors_(std::move(errors)) {}

Eigen::Vector3d Parameter::point(Units units) const {
  const auto& half = units == Units::Inch ? inch : metric;
  return {half[0], half[1], half[2]};
}

std::optional<toolpath::Value> Parameter::value(Units units) const {
  switch (kind) {
    case ValueKind::Integer: return toolpath::Value::make_integer(integer);
    case ValueKind::Number: return toolpath::Value::make_numeric(number(units));
    case ValueKind::Logical: return toolpath::Value::make_logical(logical);
    case ValueKind::Enumeration: return toolpath::Value::make_enum(text);
    case ValueKind::String: return toolpath::Value::make_string(text);
    case ValueKind::Point:
    case ValueKind::Record: break;
  }
  return std::nullopt;
}

const Parameter* MachineParameters::find(std::string_view key) const {
  auto it = index_.find(lower(key));
  return it == index_.end() ? nullptr : &parameters_[it->second];
}

const Parameter& MachineParameters::lookup(std::string_view key, ValueKind kind) const {
  const KeyInfo* info = find_key(key);
  if (!info) throw std::out_of_range(fmt::format("`{}` is not a documented PRP key", key));
  if (info->kind != kind && !(kind == ValueKind::String && info->kind == ValueKind::Enumeration))
    throw std::out_of_range(fmt::format("PRP key `{}` is of kind {}, not {}", key, kind_name(info->kind),
                                        kind_name(kind)));
  if (const Parameter* p = find(key)) return *p;
  auto it = default_index_.find(lower(key));
  if (it == default_index_.end())
    throw std::out_of_range(fmt::format("{}: `{}` is not set and has no default", file_, key));
  return defaults_[it->second];
}

bool MachineParameters::logical(std::string_view key) const { return lookup(key, ValueKind::Logical).logical; }
std::int64_t MachineParameters::integer(std::string_view key) const {
  return lookup(key, ValueKind::Integer).integer;
}
double MachineParameters::numeric(std::string_view key) const {
  return lookup(key, ValueKind::Number).number(units_);
}
Eigen::Vector3d MachineParameters::point(std::string_view key) const {
  return lookup(key, ValueKind::Point).point(units_);
}
const std::string& MachineParameters::text(std::string_view key) const {
  return lookup(key, ValueKind::String).text;
}

std::vector<const Record*> MachineParameters::records(std::string_view key) const {
  std::vector<const Record*> out;
  for (const Record& r : records_)
    if (toolpath::iequals(r.key, key)) out.push_back(&r);
  return out;
}

std::optional<std::string> dwell_parameter(const Record& record) {
  std::optional<std::string> found;
  for (const auto& p : record.params)
    if (toolpath::icontains(p, "delay") || toolpath::icontains(p, "dwell")) {
      if (found) return std::nullopt;
      found = p;
    }
  return found;
}

const Record* MachineParameters::drill_cycle(std::string_view name) const {
  for (const Record& r : records_)
    if (r.key == "drill_type" && r.form == Record::Form::Cycle && toolpath::iequals(r.name, name)) return &r;
  return nullptr;
}

const UnknownKey* MachineParameters::unknown(std::string_view key) const {
  for (const UnknownKey& u : unknown_)
    if (toolpath::iequals(u.key, key)) return &u;
  return nullptr;
}

TimeSettings time_settings(const MachineParameters& params) {
  TimeSettings t;
  t.time_factor = params.numeric("time_factor");
  t.block_time = params.numeric("block_time");
  t.change_tool_time = params.numeric("change_tool_time");
  if (params.has("rapid_feed")) t.rapid_feed = params.numeric("rapid_feed");
  t.calc_job_time = params.logical("calc_job_time");
  return t;
}

namespace {
NumberRange range(const MachineParameters& params, std::string_view prefix) {
  NumberRange r;
  auto get = [&](const char* suffix) -> std::optional<std::int64_t> {
    std::string key = fmt::format("{}_{}", prefix, suffix);
    if (!params.has(key)) return std::nullopt;
    return params.integer(key);
  };
  r.min = get("min");
  r.max = get("max");
  r.dflt = get("dflt");
  return r;
}
}  // namespace

NumberRange program_numbers(const MachineParameters& params) { return range(params, "prog_num"); }
NumberRange procedure_numbers(const MachineParameters& params) { return range(params, "proc_num"); }

}  // namespace prp
