// Turns moves and events into neutral toolpath commands (`@rapid_move`, `@line`, `@arc`, `@delay`, ...)
// and queues them for CommandSource::next. Command names and parameters: docs/pikocnc.md.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "machines/pikocnc/motion.hpp"
#include "toolpath/command.hpp"

namespace pikocnc {

class Emitter {
public:
  explicit Emitter(double chord_tolerance) : chord_tolerance_(chord_tolerance) {}

  // Starts a new command at the end of the queue; its parameters are added with the helpers below.
  toolpath::Command& add(std::string_view name);
  void move(const Move& m, const Frame& frame);

  static void number(toolpath::Command& c, std::string_view name, double v);
  static void integer(toolpath::Command& c, std::string_view name, long long v);
  static void logical(toolpath::Command& c, std::string_view name, bool v);
  static void text(toolpath::Command& c, std::string_view name, std::string_view v);
  static void word(toolpath::Command& c, std::string_view name, std::string_view v);

  bool empty() const { return head_ == tail_; }
  // Hands the oldest queued command over (swapping buffers); false when the queue is empty.
  bool pop(toolpath::Command& out, std::size_t& line);

  // The NC line the commands added from now on come from (for positions and trace lines).
  void set_line(std::size_t line, std::string_view text) {
    line_ = line;
    line_text_ = text;
    line_attached_ = false;
  }
  void attach_nc_lines(bool on) { attach_ = on; }
  // A/B appear in motion commands once the program has used them.
  void use_a() { with_a_ = true; }
  void use_b() { with_b_ = true; }

private:
  void positions(toolpath::Command& c, const Eigen::Vector3d& p, double a, double b);
  void straight(const Move& m, const Eigen::Vector3d& to, bool from_arc);
  void chords(const Move& m, const Frame& frame);

  std::vector<toolpath::Command> queue_;
  std::vector<std::size_t> lines_;
  std::size_t head_ = 0, tail_ = 0;
  std::size_t next_index_ = 0;
  std::size_t line_ = 0;
  std::string_view line_text_;
  bool line_attached_ = false;
  bool attach_ = false;
  bool with_a_ = false, with_b_ = false;
  double chord_tolerance_;
};

}  // namespace pikocnc
