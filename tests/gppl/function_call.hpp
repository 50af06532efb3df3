// Calls of the internal functions by name, shared by the function tests.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gppl/builtins/functions.hpp"

namespace function_test {

using gppl::Type;
using gppl::Value;

inline Value num(double v) { return Value::of_numeric(v); }
inline Value integer(std::int64_t v) { return Value::of_integer(v); }
inline Value str(std::string v) { return Value::of_string(std::move(v)); }

inline Value call(std::string_view name, std::vector<Value> args) {
  const gppl::FunctionSignature* f = gppl::find_function(name);
  if (f == nullptr) throw std::invalid_argument(std::string(name));
  return gppl::call_function(*f, args);
}

}  // namespace function_test
