// Word-at-a-time helpers for short names (parameter and command names, display formats): the
// filters, the key tables and the engine compare or hash a few names per command, and a memcmp
// call or a byte loop costs more than the comparison itself.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <type_traits>

namespace toolpath {

// `n` (at most 8) bytes of `s` from `at`, as a little-endian word (zero above them). Usable in
// constant expressions (the key tables are built at compile time).
constexpr std::uint64_t load_word(std::string_view s, std::size_t at, std::size_t n) {
  const char* p = s.data() + at;
  if (!std::is_constant_evaluated() && std::endian::native == std::endian::little && n >= 4) {
    if (n == 8) {
      std::uint64_t w;
      std::memcpy(&w, p, 8);
      return w;
    }
    std::uint32_t low, high;  // two overlapping halves: the bytes they share are equal
    std::memcpy(&low, p, 4);
    std::memcpy(&high, p + n - 4, 4);
    return low | std::uint64_t{high} << (8 * (n - 4));
  }
  std::uint64_t w = 0;
  for (std::size_t i = 0; i < n; ++i) w |= std::uint64_t{static_cast<unsigned char>(p[i])} << (8 * i);
  return w;
}

// Exact equality, with two overlapping word loads for texts of 4 to 16 bytes.
inline bool same_short_text(std::string_view a, std::string_view b) {
  const std::size_t n = a.size();
  if (n != b.size()) return false;
  if (n > 16) return a == b;
  const char *p = a.data(), *q = b.data();
  auto word8 = [](const char* s) { std::uint64_t w; std::memcpy(&w, s, 8); return w; };
  auto word4 = [](const char* s) { std::uint32_t w; std::memcpy(&w, s, 4); return w; };
  if (n >= 8) return word8(p) == word8(q) && word8(p + n - 8) == word8(q + n - 8);
  if (n >= 4) return word4(p) == word4(q) && word4(p + n - 4) == word4(q + n - 4);
  if (n == 0) return true;
  return p[0] == q[0] && p[n / 2] == q[n / 2] && p[n - 1] == q[n - 1];  // 1 to 3 bytes: all of them
}

}  // namespace toolpath
