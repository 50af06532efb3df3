// Warnings of the interpreter: ignored codes and words, interpretation fallbacks. Never fatal;
// fatal problems are thrown as toolpath::InputError.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "toolpath/error.hpp"

namespace pikocnc {

struct Diagnostic {
  std::size_t line = 0;    // 1-based line of the NC file
  std::size_t column = 0;  // 1-based column of the offending text
  std::string message;
};

// Keeps the first `limit` diagnostics and counts the rest, so memory stays flat on long programs.
class Diagnostics {
public:
  explicit Diagnostics(std::size_t limit = 1000) : limit_(limit) {}
  void add(std::size_t line, std::size_t column, std::string message) {
    ++total_;
    if (kept_.size() < limit_) kept_.push_back({line, column, std::move(message)});
  }
  const std::vector<Diagnostic>& kept() const { return kept_; }
  std::size_t total() const { return total_; }

private:
  std::size_t limit_;
  std::size_t total_ = 0;
  std::vector<Diagnostic> kept_;
};

}  // namespace pikocnc
