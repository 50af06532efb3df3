// Canonical PRP text: what `load_source` reads back to the same values.
#include <fmt/format.h>

#include "prp/prp.hpp"

namespace prp {

std::string format_value(const Parameter& p) {
  switch (p.kind) {
    case ValueKind::Integer: return fmt::format("{}", p.integer);
    case ValueKind::Number:
      return p.has_inch_half ? fmt::format("{}, {}", p.metric[0], p.inch[0]) : fmt::format("{}", p.metric[0]);
    case ValueKind::Point:
      return p.has_inch_half ? fmt::format("{} {} {}, {} {} {}", p.metric[0], p.metric[1], p.metric[2], p.inch[0],
                                           p.inch[1], p.inch[2])
                             : fmt::format("{} {} {}", p.metric[0], p.metric[1], p.metric[2]);
    case ValueKind::Logical: {
      std::string s = p.logical ? "Y" : "N";
      for (const auto& e : p.extra) s += " " + e;
      return s;
    }
    case ValueKind::Enumeration:
    case ValueKind::String: return p.text;
    case ValueKind::Record: break;
  }
  return p.raw;
}

std::string format_record(const Record& r) {
  std::string s = r.name;
  if (r.form == Record::Form::Declaration) return s + " " + std::string(type_name(r.type));
  if (!r.base.empty()) s += " " + r.base;
  if (r.flag) s += *r.flag ? " Y" : " N";
  for (const auto& p : r.params) s += " " + p;
  return s;
}

std::string write_source(const MachineParameters& params) {
  std::string out = "@pre_processor\n";
  for (const Parameter& p : params.parameters()) out += fmt::format("{} = {}\n", p.key, format_value(p));
  for (const Record& r : params.all_records())
    out += fmt::format("{}{}{} = {}\n", r.key, r.lang.empty() ? "" : "_", r.lang, format_record(r));
  for (const UnknownKey& u : params.unknown_keys()) out += fmt::format("{} = {}\n", u.key, u.raw);
  out += "endp\n";
  return out;
}

}  // namespace prp
