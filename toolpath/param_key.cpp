#include "toolpath/param_key.hpp"

#include <array>

#include "toolpath/short_text.hpp"
#include "toolpath/value.hpp"

namespace toolpath {
namespace {

constexpr const auto& kNames = detail::param_names;

constexpr std::size_t kLongest = [] {
  std::size_t n = 0;
  for (std::string_view s : kNames) n = s.size() > n ? s.size() : n;
  return n;
}();

// Hashes the first and the last eight bytes (fewer for short names) and the length, case folded.
// Names that share both ends and the length only cost a longer probe.
constexpr std::size_t kTableBits = 10;
constexpr std::size_t kMask = (std::size_t{1} << kTableBits) - 1;
static_assert(param_key_count * 2 < kMask, "keep the table at most half full");

constexpr std::size_t slot_of(std::string_view s) {
  const std::size_t n = s.size();
  const std::size_t head = n < 8 ? n : 8;
  const std::uint64_t a = detail::lower_ascii(load_word(s, 0, head));
  const std::uint64_t b = n > 8 ? detail::lower_ascii(load_word(s, n - 8, 8)) : 0;
  const std::uint64_t h = ((a * 0x9E3779B97F4A7C15ull) ^ (b + n)) * 0xC2B2AE3D27D4EB4Full;
  return static_cast<std::size_t>(h >> (64 - kTableBits));
}

constexpr bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (ascii_lower(a[i]) != ascii_lower(b[i])) return false;
  return true;
}

// Open addressing with linear probing; 0 marks an empty slot. Built by the compiler, so it is
// ready before any static initialiser runs.
constexpr auto kTable = [] {
  std::array<std::uint16_t, kMask + 1> table{};
  for (std::size_t k = 1; k < std::size(kNames); ++k) {
    std::size_t i = slot_of(kNames[k]);
    for (; table[i] != 0; i = (i + 1) & kMask)
      if (same_name(kNames[table[i]], kNames[k])) throw "param_names.inc lists a name twice";
    table[i] = static_cast<std::uint16_t>(k);
  }
  return table;
}();

}  // namespace

ParamKey param_key(std::string_view name) {
  if (name.empty() || name.size() > kLongest) return ParamKey::none;
  for (std::size_t i = slot_of(name);; i = (i + 1) & kMask) {
    const std::uint16_t k = kTable[i];
    if (k == 0) return ParamKey::none;
    if (iequals(kNames[k], name)) return static_cast<ParamKey>(k);
  }
}

}  // namespace toolpath
