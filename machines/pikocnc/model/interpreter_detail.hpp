// Private to the interpreter: the codes of one block and the words they own (section 2.2).
#pragma once

#include <fmt/format.h>

#include <array>
#include <bit>
#include <bitset>
#include <string>
#include <utility>
#include <vector>

#include "machines/pikocnc/model/interpreter.hpp"

namespace pikocnc {

constexpr std::uint32_t letter_bit(char letter) { return 1u << (letter - 'A'); }

constexpr std::uint32_t letters(std::string_view s) {
  std::uint32_t m = 0;
  for (char c : s) m |= letter_bit(c);
  return m;
}

// Codes that own words and allow no other motion in their line, in the order that decides
// between two of them (section 2.2).
inline int owner_rank(Op op) {
  switch (op) {
    case Op::G10: case Op::G10_1: case Op::G10_2: return 1;
    case Op::G43: case Op::G43_1: case Op::G43_2: return 2;
    case Op::G51: return 3;
    case Op::G52: case Op::G92: return 4;
    case Op::G65: return 5;
    case Op::G68: return 6;
    case Op::G68_2: return 7;
    case Op::G76: return 8;
    case Op::Macro: return 9;
    case Op::G53: case Op::G53_1: return 10;
    case Op::G28: case Op::G30: return 11;
    default: return 0;
  }
}

inline bool is_cycle(Op op) {
  return op == Op::G81 || op == Op::G83 || op == Op::G84 || op == Op::G74 || op == Op::G74_1;
}

struct Interpreter::Resolved {
  std::bitset<static_cast<std::size_t>(Op::Unknown) + 1> ops;
  std::array<std::uint32_t, static_cast<std::size_t>(Op::Unknown) + 1> columns{};
  Op motion = Op::Unknown;         // the motion-group code written in the line
  Op owner = Op::Unknown;          // the code owning the line's words
  std::uint32_t owner_words = 0;
  std::uint32_t partial_words = 0; // letters taken by G4, G25, G41/G42, G50
  const CodeInfo* motion_info = nullptr;
  CodeWord macro{};
  CodeWord tcpc{};
  std::vector<Op> transform_order;
  std::vector<std::pair<std::size_t, std::string>> conflicts;
  mutable bool cycle_in_line = false;
  std::uint32_t groups = 0;  // bit per Group of the codes in the line

  bool has(Op op) const { return ops.test(static_cast<std::size_t>(op)); }

  void reset() {
    ops.reset();
    motion = owner = Op::Unknown;
    owner_words = partial_words = 0;
    motion_info = nullptr;
    transform_order.clear();
    conflicts.clear();
    cycle_in_line = false;
    groups = 0;
  }
  // Only motion-group codes (G0, G1, ...): the common line, which skips the setting steps.
  bool only_motion() const { return (groups & ~(1u << static_cast<unsigned>(Group::Motion))) == 0; }
  std::size_t column(Op op) const { return columns[static_cast<std::size_t>(op)]; }

  void add(const CodeInfo& info, const CodeWord& cw) {
    const auto k = static_cast<std::size_t>(info.op);
    if (ops.test(k) && info.op != Op::Macro)
      conflicts.emplace_back(cw.column, fmt::format("{}{} given twice in one line", cw.letter, cw.number));
    ops.set(k);
    columns[k] = cw.column;
    groups |= 1u << static_cast<unsigned>(info.group);
    if (info.op == Op::Macro) macro = cw;
    if (info.op == Op::G234) tcpc = cw;
    if (info.group == Group::Transform) transform_order.push_back(info.op);
    if (info.group == Group::Motion) {
      if (motion != Op::Unknown)
        conflicts.emplace_back(cw.column, "two motion codes in one line: the last one counts");
      motion = info.op;
      motion_info = &info;
    }
    switch (info.op) {
      case Op::G4: partial_words |= letter_bit('P'); break;
      case Op::G25: case Op::G41: case Op::G42: partial_words |= letter_bit('R'); break;
      case Op::G50: partial_words |= letter_bit('S'); break;
      default: break;
    }
    if (const int rank = owner_rank(info.op)) {
      if (owner == Op::Unknown || rank < owner_rank(owner)) {
        if (owner != Op::Unknown)
          conflicts.emplace_back(cw.column, "two codes that take words in one line: the first in section 2.2 order takes them");
        owner = info.op;
        owner_words = letters(info.words);
        if (info.op == Op::G53 || info.op == Op::G53_1) owner_words |= letter_bit('F');
      } else {
        conflicts.emplace_back(cw.column, "two codes that take words in one line: the first in section 2.2 order takes them");
      }
    }
  }
};

struct Interpreter::Words {
  const Block& b;
  const Resolved& r;
  double unit;
  bool diameter;
  std::uint32_t used = 0;

  Words(const Block& block, const Resolved& resolved, double u, bool dia) : b(block), r(resolved), unit(u), diameter(dia) {}

  bool has(char l) const { return b.has(l); }
  // A word the line's owning code takes.
  bool owned(char l) const { return b.has(l) && (r.owner_words & letter_bit(l)); }
  // A word free for the modal motion: not taken by an owning code or by G4/G25/G41/G42/G50.
  bool free(char l) const { return b.has(l) && !((r.owner_words | r.partial_words) & letter_bit(l)); }
  // Whether any of `mask`'s letters is free, at once.
  bool any_free(std::uint32_t mask) const { return (b.present & mask & ~(r.owner_words | r.partial_words)) != 0; }
  double raw(char l) {
    used |= letter_bit(l);
    return b.get(l);
  }
  // A length: converted from inches, X (and U) halved in diameter mode.
  double len(char l) {
    double v = raw(l) * unit;
    if (diameter && (l == 'X' || l == 'U')) v /= 2;
    return v;
  }
  double len_plain(char l) { return raw(l) * unit; }
  std::size_t col(char l) const { return b.col(l); }

  template <class Warn>
  void report_unused(Warn&& warn) const {
    // Only the letters left, lowest first: most lines leave none.
    for (std::uint32_t left = b.present & ~used; left != 0; left &= left - 1) {
      const char l = static_cast<char>('A' + std::countr_zero(left));
      warn(b.col(l), fmt::format("word {} not used by this line: ignored", l));
    }
  }
};

}  // namespace pikocnc
