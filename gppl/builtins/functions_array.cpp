// adims, alen, asize: the shape of an array variable. The compiler hands over the dimension sizes
// as a string ("3,4"; "" for a scalar), since a variable's shape is fixed when the post compiles.
#include "gppl/builtins/builtin_support.hpp"

#include <charconv>

#include <fmt/format.h>

namespace gppl::builtin {

namespace {

std::vector<std::int64_t> sizes(const Value& shape) {
  std::vector<std::int64_t> out;
  const std::string& s = text(shape);
  const char* p = s.data();
  const char* end = p + s.size();
  while (p < end) {
    std::int64_t n = 0;
    p = std::from_chars(p, end, n).ptr;
    out.push_back(n);
    if (p < end) ++p;  // the comma
  }
  return out;
}

Value f_adims(const FunctionSignature&, Args a) { return Value::of_integer(static_cast<std::int64_t>(sizes(a[0]).size())); }

Value f_asize(const FunctionSignature& f, Args a) {
  std::int64_t total = 1;
  for (std::int64_t n : sizes(a[0])) total *= n;
  return integer_result(f, total);
}

Value f_alen(const FunctionSignature& f, Args a) {
  const std::vector<std::int64_t> all = sizes(a[0]);
  const std::int64_t dimension = whole(a[1]);
  if (all.empty()) out_of_range(f, "the variable is not an array");
  if (dimension < 1 || dimension > static_cast<std::int64_t>(all.size()))
    out_of_range(f, fmt::format("dimension {} is outside [1, {}]", dimension, all.size()));
  return Value::of_integer(all[static_cast<std::size_t>(dimension - 1)]);
}

}  // namespace

std::vector<Builtin> array_functions() {
  constexpr Type I = Type::Integer, S = Type::String;
  return {fn("adims", I, {S}, f_adims), fn("alen", I, {S, I}, f_alen), fn("asize", I, {S}, f_asize)};
}

}  // namespace gppl::builtin
