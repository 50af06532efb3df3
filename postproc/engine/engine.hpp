// The engine: binds a PRP file, a GPP post and a toolpath command stream into NC files.
//
//   Engine engine({.post = "fanuc.gpp", .prp = "fanuc.prp"});   // compiles the post once
//   OutputFiles out(".");
//   engine.run(reader, out, {.input_name = "job.trace"});
//   out.commit();
//
// For each stream command, in order, the engine assigns its parameters to the post's variables
// (assignment semantics; a `T`/`F` flag forces the change attribute), sets prev_command,
// current_command and next_command (it reads one command ahead), and calls the procedure of the
// same name; a command the post has no procedure for only sets its variables. docs/engine.md has
// the rules in full.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gppl/gppl.hpp"
#include "postproc/engine/output_files.hpp"
#include "postproc/engine/line_origin.hpp"
#include "prp/prp.hpp"
#include "toolpath/source.hpp"

namespace postproc {

struct EngineOptions {
  std::string post;                        // the .gpp file
  std::string prp;                         // the .prp file; empty: none
  // Which half of the PRP's metric/inch pairs applies. Unset: the job's own unit system, the
  // `inch_system` of the stream's first command (@start_of_file); metric when it has none.
  std::optional<prp::Units> units;
  std::vector<std::string> include_paths;  // where `inc` files are looked up besides the post's folder
  // Modal memory is forgotten where a subroutine body starts and after a subroutine call, because
  // the machine state there is not the one the previous block left (docs/engine.md).
  bool reset_modal_memory_at_subroutines = true;
  std::uint64_t max_loop_iterations = 100'000'000;  // per procedure run: a runaway `while` stops
  int max_call_depth = 200;                         // a runaway recursion stops (error 405)
  // Answers for the post's `input` statements (runs are not interactive); checked against the
  // post when it compiles: a value of the wrong type is an error, an answer no `input` reads a
  // warning on `log`.
  std::vector<gppl::Answer> answers;
  // The run log: the post's `print` messages and one line per `input`. nullptr: discarded.
  std::ostream* log = nullptr;
  bool log_inputs = true;  // false (`-q`): the answers to `input` statements are not logged
};

// One line the run produced (or one directive it executed), with who produced it.
struct LineEvent {
  std::string_view file;  // the output file it went to (for a directive: the file current before it)
  std::string_view text;
  bool directive = false;
  bool main_file = false;  // `file` is the main program (not a file a directive opened)
  // The empty first line of a file that the break before its first block makes (SolidCAM writes
  // breaks before blocks): a line of the file, but not one the post generated (no `>` line in a trace).
  bool leading_break = false;
  LineOrigin origin;
};

class LineObserver {
public:
  virtual ~LineObserver() = default;
  virtual void on_line(const LineEvent& event) = 0;
  // A line may carry placeholders for numbers known only later (start_line/end_line): markers
  // postproc/engine/slot_marker.hpp describes. This gives a placeholder's final text once it is known.
  virtual void on_slot_filled(std::uint32_t slot, std::string_view text) { (void)slot, (void)text; }
};

struct RunOptions {
  std::string input_name;  // for messages ("job.trace")
  // Chooses the main file's final path from its default name (`g_file_name` + `.` + gpp_file_ext).
  std::function<std::filesystem::path(const std::string& default_name)> main_path;
  LineObserver* observer = nullptr;
  std::ostream* trace = nullptr;  // the post's `trace` output and the commands skipped
  // 0..5: every procedure is traced at this level (as `trace "all":level` would), whatever the post
  // asks; -1: only what the post's own `trace` statements ask.
  int trace_level = -1;
  // Warnings about the stream (`job.trace:12:1: warning: ...`): a parameter a command should carry
  // and does not, a command the PRP does not expect. nullptr: discarded.
  std::ostream* warnings = nullptr;
  std::function<void(std::size_t commands)> progress;  // called every 4096 commands
  // Called with each command as its procedure is about to run: after the PRP filters and with the
  // structure the engine completes (`postproc verify` models the motion from these).
  std::function<void(const toolpath::Command& command)> posted;
  // Reopens the input from its start, where the engine must look ahead over the whole stream: a
  // @start_of_file without `first_user_proc` (docs/engine.md), and procedures generated in two
  // passes (a skim of a trace file first, docs/prp.md). May be empty: then one pass.
  std::function<std::unique_ptr<toolpath::CommandSource>()> reopen;
  // The input is read and checked on the PRP filters' thread (Shared: two threads with the post's),
  // or on a thread of its own (Own: three). Auto: Own where the process may use three CPUs or more.
  // The NC program, warnings and errors are the same either way.
  enum class ReaderThread : std::uint8_t { Auto, Shared, Own };
  ReaderThread reader_thread = ReaderThread::Auto;
};

struct RunSummary {
  std::size_t commands = 0;  // stream commands read
  std::size_t skipped = 0;   // commands the post has no procedure for
  std::size_t lines = 0;     // lines written
  prp::Units units = prp::Units::Metric;  // the PRP half the run used
};

// An error during a run: names the command (index and name) and, for errors of the post, the GPP
// position and the GPPTool error number.
class RunError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class Engine {
public:
  // Loads the PRP and compiles the post. Throws toolpath::InputError (PRP) or gppl::Errors (post,
  // or an answer that does not fit its variable).
  explicit Engine(EngineOptions options);
  ~Engine();

  // Posts `input` into `output` (not committed: the caller commits on success).
  RunSummary run(toolpath::CommandSource& input, OutputFiles& output, const RunOptions& options) const;

  // The PRP with the half of its metric/inch pairs that `units` selects; without an argument, the
  // half of EngineOptions::units (metric when unset). Both halves are loaded at construction.
  const prp::MachineParameters& machine(prp::Units units) const;
  const prp::MachineParameters& machine() const { return machine(options_.units.value_or(prp::Units::Metric)); }
  // The output file extension (`gpp_file_ext`), empty when the PRP has none.
  std::string file_extension() const;
  // The drill-cycle names of the PRP (`drill_type = <name> ...`), in file order.
  std::vector<std::string> drill_cycle_names() const;
  const EngineOptions& options() const { return options_; }

private:
  EngineOptions options_;
  prp::MachineParameters prp_metric_, prp_inch_;
  std::shared_ptr<const gppl::Program> program_;
};

}  // namespace postproc
