// Sinumerik 828D/840D programs read back into motion: a toolpath::CommandSource that executes a
// main program (.MPF) block by block, with the subprograms it calls from its folder (EXTCALL, L<n>,
// a program name; P repeats), and yields the neutral stream commands the blocks stand for. What it
// reads and how: docs/sinumerik.md. Streaming: memory does not grow with the program.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "toolpath/command.hpp"
#include "toolpath/diagnostic.hpp"
#include "toolpath/source.hpp"

namespace sinumerik {

struct Options {
  std::size_t max_executed_blocks = 100'000'000;  // a runaway GOTOB loop stops here, with an error
  std::size_t max_call_depth = 16;                // subprograms calling subprograms
  std::size_t max_diagnostics = 1000;             // kept; the rest are counted
  double arc_tolerance = 0.002;                   // mm: a CR= chord longer than 2|CR| by more is an error
};

class SinumerikReader final : public toolpath::CommandSource {
public:
  // Opens the main program; subprograms are looked up in its folder. Throws toolpath::InputError
  // when it cannot be read.
  static std::unique_ptr<SinumerikReader> open(const std::string& path, Options options = {});
  // A program held in memory (tests, fuzzing): it has no folder, so every subprogram call is an error.
  static std::unique_ptr<SinumerikReader> from_string(std::string text, std::string name, Options options = {});
  ~SinumerikReader() override;

  // Never throws for an error in a block: it becomes a diagnostic and the block is skipped, as a
  // control would stop there (the caller reports the errors when the stream ends). Runaway loops,
  // subprogram recursion and missing subprograms end the program with an error diagnostic.
  bool next(toolpath::Command& out) override;

  // Line of the command returned last in the main program; 0 when it came from a subprogram.
  std::size_t line() const;
  const std::string& file_name() const;
  // Errors: the motion is not the program's (a block was skipped).
  const toolpath::Diagnostics& diagnostics() const;

private:
  struct Impl;
  explicit SinumerikReader(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace sinumerik
