// The two documented versions of the PikoCNC G-code dialect.
#pragma once

#include <optional>
#include <string_view>

namespace pikocnc {

// 2016: "PikoCNC G-kod, Skrypty" v1.0; 2025: "PikoCNC G-kod" of 2025-04-16 (a superset).
enum class Dialect : unsigned char { V2016 = 1, V2025 = 2 };

// "pikocnc" (= 2025), "pikocnc-2016", "pikocnc-2025"; nullopt for anything else.
inline std::optional<Dialect> parse_dialect(std::string_view name) {
  if (name == "pikocnc" || name == "pikocnc-2025") return Dialect::V2025;
  if (name == "pikocnc-2016") return Dialect::V2016;
  return std::nullopt;
}

inline std::string_view dialect_name(Dialect d) { return d == Dialect::V2016 ? "pikocnc-2016" : "pikocnc-2025"; }

}  // namespace pikocnc
