// Shared by the built-in function files (functions_*.cpp): argument access, result checks and
// the errors every built-in raises. Internal to gppl.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gppl/builtins/functions.hpp"

namespace gppl::builtin {

using Args = std::span<const Value>;
using Impl = Value (*)(const FunctionSignature& f, Args a);

struct Builtin {
  FunctionSignature signature;
  Impl impl;
};

// A built-in whose arguments may not be omitted.
Builtin fn(std::string_view name, Type result, std::vector<Type> parameters, Impl impl);

// The three groups of the table, in listing order.
std::vector<Builtin> numeric_functions();
std::vector<Builtin> string_functions();
std::vector<Builtin> logical_functions();
std::vector<Builtin> array_functions();

inline constexpr double max_numeric = 1e300;         // spec 3.1
inline constexpr double integral_tolerance = 1e-9;   // spec 4.5: 2.9999999999 is 3

[[noreturn]] void out_of_range(const FunctionSignature& f, std::string_view detail);  // 387
[[noreturn]] void zero_divide(const FunctionSignature& f);                            // 407
[[noreturn]] void overflow(const FunctionSignature& f);                               // 410

// Argument access: 386 when a number is expected and a string given, 394 the other way round.
double number(const Value& v);
std::int64_t whole(const Value& v);
const std::string& text(const Value& v);
inline bool integer_like(const Value& v) { return v.type == Type::Integer || v.type == Type::Logical; }

// Whole numbers within the tolerance snap to the whole number; nullopt when not integral.
std::optional<double> integral(double x);
// Results checked against the value ranges (410); no negative zero.
Value numeric_result(const FunctionSignature& f, double r);
Value integer_result(const FunctionSignature& f, std::int64_t r);
// Removes binary representation noise below the 15th significant digit of `reference`:
// frac(12.345) is 0.345, mod(9.2, 4) is 1.2.
double clean(double r, double reference);

}  // namespace gppl::builtin
