#include "prp/filters/command_kind.hpp"

#include <array>

#include "toolpath/short_text.hpp"
#include "toolpath/value.hpp"

namespace prp {
namespace {

constexpr std::string_view kNames[] = {
    "",
#define PRP_KIND_NAME(kind, name) "@" name,
    PRP_COMMAND_KINDS(PRP_KIND_NAME)
#undef PRP_KIND_NAME
};
static_assert(std::size(kNames) <= 64, "KindSet holds 64 kinds");

constexpr std::size_t kBits = 8;
constexpr std::size_t kMask = (std::size_t{1} << kBits) - 1;
static_assert(std::size(kNames) * 3 < kMask, "keep the table at most a third full");

// A name as the hash sees it: its first and last eight bytes, case folded, and its length. Up to 16
// bytes these are the whole name, so comparing them is comparing the names.
struct Folded {
  std::uint64_t head = 0, tail = 0;
  std::size_t size = 0;
};

constexpr Folded fold(std::string_view s) {
  const std::size_t n = s.size();
  return {toolpath::detail::lower_ascii(toolpath::load_word(s, 0, n < 8 ? n : 8)),
          n > 8 ? toolpath::detail::lower_ascii(toolpath::load_word(s, n - 8, 8)) : 0, n};
}

constexpr std::size_t slot_of(const Folded& f) {
  const std::uint64_t h = ((f.head * 0x9E3779B97F4A7C15ull) ^ (f.tail + f.size)) * 0xC2B2AE3D27D4EB4Full;
  return static_cast<std::size_t>(h >> (64 - kBits));
}

struct Slot {
  Folded name;
  std::uint8_t kind = 0;  // 0: empty
};

constexpr std::size_t kLongest = [] {
  std::size_t n = 0;
  for (std::string_view s : kNames) n = s.size() > n ? s.size() : n;
  return n;
}();

// Open addressing, linear probing. Built by the compiler.
constexpr auto kTable = [] {
  std::array<Slot, kMask + 1> table{};
  for (std::size_t k = 1; k < std::size(kNames); ++k) {
    const Folded f = fold(kNames[k]);
    std::size_t i = slot_of(f);
    while (table[i].kind != 0) i = (i + 1) & kMask;
    table[i] = {f, static_cast<std::uint8_t>(k)};
  }
  return table;
}();

// Names over 16 bytes also compare their middle; rare, kept out of the hot path.
[[gnu::noinline]] bool same_long_name(std::uint8_t kind, std::string_view name) {
  return toolpath::iequals(kNames[kind], name);
}

}  // namespace

CommandKind command_kind(std::string_view name) {
  if (name.size() < 2 || name.size() > kLongest) return CommandKind::other;
  const Folded f = fold(name);
  for (std::size_t i = slot_of(f);; i = (i + 1) & kMask) {
    const Slot& s = kTable[i];
    if (s.kind == 0) return CommandKind::other;
    if (s.name.head == f.head && s.name.tail == f.tail && s.name.size == f.size &&
        (f.size <= 16 || same_long_name(s.kind, name)))
      return static_cast<CommandKind>(s.kind);
  }
}

CommandKind KindMemo::learn(std::string_view name, std::uint64_t head, std::uint64_t tail) {
  Entry& e = entries_[name.size() % 8];
  e = {head, tail, name.size(), command_kind(name)};
  return e.kind;
}

}  // namespace prp
