// The parameters of every toolpath command (gpptool-commands.md, sections 3 and 5-14): which commands
// carry them, and their kinds. Every one is a system variable (gppl/compile/system_variables.inc decides its
// type; tests/postproc/tables_test.cpp holds the kinds here to it). A parameter that is not in the
// table still reaches the post when the post uses its name (docs/gppl-language.md, "Names").
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace postproc {

// `Enum` parameters hold enumeration constants (`CW`, `COMP_LEFT`, ...), which GPPL sees as integers.
enum class ParameterKind : std::uint8_t { Integer, Numeric, Logical, String, Enum };

struct ParameterSpec {
  std::string_view name;
  ParameterKind kind;
  std::string_view commands;  // the commands that carry it, blank-separated (documentation, `check`)
};

// Every documented parameter, sorted by name (case-insensitively).
std::span<const ParameterSpec> parameter_table();

// Case-insensitive lookup; nullptr when the name is not documented.
const ParameterSpec* find_parameter(std::string_view name);

namespace detail {
std::span<const ParameterSpec> coordinate_set_parameters();  // part of the table (parameter_table_sets.cpp)
}

}  // namespace postproc
