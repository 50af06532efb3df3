// The public face of the GPPL library: compile a post once, then run its procedures against an
// environment of variables, writing NC lines to a sink. It knows nothing of toolpath files.
//
// Contract between gppl/ and the engine (postproc/): keep this header small and stable.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gppl {

enum class Type : std::uint8_t { Integer, Numeric, Logical, String };

struct Value {
  Type type = Type::Integer;
  std::int64_t integer = 0;  // Integer (Logical uses `logical`)
  double numeric = 0.0;      // Numeric
  bool logical = false;      // Logical
  std::string text;          // String

  static Value of_integer(std::int64_t v);
  static Value of_numeric(double v);
  static Value of_logical(bool v);
  static Value of_string(std::string v);
  friend bool operator==(const Value&, const Value&) = default;
};

struct Position {
  std::string file;  // as given (the main file's path; includes relative to it)
  int line = 0;      // 1-based
  int column = 0;    // 1-based
};

// Every diagnostic carries the GPPTool error number (section 13 of the spec) and a position:
// what() is "file:line:col: error NNN: text".
class Error : public std::runtime_error {
public:
  Error(int number, Position where, const std::string& text);
  int number() const { return number_; }
  const Position& where() const { return where_; }
  const std::string& text() const { return text_; }

private:
  int number_;
  Position where_;
  std::string text_;
};

// Several load-time errors at once (compile collects them before giving up).
class Errors : public std::runtime_error {
public:
  explicit Errors(std::vector<Error> all);
  const std::vector<Error>& all() const { return all_; }

private:
  std::vector<Error> all_;
};

// Variables the host declares before compiling: system variables (gcode, blknum, ... which the
// library itself knows), command parameters (internal: xpos, radius, ...) and PRP externals.
struct HostVariable {
  std::string name;
  Type type = Type::Numeric;
  bool read_only = false;
  std::vector<int> dimensions;  // empty for scalars; 1-based sizes for host arrays (chng_cond<<3,n>>)
};

struct SymbolIndex;  // gppl/symbols.hpp

struct CompileOptions {
  std::vector<HostVariable> host_variables;
  // Real posts read command parameters the host may not list. When true, an identifier that is
  // declared nowhere becomes a host variable whose type is fixed by its first assignment from the
  // host (a warning, not error 383). `postproc check` compiles with this false.
  bool implicit_host_variables = true;
  // With implicit_host_variables, for a host that runs a job (postproc run): such a name has a
  // value only once the host assigns it (the job carries it). Any use before that, by the post,
  // is error 383 (read) or 404 (assignment) at the name: the diagnostic `check` gives. No warning.
  bool undeclared_from_job = false;
  // Where `include`/`inc` files are looked up besides the including file's folder.
  std::vector<std::string> include_paths;
  // `postproc check`: an assignment of a constant is checked at its own line, as a run would check
  // it when the line runs: a display format into a format variable (`xpos_f = '5.3p'`: error 423,
  // with the spelling meant), a number into a text variable (394), text into a number (386).
  bool check_constant_assignments = false;
  // A call of a small procedure that only assigns and tests (no parameters, locals, generate
  // statements or calls) runs its body copied in place, without a call; a run with a trace still
  // shows it as a call. Off: every call is a call (the tests compare both).
  bool inline_leaf_calls = true;
  // An editor's index of the post's names (gppl/symbols.hpp), filled by the compile, also by one
  // that fails. Null: none is kept.
  SymbolIndex* symbols = nullptr;
};

class Program;  // parsed, resolved, immutable; shareable between interpreters

std::shared_ptr<const Program> compile_file(const std::string& path, const CompileOptions& options);
std::shared_ptr<const Program> compile_source(std::string_view text, const std::string& file_name,
                                              const CompileOptions& options);

// True when the post uses start_line/end_line (the sink's structure hooks are then called).
bool uses_line_functions(const Program& program);

// Warnings found while compiling (implicit host variables, ...), "file:line:col: warning: text".
const std::vector<std::string>& warnings(const Program& program);
// The same warnings with their positions (number 0), for a host that reports them in its own shape.
const std::vector<Error>& warning_details(const Program& program);

// The procedures a post defines, in the order written, and whether a `call` statement names them.
struct ProcedureInfo {
  std::string_view name;  // "@rapid_move", as written
  Position position;      // of the name in its header
  bool called = false;
};
std::vector<ProcedureInfo> procedures(const Program& program);

// Of `candidates`, the one nearest to `name` (case-insensitive edit distance), for a "did you mean"
// hint: empty when none is within 2 edits, or within a third of the name's length for short names.
std::string_view nearest_name(std::string_view name, std::span<const std::string_view> candidates);

// Where finished NC lines go. `origin` tells which procedure and source line started the line
// (for `postproc explain` and for naming the procedure in regression diffs).
struct LineOrigin {
  std::string_view procedure;  // "@line"
  int source_line = 0;
  std::string_view source_file;  // the file of source_line: the post as compiled, or an include file
  // The line was started by `nl` or `nb`, which write the line break before the line (the first
  // line of the output has none when text came before any nl/nb). SolidCAM files therefore begin
  // with an empty line and end without a final break (docs/engine.md, "Line breaks").
  bool after_break = true;
};

using ProcedureId = std::uint32_t;

// `start_line` and `end_line`: host item functions, allowed only as items of a generate statement
// (gpptool-commands.md 2.8, 2.11). They print the first and last block numbers of the body the
// running command belongs to (a subroutine, a loop, a turning geometry), which the host knows.
enum class LineFunction : std::uint8_t { StartLine, EndLine };
std::string_view name_of(LineFunction f);  // "start_line"

class OutputSink {
public:
  virtual ~OutputSink() = default;
  // One finished line, without the line terminator. Output directives (`!!open file=X!!`) arrive
  // here too, as plain lines: executing them is the host's job.
  virtual void write_line(std::string_view line, const LineOrigin& origin) = 0;

  // The three hooks below are called only for programs that use start_line/end_line.
  // A numbered block starts: `nb` wrote block number `number`.
  virtual void block_numbered(std::int64_t number) { (void)number; }
  // A procedure starts (`entering`) or ends, whether the host called it or a `call` statement did.
  virtual void procedure_boundary(ProcedureId procedure, bool entering) { (void)procedure, (void)entering; }
  // Appends the text of `start_line`/`end_line` to `out`, formatted with the display format `format`
  // (the item's, else integer_def_f; see format_integer). The host may append a placeholder it
  // replaces once the number is known. Throws std::runtime_error when the function has no meaning
  // here (the interpreter reports it at the item with error 404). The default supplies neither.
  // `item` is where the item stands in the post, for the host's messages.
  virtual void line_function(LineFunction which, std::string_view format, const Position& item, std::string& out);
};

// The text of an integer under a display format ("5.0(p)"), exactly as a generate item prints it.
// Throws Error (without a position) when the format is invalid.
std::string format_integer(std::int64_t value, std::string_view format);

// An answer for the `input` statements that read variable `name` (runs are not interactive).
// `value` is text, converted to that variable's type; `source` says where it came from, for
// messages ("--answer tool=3", "answers.txt:4").
struct Answer {
  std::string name;
  std::string value;
  std::string source;
};

// Checks answers against the post's `input` statements. Throws Errors (at the input statement,
// naming the answer's source) when a value does not convert to the variable's type: 386 for a
// number, 420 for a logical, 410 for an integer beyond the range. Returns one warning per answer
// that no `input` statement reads. A name answered twice takes the last answer.
std::vector<std::string> check_answers(const Program& program, std::span<const Answer> answers);

enum class ChangeOverride : std::uint8_t { Compute, ForceChanged, ForceUnchanged };

// How a procedure run ended. `exit` ends the current P-code; `abort` ends the whole run.
enum class RunResult : std::uint8_t { Normal, Exit, Abort };

using VariableId = std::uint32_t;

class Interpreter {
public:
  Interpreter(std::shared_ptr<const Program> program, OutputSink& sink);
  ~Interpreter();
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  // Name -> slot, resolved once by the host and cached; nullopt when the post never names it.
  std::optional<VariableId> find_variable(std::string_view name) const;
  std::optional<ProcedureId> find_procedure(std::string_view name) const;  // "@line"
  // find_variable, or else a new variable the post never names: the host may still assign it
  // (command parameters), and it appears in trace dumps and value(). Same name, same id.
  VariableId add_variable(std::string_view name);

  // Host assignment: converts to the variable's type, sets `change` (or forces it) and active=TRUE.
  // Throws Error on an impossible conversion.
  void assign(VariableId id, const Value& value, ChangeOverride change = ChangeOverride::Compute);
  // assign() with a Value of that type, without building one: the engine's path for every
  // parameter of every command (a number into a variable of its type costs a few instructions).
  void assign_integer(VariableId id, std::int64_t value, ChangeOverride change = ChangeOverride::Compute);
  void assign_numeric(VariableId id, double value, ChangeOverride change = ChangeOverride::Compute);
  void assign_logical(VariableId id, bool value, ChangeOverride change = ChangeOverride::Compute);
  void assign_string(VariableId id, std::string_view value, ChangeOverride change = ChangeOverride::Compute);
  // A host variable's cell, found once: assign_integer/assign_numeric through it skip the id's
  // check and lookup (the engine's plan of a command name keeps one per parameter). Only
  // host_slot() makes one, and a cell never moves, so it stays valid for the interpreter's life.
  class HostSlot {
  public:
    VariableId id() const { return id_; }

  private:
    friend class Interpreter;
    VariableId id_ = 0;
    std::uint32_t cell_ = 0;
  };
  HostSlot host_slot(VariableId id) const;  // throws std::out_of_range for an id of no variable
  void assign_integer(HostSlot slot, std::int64_t value, ChangeOverride change = ChangeOverride::Compute);
  void assign_numeric(HostSlot slot, double value, ChangeOverride change = ChangeOverride::Compute);
  // assign_string() of texts[i] to ids[i] in one call (prev_command, current_command, next_command).
  void assign_strings(std::span<const VariableId> ids, std::span<const std::string_view> texts);
  // Host assignment to one element of a host array (chng_cond<<3,n>>); indices are 1-based.
  void assign_element(VariableId id, std::span<const int> indices, const Value& value,
                      ChangeOverride change = ChangeOverride::Compute);
  void set_active(VariableId id, bool active);
  void set_changed(VariableId id, bool changed);
  // Forgets every assignment so far: the next assignment of any non-local variable counts as a
  // first one (change TRUE even when the value repeats). The engine calls it where a subroutine
  // body starts, so that modal output starts afresh there (docs/engine.md, "modal memory").
  void reset_change_memory();
  const Value& value(VariableId id) const;
  bool active(VariableId id) const;
  bool changed(VariableId id) const;
  // The type of a variable the post never reads, when that type is fixed: no statement, condition,
  // generate item or display format of the program names it, and the generator does not use it
  // (block numbering, default formats). Assigning it a value of exactly that type can neither fail
  // nor change anything the post writes, so a host may leave it out. nullopt when the post may
  // read it, when a host value can re-type it, or while a trace stream records host assignments.
  std::optional<Type> unread_type(VariableId id) const;

  // Runs @init_post, then every @init_inc, once.
  RunResult start();
  // Runs one procedure (one P-code). Runtime errors throw Error with the statement's position.
  RunResult call(ProcedureId id);
  // Flushes the open output line (end of run).
  void finish();

  // Trace output (`trace "list":level` statements) goes here; nullptr (default) discards it.
  void set_trace_stream(std::ostream* trace);
  // Traces every procedure at `level` (0..5), as `trace "all":level` does; later trace statements
  // of the post still apply.
  void trace_all(int level);
  // The run log: `print` messages and one line per `input` statement (prompt, variable, value
  // and where the value came from). nullptr (default) discards them.
  void set_log_stream(std::ostream* log);
  // Whether `input` statements log their answer there (print statements always do).
  void log_inputs(bool on);
  // Answers for the `input` statements (see check_answers, whose errors it throws).
  void set_answers(std::span<const Answer> answers);
  // A toolpath command the post has no procedure for: traced at nesting level 0 (spec 8.2).
  void trace_unhandled(std::string_view command);
  // Limits that stop a runaway post: loop iterations per P-code and call depth (error 405).
  void set_limits(std::uint64_t max_loop_iterations, int max_call_depth);

private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace gppl
