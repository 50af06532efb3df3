// GPPL internal functions: the lookup table and the calls. The implementations are in
// functions_numeric.cpp and functions_string.cpp.
#include "gppl/builtins/functions.hpp"

#include <algorithm>
#include <initializer_list>
#include <stdexcept>

#include <fmt/format.h>

#include "gppl/builtins/builtin_support.hpp"

namespace gppl {

namespace {

using builtin::Builtin;
using builtin::Impl;

struct Table {
  std::vector<FunctionSignature> signatures;
  std::vector<Impl> impls;
};

const Table& table() {
  static const Table t = [] {
    std::vector<Builtin> all = builtin::numeric_functions();
    for (auto* group : {builtin::string_functions, builtin::logical_functions, builtin::array_functions})
      for (auto& b : group()) all.push_back(std::move(b));
    Table t;
    for (auto& b : all) {
      FunctionSignature& s = b.signature;
      if (s.name == "abs" || s.name == "square" || s.name == "mod") s.integer_if_integer_args = true;
      if (s.name == "replace") s.min_args = 3;
      if (s.name == "instr") s.min_args = 2;
      if (s.name == "adims" || s.name == "alen" || s.name == "asize") s.array_argument = true;
      if (s.name == "tostr") s.min_args = 1, s.format_argument = true;
      if (s.name == "date" || s.name == "time") s.no_parentheses = true;
      t.signatures.push_back(std::move(s));
      t.impls.push_back(b.impl);
    }
    return t;
  }();
  return t;
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char c = a[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != b[i]) return false;
  }
  return true;
}

}  // namespace

const FunctionSignature* find_function(std::string_view name) {
  for (const auto& s : table().signatures)
    if (equal_ignoring_case(name, s.name)) return &s;
  return nullptr;
}

std::span<const FunctionSignature> all_functions() { return table().signatures; }

Type result_type(const FunctionSignature& f, std::span<const Type> argument_types) {
  if (!f.integer_if_integer_args) return f.result;
  bool all_integer = std::all_of(argument_types.begin(), argument_types.end(),
                                 [](Type t) { return t == Type::Integer || t == Type::Logical; });
  return all_integer ? Type::Integer : f.result;
}

Value call_function(const FunctionSignature& f, std::span<const Value> args) {
  const Table& t = table();
  const FunctionSignature* own = &f;
  if (own < t.signatures.data() || own >= t.signatures.data() + t.signatures.size()) own = find_function(f.name);
  if (own == nullptr) throw std::invalid_argument(fmt::format("gppl: '{}' is not a built-in function", f.name));
  if (args.size() < own->min_args || args.size() > own->parameters.size())
    throw std::invalid_argument(fmt::format("gppl: {} takes {} to {} arguments, got {}", own->name, own->min_args,
                                            own->parameters.size(), args.size()));
  return t.impls[static_cast<std::size_t>(own - t.signatures.data())](*own, args);
}

}  // namespace gppl
