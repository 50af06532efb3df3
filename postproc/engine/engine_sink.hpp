// The engine's end of the interpreter's output: finished lines are written to the output files,
// directive lines executed, and each line is told to the run's observer with the command that
// produced it. Internal to postproc/ (engine.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <string_view>

#include "gppl/gppl.hpp"
#include "postproc/engine/engine.hpp"
#include "postproc/engine/line_numbers.hpp"
#include "postproc/engine/output_files.hpp"

namespace postproc {

class EngineSink final : public gppl::OutputSink {
public:
  // `post`: the post's path as compiled, so that lines of its include files can be told apart.
  EngineSink(OutputFiles& files, LineObserver* observer, std::string post)
      : files_(files), observer_(observer), post_(std::move(post)) {}

  void write_line(std::string_view line, const gppl::LineOrigin& origin) override;

  // Called when a command starts (lines are attributed to the command that started them).
  void begin_command(std::size_t index, std::string_view name, std::uint32_t line) {
    command_index = index;
    command_name = name;
    command_line = line;
    wrote_in_command_ = false;
    if (opener_name_.empty()) {
      opener_index_ = index;
      opener_name_ = name;
    }
  }

  // start_line/end_line: the interpreter's structure hooks (called only for posts that use them).
  void block_numbered(std::int64_t number) override { line_numbers->block_numbered(number); }
  void procedure_boundary(gppl::ProcedureId id, bool entering) override { line_numbers->procedure_boundary(id, entering); }
  void line_function(gppl::LineFunction which, std::string_view format, const gppl::Position& item,
                     std::string& out) override {
    line_numbers->line_function(which, format, item, out);
  }
  LineNumbers* line_numbers = nullptr;

  // After the last command: the lines still open belong to the command that started them.
  void end_commands() {
    command_name = {};
    wrote_in_command_ = false;
  }

  std::size_t command_index = 0;
  std::string_view command_name;
  std::uint32_t command_line = 0;  // of the command's header in the input (0: not read from a file)
  std::size_t lines = 0;  // written, with the empty first line the break before a file's first block makes

private:
  void write_observed(std::string_view line, const gppl::LineOrigin& origin, bool maybe_directive);
  // LineOrigin::include_file of a line written by a statement of `file`; empty for the post itself.
  std::string_view include_name(std::string_view file);

  bool wrote_in_command_ = false;
  std::size_t opener_index_ = 0;
  std::string opener_name_;
  OutputFiles& files_;
  LineObserver* observer_;
  std::string file_name_;
  std::string post_;
  // Include files by their path as compiled, and their names relative to the post's folder: a
  // deque, so that the names handed out stay where they are.
  std::deque<std::pair<std::string, std::string>> include_names_;
};

}  // namespace postproc
