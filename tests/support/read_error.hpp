// Test helper shared by the reader suites: read a command stream to its end.
#pragma once

#include <string>

#include "toolpath/error.hpp"
#include "toolpath/source.hpp"

namespace test_support {

// Takes every command of `source`: "" when it reads through, else the InputError's text.
inline std::string read_error(toolpath::CommandSource& source) {
  toolpath::Command c;
  try {
    while (source.next(c)) {
    }
  } catch (const toolpath::InputError& e) {
    return e.what();
  }
  return {};
}

}  // namespace test_support
