#include "postproc/host_variables.hpp"

#include <set>
#include <string>

#include "postproc/parameter_table.hpp"

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

std::string lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

}  // namespace

std::vector<gppl::HostVariable> host_variables(const Enumerations& enums, const PrpSettings& prp) {
  std::vector<gppl::HostVariable> out;
  std::set<std::string> seen;
  auto add = [&](std::string name, gppl::Type type, bool read_only) {
    if (!seen.insert(lower(name)).second) return;
    out.push_back({std::move(name), type, read_only, {}});
  };
  for (const auto& p : parameter_table()) add(std::string(p.name), gppl_type(p.kind), false);
  for (const auto& c : enums.constants()) add(c.name, gppl::Type::Integer, true);
  // User drill-cycle parameters (`drill_type = Peck Peck Y Delay` declares `Delay`): numeric values
  // entered in the job dialog.
  for (const auto& [cycle, parameters] : prp.drill_cycle_parameters())
    for (const auto& p : parameters) add(p, gppl::Type::Numeric, false);
  return out;
}

}  // namespace postproc
