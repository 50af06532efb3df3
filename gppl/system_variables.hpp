// The system variables GPPTool predefines (spec section 12, solidcam-behaviour 2a), with the
// defaults a post sees when @init_post leaves them unset.
#pragma once

#include <span>
#include <string_view>

#include "gppl/gppl.hpp"

namespace gppl {

struct SystemVariable {
  std::string_view name;
  Type type;
  bool read_only;
  std::string_view text;  // default of string variables
  double number;          // default of the others
};

std::span<const SystemVariable> system_variables();

}  // namespace gppl
