// The table lives in system_variables.inc (one SYSVAR row per name). Defaults of the variables a
// post sets follow the manual's example values (spec 12.2): skipline TRUE, gcode_space FALSE, and
// '' (format not set: fall through to the defaults) for coordinate-set formats.
#include "gppl/compile/system_variables.hpp"

#include <algorithm>
#include <charconv>
#include <string>
#include <unordered_map>

namespace gppl {

namespace {

constexpr bool Assign = false;
constexpr bool ReadOnly = true;
using enum Type;
using enum VariableSource;
using enum TypeBasis;

constexpr SystemVariable kSystem[] = {
#define SYSVAR(name, type, access, source, rows, columns, dflt, basis, meaning) \
  {name, type, access, source, rows, columns, dflt, basis, meaning},
#define JOBTYPE(value)
#include "gppl/compile/system_variables.inc"
#undef JOBTYPE
#undef SYSVAR
};

constexpr std::string_view kJobTypes[] = {
#define SYSVAR(name, type, access, source, rows, columns, dflt, basis, meaning)
#define JOBTYPE(value) value,
#include "gppl/compile/system_variables.inc"
#undef JOBTYPE
#undef SYSVAR
};

std::string folded(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return out;
}

}  // namespace

std::span<const SystemVariable> system_variables() { return kSystem; }
std::span<const std::string_view> job_type_values() { return kJobTypes; }

const SystemVariable* find_system_variable(std::string_view name) {
  static const auto index = [] {
    std::unordered_map<std::string, const SystemVariable*> m;
    for (const SystemVariable& v : kSystem) m.emplace(folded(v.name), &v);
    return m;
  }();
  const auto it = index.find(folded(name));
  return it == index.end() ? nullptr : it->second;
}

Value default_value(const SystemVariable& v) {
  if (v.type == Type::String) return Value::of_string(std::string(v.default_text));
  double number = 0;
  if (!v.default_text.empty()) number = std::stod(std::string(v.default_text));
  switch (v.type) {
    case Type::Integer: return Value::of_integer(std::int64_t(number));
    case Type::Logical: return Value::of_logical(number != 0);
    default: return Value::of_numeric(number);
  }
}

std::string_view name_of(VariableSource source) {
  switch (source) {
    case VariableSource::Trace: return "trace";
    case VariableSource::Machine: return "machine";
    case VariableSource::Post: return "post";
    case VariableSource::Run: return "run";
    case VariableSource::Constant: return "constant";
  }
  return "";
}

std::string_view name_of(TypeBasis basis) {
  switch (basis) {
    case TypeBasis::Manual: return "manual";
    case TypeBasis::Catalogue: return "catalogue";
    case TypeBasis::Usage: return "usage";
    case TypeBasis::Observed: return "observed";
    case TypeBasis::Naming: return "naming";
    case TypeBasis::Guess: return "guess";
  }
  return "";
}

std::string_view name_of(Type type) {
  switch (type) {
    case Type::Integer: return "integer";
    case Type::Numeric: return "numeric";
    case Type::Logical: return "logical";
    case Type::String: return "string";
  }
  return "";
}

}  // namespace gppl
