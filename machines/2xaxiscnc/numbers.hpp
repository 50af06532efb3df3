// Numbers of 2XAxisCNC programs: `-0,2455`, `5,5`, `105`. The application reads them as IEEE
// single-precision floats with a comma as the decimal separator (docs/2xaxiscnc.md, "Numbers").
#pragma once

#include <string_view>

namespace twoaxis {

struct Number {
  enum class Status { Ok, NonPortable, Malformed, OutOfRange };
  Status status = Status::Malformed;
  double value = 0.0;  // the decimal value (double precision)
};

// Accepts [+|-] digits [, digits]; a `.` separator or an exponent is read but NonPortable (the
// application parses with the Russian locale and would reject them). Anything else is Malformed; a
// magnitude beyond the single-precision range is OutOfRange.
Number parse_number(std::string_view text);

// The value as the application stores it: rounded to the nearest single-precision float.
inline double as_single(double v) { return static_cast<double>(static_cast<float>(v)); }

// A value as the reader reports it: rounded to 1e-6 (a micrometre of a millimetre), which hides the
// binary tail of a small float (0,7 is 0.699999988 as a float) but not the loss of a large one
// (1234,5678 is 1234.567749 as a float), and never -0.
double tidy(double v);

}  // namespace twoaxis
