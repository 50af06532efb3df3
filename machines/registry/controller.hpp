// A controller model as the rest of the tool sees it: the names `--dialect` takes, how a program
// for it is read back into a command stream, and what its programs can say (which decides how
// `verify` compares). Each controller folder under machines/ defines one; registry.cpp lists them.
// Adding a controller: docs/architecture.md, "A new controller".
#pragma once

#include <cstddef>
#include <memory>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "toolpath/source.hpp"

namespace machines {

struct ReadOptions {
  // Every command carries the NC line it came from (`postproc read --nc-lines`).
  bool nc_lines_in_trace = false;
  // Read for `verify`: the programmed path (no cutter compensation), comments are no commands.
  bool for_verify = false;
  // A runaway loop stops after this many blocks executed (0: the model's own bound, in the hundred
  // millions); the fuzz target keeps it low so that one input runs in milliseconds.
  std::size_t max_blocks = 0;
  // The control's tool table (a file in LinuxCNC's format, machines/ncmodel/tool_table.hpp), for
  // the models that apply tool lengths; empty: none.
  std::string tool_table;
  // The post's `input` answers of the run (NAME, VALUE): a controller whose program depends on the
  // application's settings (2XAxisCNC's machine speed) takes them from there.
  std::vector<std::pair<std::string, std::string>> answers;
};

// A program read back: the commands it stands for, and where each came from.
class ProgramSource : public toolpath::CommandSource {
public:
  // The program line of the command returned last (1-based; 0 when it is not in the program, as a
  // command of a script file).
  virtual std::size_t line() const = 0;
};

// What the comparison of `verify` must know of a controller's programs.
struct VerifyProfile {
  // The program moves in X and Y only, every move a straight line at a speed (2XAxisCNC): both sides
  // are compared projected on X Y, every move as a feed, without tool changes, the spindle only on or
  // off. The toolpath's feeds become the speeds the post writes: feed / machine_speed as a
  // coefficient, rounded to 4 decimals and kept within 0.0001 .. 1; its rapids run at
  // rapid_coefficient; a move back to X0 Y0 in the program runs at coefficient 1.
  bool planar_speeds = false;
  double machine_speed = 0;       // mm/min at coefficient 1
  double rapid_coefficient = 1;
  // The program changes tools itself (M6); false: a tool change is the operator's (GRBL: the post
  // asks for the tool in a comment), so tool changes are not compared.
  bool tool_changes = true;
  // A tapping cycle feeds out to the R level, then rapids to the return level (G84 of Fanuc, LinuxCNC,
  // Sinumerik's CYCLE84); false: it feeds out all the way (a self-reversing tapping head: PikoCNC).
  bool tap_feeds_out_to_r = true;
};

class Controller {
public:
  virtual ~Controller() = default;
  // The first name is the controller's; the others are the aliases and variants `--dialect` takes.
  virtual std::span<const std::string_view> names() const = 0;
  virtual std::string_view title() const = 0;    // "PikoCNC": the controller as its maker writes it
  virtual std::string_view summary() const = 0;  // one line for --help and the docs
  // Opens a program; `dialect` is the name it was asked by (a variant such as pikocnc-2016). The
  // reader's warnings go to `warnings` when the stream ends; errors that make the motion wrong are
  // thrown (toolpath::InputError with file:line:column). Throws toolpath::InputError when the file
  // cannot be read.
  virtual std::unique_ptr<ProgramSource> open(const std::string& path, std::string_view dialect,
                                              const ReadOptions& options, std::ostream& warnings) const = 0;
  // The same for a program held in memory, `name` in its messages. Nothing is looked up beside it
  // (subprogram and script files): there is no folder. Every controller is fuzzed through this
  // (tests/fuzz/, target `controllers`), so a new one is fuzzed from its registry line on.
  virtual std::unique_ptr<ProgramSource> open_text(std::string text, const std::string& name, std::string_view dialect,
                                                   const ReadOptions& options, std::ostream& warnings) const = 0;
  virtual VerifyProfile verify_profile(const ReadOptions& options) const {
    (void)options;
    return {};
  }
  // A long typical milling program of about `blocks` blocks in this controller's language, for the
  // reading benchmark (bench/controller_bench.cpp); false: the controller has none.
  virtual bool write_sample_program(std::ostream& out, std::size_t blocks) const {
    (void)out;
    (void)blocks;
    return false;
  }
};

}  // namespace machines
