// The text of a numeric trace value: the shortest digits that read back to the same double, as
// fmt's "{}" writes them (fixed notation for decimal exponents -4 to 15, exponent notation
// otherwise), with ".0" added when that text has neither a point nor an exponent, so that it reads
// back as numeric, not integer.
#pragma once

#include <cstddef>
#include <string>

namespace toolpath {

// Enough for any double's text: `-2.2250738585072014e-308` and the ".0".
inline constexpr std::size_t kMaxNumberText = 32;

// Writes the text at `out` and returns its end; it may write bytes after the end, never more than
// kMaxNumberText in all. Values with at most nine decimals and fifteen significant digits between
// 1e-4 and 1e6 (every value the controller models write: they round to a nanometre) are written
// from an integer without the shortest-digits search; every other value goes through
// number_text_exact. Both give the same bytes (tests/toolpath/number_text_test.cpp).
char* write_number_text(char* out, double v);

// The reference: fmt's shortest "{}" and the ".0" rule (write_number_text's path for the rest).
std::string number_text_exact(double v);

}  // namespace toolpath
