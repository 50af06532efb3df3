// Test helper shared by the controller readers' suites: what a reader makes of a program.
#pragma once

#include <sstream>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "toolpath/trace_writer.hpp"

namespace test_support {

// The trace and the diagnostics (`line: severity: text`, columns left out: a number written
// otherwise moves the words after it) of a reader (ISO, Sinumerik: a CommandSource with
// diagnostics()), read to its end.
template <class Reader>
std::pair<std::string, std::string> trace_and_diagnostics(Reader& reader) {
  std::ostringstream trace;
  toolpath::write_trace(reader, trace);
  std::string diagnostics;
  for (const auto& d : reader.diagnostics().kept())
    diagnostics += fmt::format("{}: {}: {}\n", d.where.line, d.error() ? "error" : "warning", d.message);
  return {trace.str(), diagnostics};
}

}  // namespace test_support
