// PikoCNC G-code read back into motion: a toolpath::CommandSource that interprets an NC program
// (either dialect version) and yields the neutral stream commands it produces. See docs/pikocnc.md.
#pragma once

#include <cstddef>
#include <deque>
#include <istream>
#include <memory>
#include <string>

#include "machines/pikocnc/model/diagnostics.hpp"
#include "machines/pikocnc/model/options.hpp"
#include "toolpath/error.hpp"
#include "toolpath/source.hpp"

namespace pikocnc {

class Interpreter;

class PikoReader final : public toolpath::CommandSource {
public:
  // Reads from `in`, which must outlive the reader; `file_name` is used in messages.
  PikoReader(std::istream& in, std::string file_name, Options options = {});
  ~PikoReader() override;
  // Opens a file; throws toolpath::InputError when it cannot be read.
  static std::unique_ptr<PikoReader> open(const std::string& path, Options options = {});
  // A program held in memory; the reader keeps its own copy.
  static std::unique_ptr<PikoReader> from_string(std::string text, std::string file_name, Options options = {});

  // Throws toolpath::InputError (file:line:column) on an error in the program.
  bool next(toolpath::Command& out) override;

  // The NC line that produced the command returned last (0 for @start_of_file and the end).
  std::size_t line() const { return line_; }
  // Warnings so far: ignored codes and words, interpretation fallbacks.
  const Diagnostics& diagnostics() const;
  const std::string& file_name() const;

private:
  // One command as the interpreter produced it, with its NC line.
  bool pull(toolpath::Command& out, std::size_t& line);
  // An NC program says where the tool goes and how fast the spindle turns only after M6; a
  // @change_tool gets xnext/ynext/znext, spin and tool_direction from the commands that follow it.
  void complete_tool_change(toolpath::Command& change);

  struct Pending {
    toolpath::Command command;
    std::size_t line;
  };
  std::unique_ptr<std::istream> owned_;
  std::unique_ptr<Interpreter> interpreter_;
  std::deque<Pending> pending_;  // read ahead for a tool change (bounded)
  bool seen_tool_ = false;
  std::size_t line_ = 0;
};

}  // namespace pikocnc
