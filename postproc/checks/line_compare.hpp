// How `postproc test` decides that an output line matches its expected line, with the options a
// regression tester needs to ignore what legitimately differs between runs or machines.
#pragma once

#include <string>
#include <string_view>

namespace postproc {

struct CompareOptions {
  bool ignore_block_numbers = false;     // a leading `N123` (and one blank after it)
  bool ignore_trailing_blanks = false;
  bool ignore_leading_blanks = false;
  bool ignore_datetime = false;          // dates and times inside comments `( ... )` or after `;`
  double numeric_tolerance = 0.0;        // > 0: numbers match when they differ by at most this much
};

// The line as the comparison sees it: the options applied (numbers untouched).
std::string normalize_line(std::string_view line, const CompareOptions& options);

// True when the two lines are the same under the options.
bool lines_match(std::string_view expected, std::string_view actual, const CompareOptions& options);

}  // namespace postproc
