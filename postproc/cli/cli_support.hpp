// What the subcommands that post a job share: the engine options on the command line, opening the
// input, naming the output, and the progress bar.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "postproc/cli/cli.hpp"
#include "postproc/engine/engine.hpp"
#include "toolpath/trace_reader.hpp"

namespace postproc::cli {

// --post, --prp, --include, --units, --no-modal-reset, --answer (repeatable), --answers.
std::vector<OptionSpec> engine_option_specs();
// `log` receives the post's print and input messages (the subcommand's stderr).
EngineOptions engine_options(const Arguments& args, std::ostream* log);
// NAME=VALUE lines of an answers file (`#` comment lines, blank lines); throws
// std::runtime_error "FILE:LINE:COLUMN: ..." on a line without a name and `=`.
std::vector<gppl::Answer> read_answers_file(const std::string& path);

// The machine file's warnings (unknown keys, unknown VMID codes, ...), one a line, as
// `file:line:col: warning: ...`. Every subcommand that loads a PRP or VMID prints them through
// these, so none hides what another shows.
void print_machine_warnings(const prp::MachineParameters& machine, std::ostream& err);
// The engine loads the file once per unit half; both give the same warnings, so one half is printed.
void print_machine_warnings(const Engine& engine, std::ostream& err);

// Writes `text` to `path` through a temporary file renamed on success, so that a failed write never
// leaves half a file in place of the old one; throws toolpath::InputError naming `path`.
void write_file_replacing(const std::string& path, std::string_view text);

// The job file, opened so that the progress bar can tell how far the reader is.
struct Input {
  std::string path;
  std::unique_ptr<std::ifstream> stream;
  std::unique_ptr<toolpath::TraceReader> reader;
  std::uintmax_t size = 0;
  static Input open(const std::string& path);  // throws toolpath::InputError
};

// Run options for `input`: messages name it, and the engine may reopen it.
RunOptions run_options(const Input& input, std::ostream& warnings);

// `--trace LEVEL[:FILE]`: the post's `trace` output to stderr or FILE; LEVEL 0..5 traces every
// procedure at that level, `post` only what the post's own `trace` statements ask. Keeps the file
// open for the run.
class TraceOutput {
public:
  TraceOutput(const Arguments& args, std::ostream& err);
  void apply(RunOptions& options);

private:
  std::ostream* stream_ = nullptr;
  std::unique_ptr<std::ofstream> file_;
  int level_ = -1;
};

// A one-line progress bar on stderr, when stderr is a terminal and --quiet was not given, or when
// --progress asks for it (a log of a long run).
class Progress {
public:
  Progress(std::ostream& err, bool quiet, const Input& input, bool forced = false);
  ~Progress();
  void update(std::size_t commands);

private:
  std::ostream& err_;
  const Input& input_;
  bool enabled_;
  std::int64_t last_ms_ = 0;
  bool drawn_ = false;
};

// Where `run` writes: stdout (no -o, or `-o -`), a folder (`-o DIR`, existing or ending in `/`), or
// a file (`-o FILE`: the main program; files opened by directives go next to it).
struct Destination {
  bool to_stdout = true;
  std::filesystem::path directory;  // where files named by directives go
  std::filesystem::path main_file;  // empty: named from g_file_name and gpp_file_ext
  static Destination parse(const std::string& o);
};

}  // namespace postproc::cli
