// The system variables: every name SolidCAM predefines for a post, with its type, whether a post
// may assign it, its default and where its value comes from (docs/system-variables.md). The table
// itself is data, gppl/compile/system_variables.inc; the compiler declares every row before a post's own
// declarations (docs/gppl-language.md, "Names").
#pragma once

#include <span>
#include <string_view>

#include "gppl/gppl.hpp"

namespace gppl {

// Where a system variable's value comes from.
enum class VariableSource : std::uint8_t {
  Trace,     // a command of the job (a parameter of @start_of_job, @line, ...)
  Machine,   // the machine (PRP/VMID); SolidCAM writes it into the job's trace
  Post,      // the post sets it (formats and numbering, normally in @init_post)
  Run,       // the engine fills it (part_name from the job file, gcode, prev_command, ...)
  Constant,  // a constant (PI, TRUE, a job-type value)
};

// What a system variable's type rests on (the doc says which types are inferred).
enum class TypeBasis : std::uint8_t { Manual, Catalogue, Usage, Observed, Naming, Guess };

struct SystemVariable {
  std::string_view name;  // as SolidCAM's list spells it (names ignore case)
  Type type;
  bool read_only;
  VariableSource source;
  int rows;                      // array sizes: 0 = not an array
  int columns;                   // second dimension, 0 = none
  std::string_view default_text;  // '' / 0 / FALSE when empty; numbers as text
  TypeBasis basis;
  std::string_view meaning;
};

std::span<const SystemVariable> system_variables();
// The job_type values SolidCAM's list names ('3-d drill', 'pocket', ...): text, not variables.
std::span<const std::string_view> job_type_values();
// Case-insensitive; nullptr when the name is no system variable.
const SystemVariable* find_system_variable(std::string_view name);
// The default as a value of the variable's type.
Value default_value(const SystemVariable& v);

std::string_view name_of(VariableSource source);  // "trace", "machine", ...
std::string_view name_of(TypeBasis basis);        // "manual", "catalogue", ...
std::string_view name_of(Type type);              // "integer", "numeric", "logical", "string"

}  // namespace gppl
