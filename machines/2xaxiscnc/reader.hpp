// 2XAxisCNC programs read back into motion: a toolpath::CommandSource that executes the frames of
// a program (relative X/Y moves, speed coefficients, instructions) and yields the neutral stream
// commands they stand for. See docs/2xaxiscnc.md, "Reading programs back".
#pragma once

#include <array>
#include <cstddef>
#include <istream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "machines/2xaxiscnc/frame.hpp"
#include "toolpath/command.hpp"
#include "toolpath/diagnostic.hpp"
#include "toolpath/source.hpp"

namespace twoaxis {

struct Options {
  // The machine speed of the application (mm/min) that coefficient 1 stands for (the post's default
  // machine_speed). With it, moves carry `feed` = coefficient x speed and @end_program the estimated
  // motion time; 0: unknown, neither is given.
  double machine_speed = 3000.0;
  // Moves made at this coefficient are read as @rapid_move; 0 (the default): every move is a @line
  // at its coefficient's feed. The format has only linear moves: a frame at coefficient 1 may be a
  // cut, and re-posting a program to another controller must not turn cuts into rapids. X0Y0 is
  // always a rapid.
  double rapid_coefficient = 0.0;
  // Numbers become single-precision floats as in the application; false keeps their decimal value
  // (to check a post's arithmetic without the controller's rounding).
  bool single_precision = true;
  // The application's /Scripts folder: `RunScript_<name>.script` runs that file's frames in place
  // (nested up to 16 deep, recursion is an error). Empty: scripts are not read (a warning each).
  std::string scripts_folder;
  std::size_t max_diagnostics = 1000;  // kept; the rest are only counted
};

class TwoAxisReader final : public toolpath::CommandSource {
public:
  static constexpr std::size_t kMaxScriptDepth = 16;
  // Reads from `in`, which must outlive the reader; `file_name` is used in messages.
  TwoAxisReader(std::istream& in, std::string file_name, Options options = {});
  ~TwoAxisReader() override;
  // Opens a file; throws toolpath::InputError when it cannot be read.
  static std::unique_ptr<TwoAxisReader> open(const std::string& path, Options options = {});
  // Reads a program held in memory (tests, fuzzing); the reader keeps its own copy.
  static std::unique_ptr<TwoAxisReader> from_string(std::string text, std::string file_name, Options options = {});

  // Never throws for errors in the program: each becomes a diagnostic and the frame is skipped
  // (or its coefficient clamped), as the application would go on. Only a line longer than 16 MiB,
  // in the program or a script (not a program: /dev/zero, a binary file), throws
  // toolpath::InputError at that line.
  bool next(toolpath::Command& out) override;

  // Line of the command returned last in the program; 0 when it came from a script.
  std::size_t line() const { return command_script_.empty() ? command_line_ : 0; }
  // Line of the command returned last in `script_name()`, or in the program.
  std::size_t script_line() const { return command_line_; }
  const std::string& script_name() const { return command_script_; }
  // Errors: frames skipped or clamped (the motion is not the program's). A diagnostic's file is the
  // script it is in; empty: the program.
  const toolpath::Diagnostics& diagnostics() const { return diagnostics_; }
  const std::string& file_name() const { return file_name_; }

private:
  bool next_line(std::string_view& line);
  void frame(std::string_view line, toolpath::Command& out, bool& produced);
  void instruction(std::string_view text, std::size_t column, toolpath::Command& out, bool& produced);
  void move(const Frame& f, toolpath::Command& out);
  void end_program(toolpath::Command& out);
  void diagnose(toolpath::Severity s, std::size_t column, std::string message);
  bool read_number(std::string_view text, std::size_t column, double& value);
  void run_script(std::string_view name, std::size_t column, toolpath::Command& out, bool& produced);

  // The program, and the scripts running inside it: each read in chunks.
  struct Input {
    std::unique_ptr<std::istream> owned;
    std::istream* in = nullptr;
    std::string buffer;
    std::size_t pos = 0;
    bool eof = false;
    std::size_t line = 0;
    std::string script;  // file name of a script; empty for the program
  };
  std::vector<Input> inputs_;
  std::string file_name_;
  Options options_;
  std::size_t command_line_ = 0;
  std::string command_script_;
  enum class Phase { StartFile, StartProgram, Frames, EndProgram, EndFile, Done } phase_ = Phase::StartFile;
  bool first_frame_ = true;
  bool converting_ = false;  // ArtCAM / G90 program: move frames hold absolute positions
  double abs_x_ = 0, abs_y_ = 0;  // conversion: the previous absolute position (decimal)
  double x_ = 0, y_ = 0, a_ = 0, coef_ = 1.0;
  bool spindle_ = false;
  std::array<bool, 4> relays_{};
  double path_length_ = 0, motion_minutes_ = 0, pause_seconds_ = 0;
  toolpath::Diagnostics diagnostics_;
  std::size_t index_ = 0;
};

}  // namespace twoaxis
