#include "toolpath/error.hpp"

#include <fmt/format.h>

namespace toolpath {

InputError::InputError(SourcePosition where, const std::string& message)
    : std::runtime_error(where.line == 0 ? fmt::format("{}: {}", where.file, message)  // the whole file: no position
                                         : fmt::format("{}:{}:{}: {}", where.file, where.line, where.column, message)),
      where_(std::move(where)),
      message_(message) {}

}  // namespace toolpath
