#include "postproc/engine/host_variables.hpp"

#include <set>
#include <string>

#include "postproc/engine/parameter_table.hpp"

namespace postproc {
namespace {

gppl::Type gppl_type(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::Integer: return gppl::Type::Integer;
    case ParameterKind::Numeric: return gppl::Type::Numeric;
    case ParameterKind::Logical: return gppl::Type::Logical;
    case ParameterKind::String: return gppl::Type::String;
    case ParameterKind::Enum: return gppl::Type::Integer;  // enumeration constants are integers
  }
  return gppl::Type::Numeric;
}

gppl::Type gppl_type(prp::VarType type) {
  switch (type) {
    case prp::VarType::Integer: return gppl::Type::Integer;
    case prp::VarType::Numeric: return gppl::Type::Numeric;
    case prp::VarType::Logical: return gppl::Type::Logical;
    case prp::VarType::String: return gppl::Type::String;
  }
  return gppl::Type::Numeric;
}

std::string lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

gppl::Type gppl_type(toolpath::ValueKind kind) {
  switch (kind) {
    case toolpath::ValueKind::Integer: return gppl::Type::Integer;
    case toolpath::ValueKind::Numeric: return gppl::Type::Numeric;
    case toolpath::ValueKind::Logical: return gppl::Type::Logical;
    case toolpath::ValueKind::String: return gppl::Type::String;
    case toolpath::ValueKind::Enum: return gppl::Type::Integer;
  }
  return gppl::Type::Numeric;
}

}  // namespace

std::vector<gppl::HostVariable> job_variables(toolpath::CommandSource& job) {
  std::vector<gppl::HostVariable> out;
  std::set<std::string> seen;
  toolpath::Command command;
  while (job.next(command))
    for (const auto& p : command.parameters)
      if (p.name.find('<') == std::string::npos && seen.insert(lower(p.name)).second)  // not array elements
        out.push_back({p.name, gppl_type(p.value.kind), false, {}});
  return out;
}

std::vector<gppl::HostVariable> host_variables(const Enumerations& enums, const prp::MachineParameters& machine) {
  std::vector<gppl::HostVariable> out;
  std::set<std::string> seen;
  auto add = [&](std::string name, gppl::Type type, bool read_only) {
    if (!seen.insert(lower(name)).second) return;
    out.push_back({std::move(name), type, read_only, {}});
  };
  for (const auto& p : parameter_table()) add(std::string(p.name), gppl_type(p.kind), false);
  for (const auto& c : enums.constants()) add(c.name, gppl::Type::Integer, true);
  for (const auto& v : machine.external_variables()) add(v.name, gppl_type(v.type), false);
  return out;
}

}  // namespace postproc
