#include "postproc/engine/engine.hpp"

#include <fmt/format.h>
#ifdef __linux__
#include <sched.h>
#endif

#include <algorithm>
#include <array>
#include <cstring>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unordered_map>
#include <utility>

#include "gppl/gppl.hpp"
#include "gppl/compile/system_variables.hpp"
#include "postproc/engine/directive.hpp"
#include "postproc/engine/engine_sink.hpp"
#include "postproc/engine/command_names.hpp"
#include "postproc/engine/cycle_retreat.hpp"
#include "postproc/engine/enumerations.hpp"
#include "postproc/engine/host_variables.hpp"
#include "postproc/engine/line_numbers.hpp"
#include "postproc/engine/parameter_check.hpp"
#include "postproc/engine/parameter_binding.hpp"
#include "postproc/engine/structure.hpp"
#include "toolpath/prefetch.hpp"
#include "toolpath/short_text.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/value.hpp"

namespace postproc {
namespace {

using toolpath::iequals;

// The unit system a job states in its @start_of_file (`inch_system`); metric when it does not.
struct NoCommands final : toolpath::CommandSource {
  bool next(toolpath::Command&) override { return false; }
};

// `first`, taken to learn the job's units, then the rest of `inner`.
class StartsWith final : public toolpath::CommandSource {
public:
  StartsWith(toolpath::CommandSource& inner, toolpath::Command&& first) : inner_(inner), first_(std::move(first)) {}
  bool next(toolpath::Command& out) override {
    if (!has_first_) return inner_.next(out);
    swap(out, first_);
    has_first_ = false;
    return true;
  }

private:
  toolpath::CommandSource& inner_;
  toolpath::Command first_;
  bool has_first_ = true;
};

// The CPUs this process may run on.
unsigned usable_cpus() {
#ifdef __linux__
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return static_cast<unsigned>(CPU_COUNT(&set));
#endif
  return std::thread::hardware_concurrency();
}

// Reading on a thread of its own pays where a third CPU can run it. On two, the post and the
// filters wait for it in turn and every command crosses between the CPUs once more: measured
// slower (docs/performance.md, "Where the engine stands").
bool reader_on_own_thread(RunOptions::ReaderThread choice) {
  if (choice != RunOptions::ReaderThread::Auto) return choice == RunOptions::ReaderThread::Own;
  static const bool three_or_more = usable_cpus() >= 3;
  return three_or_more;
}

prp::Units job_units(const toolpath::Command* first) {
  if (!first || !iequals(first->name, "@start_of_file")) return prp::Units::Metric;
  const toolpath::Value* inch = first->find("inch_system");
  if (!inch) return prp::Units::Metric;
  bool is_inch = inch->kind == toolpath::ValueKind::Logical ? inch->logical : inch->as_number() != 0;
  return is_inch ? prp::Units::Inch : prp::Units::Metric;
}

struct TransparentHash {
  using is_transparent = void;
  std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
};

std::string default_main_name(const std::string& g_file_name, const std::string& extension) {
  std::string name = g_file_name;
  bool has_extension = std::filesystem::path(name).has_extension();
  if (!has_extension && !extension.empty()) name += "." + extension;
  return name;
}

// Warnings about the stream, from the reading thread and the filters' thread: one lock keeps the
// lines whole, and a damaged job says the first hundred things, not a million.
// With `held`, they wait for release() (a run that may start again must not say them twice).
class StreamWarnings {
public:
  StreamWarnings(std::ostream* out, std::string input, bool held)
      : out_(out), input_(std::move(input)), held_(held) {}
  ~StreamWarnings() {
    if (out_ && !held_ && shown_ > kShown) *out_ << fmt::format("{}: {} more warnings not shown\n", input_, shown_ - kShown);
  }

  void operator()(std::uint32_t line, const std::string& message) {
    if (!out_) return;
    std::lock_guard lock(mutex_);
    if (++shown_ > kShown) return;
    std::string text = line ? fmt::format("{}:{}:1: warning: {}\n", input_, line, message)
                            : fmt::format("{}: warning: {}\n", input_, message);
    if (held_) waiting_ += text;
    else *out_ << text;
  }

  void release() {
    if (!out_ || !held_) return;
    std::lock_guard lock(mutex_);
    *out_ << waiting_;
    waiting_.clear();
    held_ = false;
  }

private:
  static constexpr std::size_t kShown = 100;  // also bounds what waits
  std::ostream* out_;
  std::string input_;
  bool held_;
  std::string waiting_;
  std::mutex mutex_;
  std::size_t shown_ = 0;
};

// The system variables the engine reads back from the post's cells: they are assigned from a
// command even when the post itself never reads them (ParameterBinding leaves those out).
// label: LineNumbers::label(); xpos/ypos/zpos: follow_cycle_retreat(); num_user_procs:
// subroutine numbering; print_file_size: the end of the run.
constexpr std::array<std::string_view, 6> kReadByEngine{"label", "xpos", "ypos", "zpos", "num_user_procs",
                                                        "print_file_size"};

class Session {
public:
  Session(const Engine& engine, std::shared_ptr<const gppl::Program> program, OutputFiles& files,
          const RunOptions& options)
      : engine_(engine),
        options_(options),
        files_(files),
        enums_(engine.drill_cycle_names()),
        sink_(files, options.observer, engine.options().post),
        uses_line_functions_(gppl::uses_line_functions(*program)),
        procedures_(gppl::procedures(*program)),
        interpreter_(std::move(program), sink_),
        binding_(interpreter_, enums_, {kReadByEngine.begin(), kReadByEngine.end()}),
        line_numbers_(interpreter_, files, options.observer, [this] {
          return sink_.command_name.empty() ? std::string()
                                            : fmt::format("command #{} {}", sink_.command_index, sink_.command_name);
        }) {
    sink_.line_numbers = &line_numbers_;
    binding_.set_input_name(options.input_name);
    interpreter_.set_trace_stream(options.trace);
    interpreter_.set_log_stream(engine.options().log);
    interpreter_.log_inputs(engine.options().log_inputs);
    if (!engine.options().answers.empty()) interpreter_.set_answers(engine.options().answers);
    interpreter_.set_limits(engine.options().max_loop_iterations, engine.options().max_call_depth);
    for (const auto& c : enums_.constants())
      if (auto id = interpreter_.find_variable(c.name)) interpreter_.assign(*id, gppl::Value::of_integer(c.code));
    // Integer constants of the system table are words a trace sends (tool types: `tool_type:face_mill`):
    // each holds the code that word gets, so `tool_type eq face_mill` compares codes.
    for (const auto& v : gppl::system_variables())
      if (v.source == gppl::VariableSource::Constant && v.type == gppl::Type::Integer)
        if (auto id = interpreter_.find_variable(v.name)) interpreter_.assign(*id, gppl::Value::of_integer(enums_.code(v.name)));
    // A name the post never reads is not assigned (three string copies a command otherwise).
    auto read_name = [&](std::string_view name) -> std::optional<gppl::VariableId> {
      auto id = interpreter_.find_variable(name);
      if (id && interpreter_.unread_type(*id) == gppl::Type::String) return std::nullopt;
      return id;
    };
    prev_command_ = read_name("prev_command");
    current_command_ = read_name("current_command");
    next_command_ = read_name("next_command");
    if (prev_command_ && current_command_ && next_command_)
      command_names_ = std::array<gppl::VariableId, 3>{*prev_command_, *current_command_, *next_command_};
    for (const auto* cycle : engine.machine().records("drill_type"))
      for (const auto& p : cycle->params) drill_parameters_.push_back(p);
    fill_run_values();
    // PRP external variables start with their declared value, or inactive until a command sets them.
    // Cycle parameters are inactive whatever their value (a VMID gives them the dialog's default).
    for (const auto& v : engine.machine().external_variables()) {
      auto id = interpreter_.find_variable(v.name);
      if (!id) continue;
      if (v.initial) interpreter_.assign(*id, binding_.convert(*v.initial, v.type == prp::VarType::String));
      if (!v.initial || v.declared_by == "drill_type") interpreter_.set_active(*id, false);
    }
  }

  // With `two_passes`, procedure generation may take a forecast of the job (prp::forecast_jobs),
  // and prp::ForecastMismatch may come out: the caller then runs again without.
  RunSummary run(toolpath::CommandSource& input, bool two_passes) {
    RunSummary summary;
    sink_.command_name = "@init_post";
    guarded([&] { interpreter_.start(); });
    if (options_.trace_level >= 0) interpreter_.trace_all(options_.trace_level);  // after @init_post's own
    // Three stages overlap: reading the job, the PRP's filters, the post. Reading gets a thread of
    // its own because a filter may have to take in the whole job before it hands anything on
    // (gen_procs: @start_of_file names the last subroutine label).
    StreamWarnings warnings(options_.warnings, options_.input_name, two_passes);
    try {
      run_stream(input, summary, warnings, two_passes);
    } catch (const prp::ForecastMismatch&) {
      throw;  // not said: the run starts again
    } catch (...) {
      warnings.release();
      throw;
    }
    warnings.release();
    return summary;
  }

private:
  void run_stream(toolpath::CommandSource& input, RunSummary& summary, StreamWarnings& warnings, bool two_passes) {
    // Wrong values stop at their own position; a command without what it needs at its header.
    // Only the stream is posted: the original post's own deeper calls are left out here.
    ParameterCheck checked(input, options_.input_name,
                           [&](const toolpath::SourcePosition& at, const std::string& m) { warnings(static_cast<std::uint32_t>(at.line), m); },
                           ParameterCheck::Deeper::Leave);
    // The PRP half follows the job's unit system, which the first command states; it must be
    // chosen before the filters compare anything against the PRP's tolerances.
    toolpath::Command first;
    first.keep_name_on_heap();
    const bool any = checked.next(first);
    summary.units = engine_.options().units.value_or(job_units(any ? &first : nullptr));
    machine_ = &engine_.machine(summary.units);
    retreat_.emplace(*machine_);
    refuse_procedures_without_calls();
    std::shared_ptr<prp::JobForecast> forecast = two_passes ? forecast_jobs() : nullptr;
    NoCommands ended;  // an empty job: the reader is not asked again
    // Reading and checking run on the filters' thread, or on one of their own before them.
    std::optional<toolpath::PrefetchSource> read_ahead;
    std::optional<StartsWith> read_inline;
    toolpath::CommandSource* read = &ended;
    if (any && reader_on_own_thread(options_.reader_thread)) read = &read_ahead.emplace(checked, std::move(first));
    else if (any) read = &read_inline.emplace(checked, std::move(first));
    auto filtered = prp::build_filter_chain(
        *machine_, *read,
        [&](const toolpath::Command& c, const std::string& m) {
          warnings(c.line, fmt::format("command #{} {}: {}", c.index, c.name, m));
        },
        std::move(forecast));
    toolpath::PrefetchSource prefetched(*filtered);
    // The one before (its name is prev_command), the current one and the one after it
    // (next_command, read before the current one runs) stay where the prefetch put them: no
    // command is moved, no name copied.
    static_assert(toolpath::PrefetchSource::kept >= 2);
    toolpath::Command* previous = nullptr;
    for (toolpath::Command* current = prefetched.next_in_place(); current;) {
      ++summary.commands;
      sink_.begin_command(current->index, current->name, current->line);
      toolpath::Command* following = prefetched.next_in_place();
      guarded([&] {
        execute(*current, previous ? std::string_view(previous->name) : std::string_view{},
                following ? std::string_view(following->name) : std::string_view{}, summary);
      });
      previous = std::exchange(current, following);
      if (options_.progress && (summary.commands & 4095) == 0) options_.progress(summary.commands);
    }
    sink_.end_commands();
    warn_unhandled(warnings);
    guarded([&] { interpreter_.finish(); });
    if (uses_line_functions_) guarded([&] { line_numbers_.finish(); });
    auto print_file_size = interpreter_.find_variable("print_file_size");
    guarded([&] { files_.finish_placeholders(print_file_size && interpreter_.value(*print_file_size).integer == 1); });
    if (files_.main_path().empty()) name_main_file(default_main_name(input_stem(), engine_.file_extension()));
    summary.lines = sink_.lines;
  }

  // The first pass of procedure generation in two passes, over a skim of the input reopened, when
  // the PRP allows it and nothing watches the run line by line (a second run would show it twice).
  std::shared_ptr<prp::JobForecast> forecast_jobs() const {
    if (!options_.reopen || options_.observer || options_.posted || options_.trace || options_.trace_level >= 0 ||
        !prp::two_passes_possible(*machine_))
      return nullptr;
    std::unique_ptr<toolpath::CommandSource> source;
    try {
      source = options_.reopen();
    } catch (const std::exception&) {
      return nullptr;  // gone since it was opened: one pass, on what was opened
    }
    auto* reader = dynamic_cast<toolpath::TraceReader*>(source.get());
    if (!reader) return nullptr;  // only a trace file can be skimmed
    reader->skim_job_motions();
    // Checked as the full pass checks, so that the post never runs a value the check would refuse
    // (the main program goes to it before the full pass reads that far). A check that fails here,
    // as the skim left out what an earlier command gave, means one pass.
    ParameterCheck checked(*reader, options_.input_name, {}, ParameterCheck::Deeper::Leave);
    return prp::forecast_jobs(*machine_, checked);
  }

  // What the engine needs to know about a command name, looked up once per name.
  struct CommandInfo {
    std::optional<gppl::ProcedureId> procedure;
    ParameterBinding::Plan parameters;  // what each parameter does, by position
    // What execute() does besides assigning, decided once per name instead of by name tests.
    bool start_of_file = false;
    bool starts_body = false;
    bool calls_subroutine = false;
    bool drill = false;
    bool structural = false;  // ProgramStructure::before() has something to do
    bool motion = false;      // @rapid_move, @line, @arc: without a procedure the moves are lost
    bool lathe_cycle = false; // @turning, @turn_endproc: a cycle may leave the tool elsewhere
    // Commands of this name the post had no procedure for, the first one's line, and whether any
    // came at a depth other than 0 (a trace's depth 0: SolidCAM's own post had none either).
    std::size_t unhandled = 0;
    std::uint32_t first_unhandled_line = 0;
    bool unhandled_expected_handled = false;
  };

  template <class F>
  void guarded(F&& f) {
    try {
      f();
    } catch (const gppl::Error& e) {
      fail(e.what());
    } catch (const DirectiveError& e) {
      fail(e.what());
    } catch (const toolpath::InputError&) {
      throw;  // the stream itself is malformed: its own position says it all
    } catch (const RunError&) {
      throw;
    } catch (const std::runtime_error& e) {
      fail(e.what());
    }
  }

  // The command being run, as `command #N @name`, after the input position of its header when
  // it has one: `job.trace:58:1: command #13 @arc`.
  std::string command_here() const {
    std::string command = fmt::format("command #{} {}", sink_.command_index, sink_.command_name);
    return sink_.command_line ? fmt::format("{}:{}:1: {}", options_.input_name, sink_.command_line, command)
                              : command;
  }

  [[noreturn]] void fail(const std::string& what) const {
    if (sink_.command_name.empty()) throw RunError(fmt::format("{}: at the end of the run: {}", options_.input_name, what));
    if (sink_.command_line) throw RunError(fmt::format("{}: {}", command_here(), what));
    throw RunError(fmt::format("{}: {}: {}", options_.input_name, command_here(), what));
  }

  std::string input_stem() const {
    std::string stem = std::filesystem::path(options_.input_name).stem().string();
    return stem.empty() ? "output" : stem;
  }

  void name_main_file(const std::string& default_name) {
    files_.set_main_path(options_.main_path ? options_.main_path(default_name) : std::filesystem::path(default_name));
  }

  // The command names seen last come first (a job alternates a few names: @line, @arc, ...).
  CommandInfo& info(std::string_view name) {
    for (auto& [seen, found] : recent_)
      if (found && toolpath::same_short_text(seen, name)) return *found;
    auto it = commands_.find(name);
    if (it == commands_.end()) {
      toolpath::Command probe;
      probe.name = std::string(name);
      CommandInfo made{interpreter_.find_procedure(name), {}};
      made.start_of_file = iequals(name, "@start_of_file");
      made.starts_body = ProgramStructure::starts_body(probe);
      made.calls_subroutine = ProgramStructure::calls_subroutine(probe);
      made.drill = iequals(name, "@drill");
      made.structural = ProgramStructure::concerns(probe);
      made.motion = is_basic_motion(name);
      made.lathe_cycle = iequals(name, "@turning") || iequals(name, "@turn_endproc");
      it = commands_.emplace(std::string(name), std::move(made)).first;
    }
    std::move_backward(recent_.begin(), recent_.end() - 1, recent_.end());
    recent_.front() = {it->first, &it->second};
    return it->second;
  }

  void set_string(const std::optional<gppl::VariableId>& id, std::string_view text) {
    if (id) interpreter_.assign_string(*id, text);
  }

  // Optional parameters a command did not supply are inactive (gppl-language.md 1.2).
  void deactivate_missing(const toolpath::Command& command, const CommandInfo& info) {
    auto deactivate = [&](std::string_view name) {
      if (command.find(name)) return;
      if (const ParameterBinding::Slot& s = binding_.slot(name); s.id) interpreter_.set_active(*s.id, false);
    };
    if (info.calls_subroutine) {
      for (std::string_view name : {"message", "parm1", "parm2", "parm3"}) deactivate(name);
    } else if (info.drill) {
      for (const auto& name : drill_parameters_) deactivate(name);
    }
  }

  void execute(toolpath::Command& command, std::string_view previous, std::string_view next, RunSummary& summary) {
    CommandInfo& command_info = info(command.name);
    if (command_info.structural) structure_.before(command);
    if (command_info.start_of_file) start_of_file(command);
    if (options_.posted) options_.posted(command);
    bool reset = engine_.options().reset_modal_memory_at_subroutines;
    if (reset && command_info.starts_body) interpreter_.reset_change_memory();

    binding_.assign_all(command, command_info.parameters);
    deactivate_missing(command, command_info);
    if (command_names_) {
      const std::array<std::string_view, 3> names{previous, command.name, next};
      interpreter_.assign_strings(*command_names_, names);
    } else {
      set_string(prev_command_, previous);
      set_string(current_command_, command.name);
      set_string(next_command_, next);
    }

    if (!command_info.procedure) {
      if (command_info.motion) fail(missing_motion(command.name));
      if (command_info.unhandled++ == 0) command_info.first_unhandled_line = command.line;
      if (command.depth != 0 && !is_informational(command.name)) command_info.unhandled_expected_handled = true;
      ++summary.skipped;
      if (uses_line_functions_) line_numbers_.command_without_procedure(command.name);
      interpreter_.trace_unhandled(command.name);
    } else if (interpreter_.call(*command_info.procedure) == gppl::RunResult::Abort) {
      throw std::runtime_error("the post stopped the run (`abort` in " + command.name + ")");
    }
    if (reset && command_info.calls_subroutine) interpreter_.reset_change_memory();
    if (command_info.lathe_cycle) follow_cycle_retreat(command, next);
  }

  // The tool is where the cycle left it: the post's position holds that point, unchanged, so the
  // next move writes the axes that really move (docs/engine.md, "Turning cycles").
  void follow_cycle_retreat(const toolpath::Command& command, std::string_view next) {
    std::array<std::optional<gppl::VariableId>, 3> axes{binding_.slot("xpos").id, binding_.slot("ypos").id,
                                                        binding_.slot("zpos").id};
    auto read = [&](const std::optional<gppl::VariableId>& id) {
      if (!id) return 0.0;
      const gppl::Value& v = interpreter_.value(*id);
      return v.type == gppl::Type::Integer ? static_cast<double>(v.integer) : v.numeric;
    };
    const CycleRetreat::Point where{read(axes[0]), read(axes[1]), read(axes[2])};
    const std::optional<CycleRetreat::Point> end = retreat_->after(command, next, where);
    if (!end) return;
    const std::array<double, 3> values{end->x, end->y, end->z};
    for (std::size_t i = 0; i < 3; ++i)
      if (axes[i]) interpreter_.assign_numeric(*axes[i], values[i], gppl::ChangeOverride::ForceUnchanged);
  }

  // gen_procs = Y (or C) makes the jobs subroutines: @proc .. @end_proc bodies after the main program,
  // @call_proc where they were. A post with neither procedure would write every job's moves after
  // the program's end (M30): stop before anything is written.
  void refuse_procedures_without_calls() const {
    const std::string& g = machine_->text("gen_procs");
    if (!iequals(g, "Y") && !iequals(g, "C")) return;
    if (interpreter_.find_procedure("@proc") || interpreter_.find_procedure("@call_proc")) return;
    throw RunError(fmt::format(
        "{}: the PRP says gen_procs = {}: the jobs become subroutines (@proc .. @end_proc after the main "
        "program, @call_proc where they were), but the post has neither @proc nor @call_proc, so every job's "
        "moves would come after the end of the program; give the post those procedures, or set gen_procs = N",
        engine_.options().prp.empty() ? options_.input_name : engine_.options().prp, g));
  }

  // The post's procedures that neither a job sends nor a `call` names: a misspelled command name
  // (`@rapid_mvoe`) is among them. A hint naming the one nearest to `name`, or empty.
  std::string misspelling_hint(std::string_view name) const {
    std::vector<std::string_view> unused;
    for (const auto& p : procedures_)
      if (!p.called && !is_stream_command_name(p.name)) unused.push_back(p.name);
    const std::string_view guess = gppl::nearest_name(name, unused);
    return guess.empty() ? std::string()
                         : fmt::format(" (the post defines {}, which no command has and nothing calls: a misspelling?)", guess);
  }

  std::string missing_motion(std::string_view name) const {
    return fmt::format("the post has no {} procedure, so these moves would be missing from the NC program{}", name,
                       misspelling_hint(name));
  }

  // After the run: one warning for each command name the post had no procedure for, unless the
  // trace says SolidCAM's post had none either (depth 0) or the command only informs (@def_tool).
  void warn_unhandled(StreamWarnings& warnings) const {
    std::vector<std::pair<const std::string*, const CommandInfo*>> kinds;
    for (const auto& [name, info] : commands_)
      if (info.unhandled > 0 && info.unhandled_expected_handled) kinds.emplace_back(&name, &info);
    std::sort(kinds.begin(), kinds.end(),
              [](const auto& a, const auto& b) { return a.second->first_unhandled_line < b.second->first_unhandled_line; });
    for (const auto& [name, info] : kinds) {
      const std::string what = info->unhandled == 1 ? std::string("this command was")
                                                    : fmt::format("its {} commands were", info->unhandled);
      warnings(info->first_unhandled_line, fmt::format("{}: the post has no procedure for it, so {} not posted{}", *name,
                                                       what, misspelling_hint(*name)));
    }
  }

  // System variables the run knows before the job says anything (docs/system-variables.md, source
  // "run"); a command of the job that carries one assigns it again, so the trace wins.
  // The paths are written with backslashes, as SolidCAM gives them: posts take the name out of a
  // path by looking for the last `\\` (the Siemens 828D post: `right(part_model_name,
  // instr(rev(part_model_name), '\\') - 1)`, error 387 for a path without one).
  void fill_run_values() {
    const std::filesystem::path job(options_.input_name);
    auto windows = [](std::string path) {
      std::replace(path.begin(), path.end(), '/', '\\');
      return path;
    };
    set_string(interpreter_.find_variable("part_name"), input_stem());
    set_string(interpreter_.find_variable("part_full_name"), windows((job.parent_path() / job.stem()).string()));
    set_string(interpreter_.find_variable("part_model_name"), windows(job.string()));
    set_string(interpreter_.find_variable("path_part"), windows(job.parent_path().string()));
    set_string(interpreter_.find_variable("pre_processor"), std::filesystem::path(engine_.options().post).stem().string());
  }

  // Names the main file, and completes the subroutine numbers the stream left out.
  void start_of_file(toolpath::Command& command) {
    const toolpath::Value* name = command.find("g_file_name");
    std::string base = name && !name->text.empty() ? name->text : input_stem();
    name_main_file(default_main_name(base, engine_.file_extension()));
    // The trace's own full_g_file_name, when it has one, is assigned after this and wins.
    if (!options_.main_path) return;
    std::error_code ignored;
    const auto full = std::filesystem::absolute(files_.main_path(), ignored);
    set_string(interpreter_.find_variable("full_g_file_name"), full.string());
    if (!command.find("first_user_proc") && options_.reopen) derive_procedure_numbers(command);
  }

  // first_user_proc is the label after the last subroutine of the stream; the post's
  // num_user_procs (set in @init_post) user subroutines follow it (gpptool-commands.md 2.8).
  void derive_procedure_numbers(toolpath::Command& command) {
    std::int64_t low = 0, high = 0;
    auto source = options_.reopen();
    toolpath::Command c;
    while (source->next(c)) {
      if (!c.is_stream_command() || !(ProgramStructure::starts_body(c) || ProgramStructure::calls_subroutine(c))) continue;
      const toolpath::Value* label = c.find("label");
      if (!label) continue;
      auto l = static_cast<std::int64_t>(label->kind == toolpath::ValueKind::Integer ? label->integer : label->as_number());
      low = low == 0 ? l : std::min(low, l);
      high = std::max(high, l);
    }
    std::int64_t first_label = prp::procedure_numbers(*machine_).dflt.value_or(1);
    std::int64_t user_procs = 0;
    if (auto id = interpreter_.find_variable("num_user_procs")) user_procs = interpreter_.value(*id).integer;
    std::int64_t first_user = high > 0 ? high + 1 : first_label;
    command.set("first_user_proc", toolpath::Value::make_integer(first_user));
    if (!command.find("first_proc_number"))
      command.set("first_proc_number", toolpath::Value::make_integer(low > 0 ? low : first_user));
    if (!command.find("last_proc_number"))
      command.set("last_proc_number", toolpath::Value::make_integer(user_procs > 0 ? first_user + user_procs - 1 : high));
  }

  const Engine& engine_;
  const prp::MachineParameters* machine_ = nullptr;  // the half of the PRP this run uses
  const RunOptions& options_;
  OutputFiles& files_;
  Enumerations enums_;
  EngineSink sink_;
  bool uses_line_functions_;
  std::vector<gppl::ProcedureInfo> procedures_;  // the post's, for "a misspelling?" hints
  gppl::Interpreter interpreter_;
  ParameterBinding binding_;
  LineNumbers line_numbers_;
  ProgramStructure structure_;
  std::optional<CycleRetreat> retreat_;  // made with the PRP half of the run
  std::optional<gppl::VariableId> prev_command_, current_command_, next_command_;
  std::optional<std::array<gppl::VariableId, 3>> command_names_;  // all three: assigned in one call
  std::vector<std::string> drill_parameters_;
  std::unordered_map<std::string, CommandInfo, TransparentHash, std::equal_to<>> commands_;
  std::array<std::pair<std::string_view, CommandInfo*>, 4> recent_{};  // names point into commands_
};

}  // namespace

Engine::Engine(EngineOptions options) : options_(std::move(options)) {
  auto load = [&](prp::Units units) { return options_.prp.empty() ? prp::defaults(units) : prp::load_file(options_.prp, units); };
  prp_metric_ = load(prp::Units::Metric);
  prp_inch_ = load(prp::Units::Inch);
  Enumerations enums(drill_cycle_names());
  gppl::CompileOptions compile;
  compile.host_variables = host_variables(enums, machine());
  compile.include_paths = options_.include_paths;
  compile.undeclared_from_job = true;  // a name nothing declares is the job's, or an error where used
  program_ = gppl::compile_file(options_.post, compile);
  for (const std::string& warning : gppl::check_answers(*program_, options_.answers))
    if (options_.log) *options_.log << warning << '\n';
}

Engine::~Engine() = default;

const prp::MachineParameters& Engine::machine(prp::Units units) const {
  return units == prp::Units::Inch ? prp_inch_ : prp_metric_;
}

std::string Engine::file_extension() const {
  const prp::Parameter* p = machine().find("gpp_file_ext");
  return p ? p->text : std::string();
}

std::vector<std::string> Engine::drill_cycle_names() const {
  std::vector<std::string> names;
  for (const auto* r : machine().records("drill_type")) names.push_back(r->name);
  return names;
}

RunSummary Engine::run(toolpath::CommandSource& input, OutputFiles& output, const RunOptions& options) const {
  try {
    try {
      Session session(*this, program_, output, options);
      return session.run(input, true);
    } catch (const prp::ForecastMismatch&) {
      // The job is not what its skim forecast (docs/prp.md): everything again, in one pass.
      output.discard();
      std::unique_ptr<toolpath::CommandSource> again = options.reopen();
      Session session(*this, program_, output, options);
      return session.run(*again, false);
    }
  } catch (const prp::StreamError& e) {
    // A command the PRP's filters cannot take: point at its header in the input.
    const std::string what = fmt::format("command #{} {}: {}", e.command_index(), e.command_name(), e.message());
    if (e.line()) throw toolpath::InputError({options.input_name, e.line(), 1}, what);
    throw RunError(fmt::format("{}: {}", options.input_name, what));
  }
}

}  // namespace postproc
