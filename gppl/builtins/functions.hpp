// GPPL internal (built-in) functions: numeric (angles in degrees), string and logical.
//
// The interpreter resolves a call once with find_function() and converts the arguments to the
// parameter types before call_function(). `change(v)` and `active(v)` are not here: they read
// variable attributes, so the interpreter implements them itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "gppl/gppl.hpp"

namespace gppl {

struct FunctionSignature {
  std::string_view name;  // lower case
  Type result;            // for `integer_if_integer_args` functions: the result for Numeric arguments
  std::vector<Type> parameters;

  // Arguments from min_args to parameters.size() may be omitted (replace's k, tostr's format).
  std::size_t min_args = 0;
  // abs, square, mod: when every argument is Integer or Logical, pass them
  // as Integer and the result is Integer; otherwise pass Numeric and the result is `result`.
  bool integer_if_integer_args = false;
  // tostr: its optional last parameter (the display format) is written `tostr(x : fmt)`, not with
  // a comma. The interpreter passes the format string, or the value of `numeric_def_f` when the
  // call has none (call_function falls back to '5.3' when that is missing or empty).
  bool format_argument = false;
  // date, time: written without parentheses (a lenient parser also accepts `date()`).
  bool no_parentheses = false;
  // adims, alen, asize: the first argument names an array variable (without indices). The
  // compiler passes its dimension sizes as a string ("3,4"; "" for a scalar), since they are
  // known when the post is compiled.
  bool array_argument = false;
};

// Integers hold ±999 999 999 (spec 3.1); integer results beyond it raise error 410.
inline constexpr std::int64_t max_integer = 999'999'999;

// Case-insensitive; nullptr if `name` is not a built-in function.
const FunctionSignature* find_function(std::string_view name);

// The result type for these argument types (differs from `result` only for
// integer_if_integer_args functions).
Type result_type(const FunctionSignature& f, std::span<const Type> argument_types);

// All built-ins, for listings and tests.
std::span<const FunctionSignature> all_functions();

// `args` are already converted to the parameter types (Integer is also accepted where Numeric
// is expected). Throws Error with an empty position: 387 argument out of range, 407 zero divide,
// 410 result out of range, and the format errors 408-423 of tostr.
Value call_function(const FunctionSignature& f, std::span<const Value> args);

}  // namespace gppl
