// Turns moves and events into neutral toolpath commands (`@rapid_move`, `@line`, `@arc`, `@delay`, ...)
// and queues them for CommandSource::next. Command names and parameters: docs/pikocnc.md.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "machines/pikocnc/model/geometry.hpp"
#include "machines/pikocnc/model/motion.hpp"
#include "toolpath/command.hpp"
#include "toolpath/parameter_shelf.hpp"
#include "toolpath/short_text.hpp"

namespace pikocnc {

class Emitter {
public:
  explicit Emitter(double chord_tolerance) : chord_tolerance_(chord_tolerance) {}

  // Starts a new command at the end of the queue; the helpers below add its parameters. Commands
  // are recycled with their buffers, so a long program allocates nothing per command.
  void add(std::string_view name);
  void move(const Move& m, const Frame& frame);

  // Inline: every parameter of every command comes here, mostly with a literal name, so that the
  // comparison with the name the recycled slot already has folds to a few word compares.
  [[gnu::always_inline]] void number(std::string_view name, double v) { slot(name, toolpath::ValueKind::Numeric).numeric = clean(v); }
  [[gnu::always_inline]] void integer(std::string_view name, long long v) { slot(name, toolpath::ValueKind::Integer).integer = v; }
  [[gnu::always_inline]] void logical(std::string_view name, bool v) { slot(name, toolpath::ValueKind::Logical).logical = v; }
  [[gnu::always_inline]] void text(std::string_view name, std::string_view v) { slot(name, toolpath::ValueKind::String).text.assign(v); }
  [[gnu::always_inline]] void word(std::string_view name, std::string_view v) { slot(name, toolpath::ValueKind::Enum).text.assign(v); }

  // True when no command can be handed over: the queue is empty or stops at an unfilled hole.
  bool empty() const { return head_ == (holes_.empty() ? tail_ : holes_.front().pos); }
  // Hands the oldest queued command over (swapping buffers); false when the queue is empty.
  bool pop(toolpath::Command& out, std::size_t& line);

  // Holes keep the place of commands that are not known yet (cutter compensation waits for the
  // next element): reserve() marks the end of the queue; commands added between begin_fill() and
  // end_fill() go into the oldest hole, with the NC line that was current when it was reserved.
  // Nothing behind a hole is handed over until it is filled. Holes are filled oldest first.
  void reserve();
  void begin_fill();
  void end_fill();
  std::size_t holes() const { return holes_.size(); }

  // While muted (the interpreter looking ahead), commands are built and thrown away.
  struct Context {
    std::size_t line;
    bool line_attached, with_a, with_b;
  };
  Context context() const { return {line_, line_attached_, with_a_, with_b_}; }
  void mute(bool on);
  void restore(const Context& c) {
    line_ = c.line;
    line_text_ = {};
    line_attached_ = true;
    with_a_ = c.with_a;
    with_b_ = c.with_b;
  }

  // The NC line the commands added from now on come from (for positions and trace lines).
  void set_line(std::size_t line, std::string_view text) {
    line_ = line;
    line_text_ = text;
    line_attached_ = false;
  }
  void attach_nc_lines(bool on) { attach_ = on; }
  // At most `max_commands` commands are built, muted ones included; one more is an InputError at
  // the current line of `file` (a runaway loop or a cycle without end).
  void limit(std::size_t max_commands, std::string file) {
    budget_ = max_commands;
    file_ = std::move(file);
  }
  // A/B appear in motion commands once the program has used them.
  void use_a() { with_a_ = true; }
  void use_b() { with_b_ = true; }

private:
  void finish_command();
  // The next parameter of the command being filled, named `name`: a recycled slot mostly has that
  // name already. Forced inline into the helpers above; the rare steps are calls.
  [[gnu::always_inline]] toolpath::Value& slot(std::string_view name, toolpath::ValueKind kind) {
    auto& params = current_->parameters;
    toolpath::Parameter& p = fill_ < params.size() ? params[fill_] : new_slot();
    ++fill_;
    if (!toolpath::same_short_text(p.name, name)) rename(p, name);
    p.value.kind = kind;
    p.value.flag = toolpath::ChangeFlag::None;
    return p.value;
  }
  toolpath::Parameter& new_slot();
  static void rename(toolpath::Parameter& p, std::string_view name);
  void positions(const Eigen::Vector3d& p, double a, double b);
  void straight(const Move& m, const Eigen::Vector3d& to, bool from_arc);
  void chords(const Move& m, const Frame& frame);
  // compensated:true and the programmed end point (prog_xpos ...) of a move G41/G42 moved.
  void compensation_marks(const Move& m, const Frame& frame);

  struct Hole {
    std::size_t pos;   // queue position of its first command
    std::size_t line;  // NC line of the commands that fill it
    bool wants_text;   // the NC line text goes to its first command
    std::string text;
  };

  std::vector<toolpath::Command> queue_;
  toolpath::Command* current_ = nullptr;  // the command being filled
  std::size_t fill_ = 0;                  // its parameters so far
  std::vector<std::size_t> lines_;
  std::size_t head_ = 0, tail_ = 0;
  std::size_t next_index_ = 0;
  std::size_t line_ = 0;
  std::string_view line_text_;
  bool line_attached_ = false;
  bool attach_ = false;
  bool with_a_ = false, with_b_ = false;
  double chord_tolerance_;
  std::vector<Hole> holes_;  // oldest first; few at a time
  std::size_t fill_start_ = 0;
  std::size_t saved_line_ = 0;
  std::string_view saved_text_;
  bool saved_attached_ = false;
  bool muted_ = false;
  toolpath::Command scratch_;  // where muted commands go
  // The queue's commands come back from the consumer in turn, so an @arc is mostly refilled
  // from a @line: the shelf keeps the parameter vectors of other command names, so that their
  // names need not be renamed (and looked up) arc after arc.
  toolpath::ParameterShelf shelf_;
  std::size_t built_ = 0;
  std::size_t budget_ = static_cast<std::size_t>(-1);
  std::string file_;
};

}  // namespace pikocnc
