#include "toolpath/diagnostic.hpp"

#include <fmt/format.h>

#include <functional>

namespace toolpath {

std::string Diagnostic::text() const {
  const std::string_view kind = error() ? "error" : "warning";
  const std::string what = number ? fmt::format("{} {}: {}", kind, number, message) : fmt::format("{}: {}", kind, message);
  if (where.line == 0) return fmt::format("{}: {}", where.file, what);
  return fmt::format("{}:{}:{}: {}", where.file, where.line, where.column, what);
}

void Diagnostics::add(Diagnostic d) {
  constexpr std::size_t kRemembered = 100'000;  // beyond that, repeats are counted again
  std::size_t h = std::hash<std::string>{}(d.message);
  for (std::size_t v : {d.where.line, d.where.column, std::hash<std::string>{}(d.where.file),
                        static_cast<std::size_t>(d.severity), static_cast<std::size_t>(d.number)})
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
  if (seen_.count(h)) return;
  if (seen_.size() < kRemembered) seen_.insert(h);
  ++total_;
  if (d.error()) ++errors_;
  if (kept_.size() < limit_) kept_.push_back(std::move(d));
}

const Diagnostic* Diagnostics::first_error() const {
  for (const auto& d : kept_)
    if (d.error()) return &d;
  return nullptr;
}

}  // namespace toolpath
