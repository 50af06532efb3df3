// Operators and conversions on run-time values, shared by the interpreter and the compiler's
// constant folding. Errors throw OpError; the caller adds the position.
#pragma once

#include <stdexcept>
#include <string>

#include "machines/pikocnc/script/compiled.hpp"

namespace pikocnc::script {

struct OpError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

Value apply_binary(Bin op, const Value& a, const Value& b);
Value apply_unary(Un op, const Value& a);
// Converts to a basic kind (the Variant rules of 2.3); throws OpError when it cannot.
Value convert_to(const Value& v, const Type& to);
// Pascal's Round: half to even, as Delphi does (spec 8); throws OpError outside Integer.
std::int64_t round_even(double v);
std::int64_t checked_int(double v);  // Trunc
bool truthy(const Value& v);         // a Boolean condition (Variant booleans too)
// FloatToStr (spec 7): 15 significant digits, '.', no point for integral values.
std::string float_to_str(double v);
std::string value_text(const Value& v);  // any basic value as text (diagnostics, JSON)

}  // namespace pikocnc::script
