// One diagnostic shape for every library: where (file, line, column), how bad, what, and the GPPTool
// error number when there is one. Diagnostics keeps the first few and counts the rest, so a reader's
// memory stays flat on a long program full of the same mistake; a diagnostic met again (a block in a
// loop or a subprogram runs many times) is kept and counted once.
#pragma once

#include <cstddef>
#include <string>
#include <unordered_set>
#include <vector>

#include "toolpath/error.hpp"

namespace toolpath {

enum class Severity { Warning, Error };

struct Diagnostic {
  SourcePosition where;
  Severity severity = Severity::Error;
  std::string message;
  int number = 0;  // GPPTool error number; 0: none

  bool error() const { return severity == Severity::Error; }
  // "file:line:col: error: message" ("file: ..." when the line is 0; "error 383: ..." with a number).
  std::string text() const;
};

class Diagnostics {
public:
  explicit Diagnostics(std::size_t limit = 1000) : limit_(limit) {}
  void add(Diagnostic d);
  const std::vector<Diagnostic>& kept() const { return kept_; }
  std::size_t total() const { return total_; }
  std::size_t errors() const { return errors_; }
  const Diagnostic* first_error() const;  // of those kept

private:
  std::size_t limit_;
  std::size_t total_ = 0, errors_ = 0;
  std::vector<Diagnostic> kept_;
  std::unordered_set<std::size_t> seen_;  // hashes of those met so far (up to a bound)
};

}  // namespace toolpath
