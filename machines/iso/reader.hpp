// ISO-family programs read back into motion (Fanuc, LinuxCNC, Mach3, GRBL): a toolpath::CommandSource
// that executes a program block by block, with its subprograms (Fanuc M98/M99 and O numbers in the
// same file, LinuxCNC o-word subroutines and repeats) and canned cycles, and yields the neutral
// stream commands the blocks stand for. The dialects differ as data (Rules): what each control
// accepts and how it reads a dwell. docs/iso.md.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "machines/ncmodel/tool_table.hpp"
#include "toolpath/command.hpp"
#include "toolpath/diagnostic.hpp"
#include "toolpath/source.hpp"

namespace iso {

enum class Scaling { None, PerAxis };  // G51: none, or Mach3's factors per axis

// What a dialect's control does differently (docs/iso.md, "Dialects").
struct Rules {
  std::string_view name;   // as --dialect takes it
  std::string_view title;  // as its maker writes it
  bool canned_cycles = true;   // G73, G81-G89 (GRBL: none)
  bool tool_change = true;     // M6 (GRBL: error 20)
  bool subprograms = true;     // M98/M99 with O numbers (GRBL: none)
  bool o_words = false;        // LinuxCNC o<n> sub/endsub/call, repeat/endrepeat
  bool macro_b = false;        // Fanuc custom macro B: #n variables, WHILE [..] DOm / ENDm
  bool dwell_p_in_ms = false;  // Fanuc: G4 P in milliseconds (X in seconds); the others: P in seconds
  double chip_break_lift = 0.254;  // G73's retract after each peck, mm
  Scaling scaling = Scaling::None;
};
// nullptr for an unknown name: fanuc, linuxcnc, mach3, grbl.
const Rules* rules_of(std::string_view dialect);

struct Options {
  // The control's tool table: with one, G43 H applies tool lengths and positions are the tool tip's
  // (docs/iso.md, "Tool table"); without, positions are as programmed.
  std::shared_ptr<const ncmodel::ToolTable> tools;
  std::size_t max_executed_blocks = 100'000'000;  // a runaway loop stops here, with an error
  std::size_t max_call_depth = 16;
  std::size_t max_diagnostics = 1000;
  double arc_tolerance = 0.002;  // mm: an R arc whose chord is longer than 2|R| by more is an error
};

class IsoReader final : public toolpath::CommandSource {
public:
  // Opens a program; throws toolpath::InputError when it cannot be read.
  static std::unique_ptr<IsoReader> open(const std::string& path, const Rules& rules, Options options = {});
  // A program held in memory (tests, fuzzing).
  static std::unique_ptr<IsoReader> from_string(std::string text, std::string name, const Rules& rules,
                                                Options options = {});
  ~IsoReader() override;

  // Never throws for an error in a block: it becomes a diagnostic and the block is skipped.
  bool next(toolpath::Command& out) override;

  std::size_t line() const;  // of the block the command returned last came from
  const std::string& file_name() const;
  // Errors: the motion is not the program's (a block was skipped).
  const toolpath::Diagnostics& diagnostics() const;

  struct Impl;

private:
  explicit IsoReader(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace iso
