// Internal: which attributes of a SolidCAM machine ID file (VMID) stand for which PRP keys.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "prp/prp.hpp"

namespace prp {

// How an attribute's text becomes the PRP value.
enum class VmidValue : std::uint8_t {
  Flag,      // 0 / 1 -> N / Y
  Integer,   // an integer
  Number,    // a number, the same for metric and inch jobs (angles, counts, factors)
  Length,    // millimetres: the inch half is the value / 25.4
  Text,      // the attribute's text
  GenProcs,  // ProceduresDef GenProc: 0 -> N, 1 -> Y
  MachineType,  // Machine OperationType: 6 -> WIRE_CUT (a wire machine); milling (0) sets nothing
};

struct VmidAttribute {
  std::string_view element;    // element name, anywhere outside <Components>
  std::string_view attribute;  // attribute name
  std::string_view key;        // PRP key, spelled as the catalogue spells it
  VmidValue value;
};

// The kind of PRP value each conversion gives.
ValueKind vmid_kind(VmidValue value);

// Every mapped attribute, grouped by element.
std::span<const VmidAttribute> vmid_attributes();

// ValueType of a user parameter (`<Param ValueType=...>`) as a GPPL type; nullopt when unknown.
std::optional<VarType> vmid_value_type(std::string_view value_type);

// DrillType of a `<DrillCycle>` (0..6) as a drill base type; nullopt when unknown.
std::optional<std::string_view> vmid_drill_base(std::string_view drill_type);

}  // namespace prp
