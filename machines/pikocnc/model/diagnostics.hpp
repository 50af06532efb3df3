// Warnings of the interpreter: ignored codes and words, interpretation fallbacks. Never fatal;
// fatal problems are thrown as toolpath::InputError. The shape is every library's
// (toolpath/diagnostic.hpp); these are all warnings in the program itself (no file).
#pragma once

#include <cstddef>
#include <string>

#include "toolpath/diagnostic.hpp"

namespace pikocnc {

using Diagnostic = toolpath::Diagnostic;

class Diagnostics : public toolpath::Diagnostics {
public:
  using toolpath::Diagnostics::Diagnostics;
  using toolpath::Diagnostics::add;
  void add(std::size_t line, std::size_t column, std::string message) {
    add({{"", line, column}, toolpath::Severity::Warning, std::move(message)});
  }
};

}  // namespace pikocnc
