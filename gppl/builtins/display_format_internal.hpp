// Display-format internals shared by the printer and its tests; not part of the public interface.
// The exact printer is the fast printer's fallback and the oracle the tests compare it with.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "gppl/builtins/display_format.hpp"

namespace gppl {

// What both printers format. An integer or logical under a format without scaling stays an exact
// integer; anything else becomes a double with the format's scales and sign inversion applied.
inline bool formats_as_integer(const DisplayFormat& f, const Value& v) {
  return v.type != Type::Numeric && f.scale_count == 0;
}
inline std::int64_t integer_of(const Value& v) { return v.type == Type::Logical ? (v.logical ? 1 : 0) : v.integer; }
inline double scaled_number(const DisplayFormat& f, const Value& v) {
  double x = v.type == Type::Numeric ? v.numeric : static_cast<double>(integer_of(v));
  for (int s = 0; s < f.scale_count; ++s) x = f.scales[s].divide ? x / f.scales[s].factor : x * f.scales[s].factor;
  return f.invert ? -x : x;
}

}  // namespace gppl

namespace gppl::exact {

// Longest number part: pad up to M, sign, 101 integer digits of 1e100 (or m zeros), point, N digits.
constexpr std::size_t max_number = 2 * DisplayFormat::max_digits + 110;

// How the 15 significant digits of a value are found: `Library` always asks std::to_chars (the
// reference), `Quick` first tries one multiplication by a power of ten (same digits, faster).
enum class Digits { Library, Quick };

// Writes the number part of `v` (not a string) without affixes at `p` and returns its end, or
// nullptr when option d suppresses the whole item. Throws Error 410 beyond 1e100.
char* format_number(char* p, const DisplayFormat& f, const Value& v, Digits digits);

// The whole item (affixes included) through the exact path with library digits: the reference
// the fast printer must match byte for byte.
void format_reference(std::string& out, const DisplayFormat& f, const Value& v);

}  // namespace gppl::exact

namespace gppl::fast {

constexpr int max_fraction = 15;  // larger N always take the exact path

// `magnitude` (>= 0) rounded the documented way to n decimals (n <= max_fraction), times 10^n,
// when one multiplication decides it; false when the exact printer must decide.
bool round_to_units(double magnitude, int n, std::uint64_t& units);

// write_formatted() for a quick format (DisplayFormat::quick) and an integer or numeric value
// whose integer part is below 10^6; nullptr when it is not such a case (the general path prints it).
char* write_quick(char* out, const DisplayFormat& f, const Value& v);

}  // namespace gppl::fast
