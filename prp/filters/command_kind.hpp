// The commands the stream filters react to, as a small enum: every filter looks at every command,
// so a command's name is classified once per filter with one hash probe instead of being compared
// with a list of names (ASCII case ignored, as everywhere in the stream).
//
//   switch (command_kind(c)) { case CommandKind::arc: ... }
//   if (has(command_kind(c), kMovesTool)) ...
#pragma once

#include <cstdint>
#include <string_view>

#include "toolpath/command.hpp"
#include "toolpath/short_text.hpp"

namespace prp {

// X(enumerator, name without the '@')
#define PRP_COMMAND_KINDS(X)                                                                                           \
  X(rapid_move, "rapid_move") X(line, "line") X(arc, "arc") X(line_on, "line_on") X(move_5x, "move_5x")                \
  X(line_5x, "line_5x") X(arc_5x, "arc_5x") X(move_4x, "move_4x") X(line_4x, "line_4x")                                \
  X(move4x_cartesian, "move4x_cartesian") X(move4x_polar, "move4x_polar") X(move4x_dir, "move4x_dir")                  \
  X(line4x_cartesian, "line4x_cartesian") X(line4x_polar, "line4x_polar") X(line4x_dir, "line4x_dir")                  \
  X(arc4x_cartesian, "arc4x_cartesian") X(arc4x_polar, "arc4x_polar") X(start_program, "start_program")                \
  X(end_program, "end_program") X(drill, "drill") X(drill_point, "drill_point") X(end_drill, "end_drill")              \
  X(compensation, "compensation") X(message, "message") X(feed_spin, "feed_spin") X(delay, "delay")                    \
  X(tool_path_info, "tool_path_info") X(absolute_mode, "absolute_mode") X(relative_mode, "relative_mode")              \
  X(change_tool, "change_tool") X(turn_change_tool, "turn_change_tool") X(chng_tool_cnext, "chng_tool_cnext")          \
  X(proc, "proc") X(end_proc, "end_proc") X(call_proc, "call_proc") X(call_prms, "call_prms") X(loop, "loop")          \
  X(end_loop, "end_loop") X(rotate, "rotate") X(mirror, "mirror") X(change_ref_point, "change_ref_point")              \
  X(start_of_file, "start_of_file") X(end_of_file, "end_of_file") X(start_of_job, "start_of_job")                      \
  X(end_of_job, "end_of_job") X(home_number, "home_number") X(rotary_info, "rotary_info") X(init_cpos, "init_cpos")  \
  X(turning, "turning") X(groove, "groove")

enum class CommandKind : std::uint8_t {
  other,  // any command the filters pass without looking at it
#define PRP_KIND_ENUM(kind, name) kind,
  PRP_COMMAND_KINDS(PRP_KIND_ENUM)
#undef PRP_KIND_ENUM
};

// The kind of a command name (with its '@'); CommandKind::other for any other name.
CommandKind command_kind(std::string_view name);
inline CommandKind command_kind(const toolpath::Command& c) { return command_kind(c.name); }

// command_kind() of the names seen last, by their exact bytes: a stream repeats a handful of names,
// and comparing a name with the one remembered for its length costs a third of hashing it.
class KindMemo {
public:
  // A name of up to 16 bytes is wholly in (head, tail, size); a longer one is classified in full.
  CommandKind operator()(std::string_view name) {
    const std::size_t n = name.size();
    if (n == 0 || n > 16) return command_kind(name);
    const std::uint64_t head = toolpath::load_word(name, 0, n < 8 ? n : 8);
    const std::uint64_t tail = n > 8 ? toolpath::load_word(name, n - 8, 8) : 0;
    const Entry& e = entries_[n % 8];
    if (e.size == n && e.head == head && e.tail == tail) return e.kind;
    return learn(name, head, tail);
  }

private:
  CommandKind learn(std::string_view name, std::uint64_t head, std::uint64_t tail);  // out of line: rare

  struct Entry {
    std::uint64_t head = 0, tail = 0;  // the name's first and last eight bytes (size 0: empty)
    std::size_t size = 0;
    CommandKind kind = CommandKind::other;
  };
  Entry entries_[8];  // by the name's length, modulo 8
};

// Groups of kinds, as bits.
using KindSet = std::uint64_t;
constexpr KindSet bit(CommandKind k) { return KindSet{1} << static_cast<unsigned>(k); }
constexpr bool has(KindSet set, CommandKind k) { return (set & bit(k)) != 0; }

// Commands whose xpos/ypos/zpos is where the tool is afterwards.
inline constexpr KindSet kMovesTool = bit(CommandKind::rapid_move) | bit(CommandKind::line) | bit(CommandKind::arc) |
                                      bit(CommandKind::line_on) | bit(CommandKind::move_5x) |
                                      bit(CommandKind::line_5x) | bit(CommandKind::arc_5x) |
                                      bit(CommandKind::start_program) | bit(CommandKind::end_program);
inline constexpr KindSet kFeedMotion = bit(CommandKind::line) | bit(CommandKind::arc) | bit(CommandKind::line_on) |
                                       bit(CommandKind::line_5x) | bit(CommandKind::arc_5x);
// Everything that moves the machine: 3-, 4- and 5-axis moves and arcs, and @drill (its first hole).
inline constexpr KindSet kMotionBlock =
    (kMovesTool & ~(bit(CommandKind::start_program) | bit(CommandKind::end_program))) | bit(CommandKind::move_4x) |
    bit(CommandKind::line_4x) | bit(CommandKind::move4x_cartesian) | bit(CommandKind::move4x_polar) |
    bit(CommandKind::move4x_dir) | bit(CommandKind::line4x_cartesian) | bit(CommandKind::line4x_polar) |
    bit(CommandKind::line4x_dir) | bit(CommandKind::arc4x_cartesian) | bit(CommandKind::arc4x_polar) |
    bit(CommandKind::drill);

}  // namespace prp
