// Errors in input text, always with the position: `file:line:col: message`.
#pragma once

#include <stdexcept>
#include <string>

namespace toolpath {

struct SourcePosition {
  std::string file;
  std::size_t line = 0;    // 1-based
  std::size_t column = 0;  // 1-based
};

class InputError : public std::runtime_error {
public:
  InputError(SourcePosition where, const std::string& message);
  const SourcePosition& where() const { return where_; }
  const std::string& message() const { return message_; }

private:
  SourcePosition where_;
  std::string message_;
};

}  // namespace toolpath
