#include "postproc/engine.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "gppl/gppl.hpp"
#include "postproc/directive.hpp"
#include "postproc/enumerations.hpp"
#include "postproc/host_variables.hpp"
#include "postproc/line_numbers.hpp"
#include "postproc/parameter_table.hpp"
#include "postproc/structure.hpp"
#include "toolpath/prefetch.hpp"
#include "toolpath/short_text.hpp"
#include "toolpath/value.hpp"

namespace postproc {
namespace {

using toolpath::iequals;

// Only depth 0 and 1 commands are the stream; deeper ones record calls the original post made itself.
class StreamCommands final : public toolpath::CommandSource {
public:
  explicit StreamCommands(toolpath::CommandSource& inner) : inner_(inner) {}
  bool next(toolpath::Command& out) override {
    while (inner_.next(out))
      if (out.is_stream_command()) return true;
    return false;
  }

private:
  toolpath::CommandSource& inner_;
};

// The unit system a job states in its @start_of_file (`inch_system`); metric when it does not.
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

// Receives the post's finished lines: executes directives, writes the rest, tells the observer.
class Sink final : public gppl::OutputSink {
public:
  Sink(OutputFiles& files, LineObserver* observer) : files_(files), observer_(observer) {}

  void write_line(std::string_view line, const gppl::LineOrigin& origin) override {
    std::size_t first = 0;  // a directive may be indented (find_first_not_of costs a memchr per character)
    while (first < line.size() && (line[first] == ' ' || line[first] == '\t')) ++first;
    bool maybe_directive = first < line.size() && line[first] == '!';
    std::optional<Directive> directive = maybe_directive ? parse_directive(line) : std::nullopt;
    if (observer_) {
      // The line was started by the command that flushed the line before it (nb and nl flush the
      // open line and open the next one), unless this command already flushed one.
      bool own = wrote_in_command_;
      file_name_ = files_.current_name();
      LineEvent e{file_name_, line, directive.has_value(), files_.current_is_main(),
                  {own ? command_index : opener_index_, own ? command_name : std::string_view(opener_name_),
                   origin.procedure, origin.source_line}};
      observer_->on_line(e);
      opener_index_ = command_index;
      opener_name_ = command_name;
      wrote_in_command_ = true;
    }
    if (directive) {
      if (observer_ && directive->verb == Directive::Verb::Copy) {
        // The copied text becomes lines of the current file, attributed to the command that copies.
        LineEvent copied{file_name_, {}, false, files_.current_is_main(),
                         {command_index, command_name, origin.procedure, origin.source_line}};
        files_.execute(*directive, [&](std::string_view text) {
          copied.text = text;
          observer_->on_line(copied);
          ++lines;
        });
      } else {
        files_.execute(*directive);
      }
    } else {
      files_.write_line(line);
      ++lines;
    }
  }

  // Called when a command starts (lines are attributed to the command that started them).
  void begin_command(std::size_t index, std::string_view name) {
    command_index = index;
    command_name = name;
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
  std::size_t lines = 0;

private:
  bool wrote_in_command_ = false;
  std::size_t opener_index_ = 0;
  std::string opener_name_;
  OutputFiles& files_;
  LineObserver* observer_;
  std::string file_name_;
};

std::string default_main_name(const std::string& g_file_name, const std::string& extension) {
  std::string name = g_file_name;
  bool has_extension = std::filesystem::path(name).has_extension();
  if (!has_extension && !extension.empty()) name += "." + extension;
  return name;
}

class Session {
public:
  Session(const Engine& engine, std::shared_ptr<const gppl::Program> program, OutputFiles& files,
          const RunOptions& options)
      : engine_(engine),
        options_(options),
        files_(files),
        enums_(engine.drill_cycle_names()),
        sink_(files, options.observer),
        uses_line_functions_(gppl::uses_line_functions(*program)),
        interpreter_(std::move(program), sink_),
        line_numbers_(interpreter_, files, options.observer, [this] {
          return sink_.command_name.empty() ? std::string()
                                            : fmt::format("command #{} {}", sink_.command_index, sink_.command_name);
        }) {
    sink_.line_numbers = &line_numbers_;
    interpreter_.set_trace_stream(options.trace);
    interpreter_.set_limits(engine.options().max_loop_iterations, engine.options().max_call_depth);
    for (const auto& c : enums_.constants())
      if (auto id = interpreter_.find_variable(c.name)) interpreter_.assign(*id, gppl::Value::of_integer(c.code));
    prev_command_ = interpreter_.find_variable("prev_command");
    current_command_ = interpreter_.find_variable("current_command");
    next_command_ = interpreter_.find_variable("next_command");
    for (const auto* cycle : engine.machine().records("drill_type"))
      for (const auto& p : cycle->params) drill_parameters_.push_back(p);
    // PRP external variables start with their declared value, or inactive until a command sets them.
    for (const auto& v : engine.machine().external_variables()) {
      auto id = interpreter_.find_variable(v.name);
      if (!id) continue;
      if (v.initial)
        interpreter_.assign(*id, convert(*v.initial, v.type == prp::VarType::String));
      else
        interpreter_.set_active(*id, false);
    }
  }

  RunSummary run(toolpath::CommandSource& input) {
    RunSummary summary;
    sink_.command_name = "@init_post";
    guarded([&] { interpreter_.start(); });
    // Three stages overlap: reading the job, the PRP's filters, the post. Reading gets a thread of
    // its own because a filter may have to take in the whole job before it hands anything on
    // (gen_procs: @start_of_file names the last subroutine label).
    StreamCommands stream(input);
    // The PRP half follows the job's unit system, which the first command states; it must be
    // chosen before the filters compare anything against the PRP's tolerances.
    toolpath::LookaheadSource first(stream);
    summary.units = engine_.options().units.value_or(job_units(first.peek()));
    machine_ = &engine_.machine(summary.units);
    toolpath::PrefetchSource read_ahead(first);
    auto filtered = prp::build_filter_chain(*machine_, read_ahead);
    toolpath::PrefetchSource prefetched(*filtered);
    // Three commands in rotation: the one before (its name is prev_command), the current one and
    // the one after it (next_command, read before the current one runs): no name is copied.
    std::array<toolpath::Command, 3> rotation;
    toolpath::Command* previous = nullptr;
    toolpath::Command* current = &rotation[0];
    toolpath::Command* following = &rotation[1];
    toolpath::Command* spare = &rotation[2];
    for (bool more = prefetched.next(*current); more;) {
      ++summary.commands;
      sink_.begin_command(current->index, current->name);
      more = prefetched.next(*following);
      guarded([&] {
        execute(*current, previous ? std::string_view(previous->name) : std::string_view{},
                more ? std::string_view(following->name) : std::string_view{}, summary);
      });
      toolpath::Command* reused = previous ? previous : spare;
      previous = std::exchange(current, following);
      following = reused;
      if (options_.progress && (summary.commands & 4095) == 0) options_.progress(summary.commands);
    }
    sink_.end_commands();
    guarded([&] { interpreter_.finish(); });
    if (uses_line_functions_) guarded([&] { line_numbers_.finish(); });
    auto print_file_size = interpreter_.find_variable("print_file_size");
    guarded([&] { files_.finish_placeholders(print_file_size && interpreter_.value(*print_file_size).integer == 1); });
    if (files_.main_path().empty()) name_main_file(default_main_name(input_stem(), engine_.file_extension()));
    summary.lines = sink_.lines;
    return summary;
  }

private:
  struct Slot {
    std::optional<gppl::VariableId> id;
    bool is_string = false;
  };
  // What the engine needs to know about a command name, looked up once per name. The slots of its
  // parameters are remembered by position: a command name's parameters come in the same order
  // command after command, so one string comparison usually replaces a name lookup.
  struct Bound {  // the parameter at one position of a command name
    std::string name;
    Slot slot;
    std::string enum_word;  // the last enumeration word seen here, and its code
    std::int64_t enum_code = 0;
  };
  struct CommandInfo {
    std::optional<gppl::ProcedureId> procedure;
    std::vector<Bound> slots;  // by parameter position
    // What execute() does besides assigning, decided once per name instead of by name tests.
    bool start_of_file = false;
    bool starts_body = false;
    bool calls_subroutine = false;
    bool drill = false;
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

  [[noreturn]] void fail(const std::string& what) const {
    std::string where = sink_.command_name.empty()
                            ? std::string("at the end of the run")
                            : fmt::format("command #{} {}", sink_.command_index, sink_.command_name);
    throw RunError(fmt::format("{}: {}: {}", options_.input_name, where, what));
  }

  std::string input_stem() const {
    std::string stem = std::filesystem::path(options_.input_name).stem().string();
    return stem.empty() ? "output" : stem;
  }

  void name_main_file(const std::string& default_name) {
    files_.set_main_path(options_.main_path ? options_.main_path(default_name) : std::filesystem::path(default_name));
  }

  const Slot& slot(std::string_view name) {
    auto it = slots_.find(name);
    if (it != slots_.end()) return it->second;
    Slot s;
    s.id = interpreter_.find_variable(name);
    if (const ParameterSpec* p = find_parameter(name))
      s.is_string = p->kind == ParameterKind::String;
    else if (s.id)
      s.is_string = interpreter_.value(*s.id).type == gppl::Type::String;
    return slots_.emplace(std::string(name), s).first->second;
  }

  // A PRP value as a post value (start-up only; commands go through assign() below).
  gppl::Value convert(const toolpath::Value& v, bool to_string) {
    switch (v.kind) {
      case toolpath::ValueKind::Integer: return gppl::Value::of_integer(v.integer);
      case toolpath::ValueKind::Numeric: return gppl::Value::of_numeric(v.numeric);
      case toolpath::ValueKind::Logical: return gppl::Value::of_logical(v.logical);
      case toolpath::ValueKind::String: break;
      case toolpath::ValueKind::Enum:
        if (!to_string) return gppl::Value::of_integer(enums_.code(v.text));
        break;
    }
    return gppl::Value::of_string(v.text);
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
      it = commands_.emplace(std::string(name), std::move(made)).first;
    }
    std::move_backward(recent_.begin(), recent_.end() - 1, recent_.end());
    recent_.front() = {it->first, &it->second};
    return it->second;
  }

  // The binding of parameter number `position` of a command, remembered per command name.
  Bound& bound_at(CommandInfo& info, std::size_t position, std::string_view name) {
    if (position < info.slots.size() && toolpath::same_short_text(info.slots[position].name, name)) return info.slots[position];
    if (position >= info.slots.size()) info.slots.resize(position + 1);
    info.slots[position] = Bound{std::string(name), slot(name), {}, 0};
    return info.slots[position];
  }

  static gppl::ChangeOverride change_override(toolpath::ChangeFlag flag) {
    switch (flag) {
      case toolpath::ChangeFlag::Changed: return gppl::ChangeOverride::ForceChanged;
      case toolpath::ChangeFlag::Unchanged: return gppl::ChangeOverride::ForceUnchanged;
      case toolpath::ChangeFlag::None: break;
    }
    return gppl::ChangeOverride::Compute;
  }

  void set_string(const std::optional<gppl::VariableId>& id, std::string_view text) {
    if (id) interpreter_.assign_string(*id, text);
  }

  // A parameter into its post variable, converted as convert() would, without building a Value.
  void assign(Bound& b, const toolpath::Value& v) {
    const gppl::VariableId id = *b.slot.id;
    const gppl::ChangeOverride change = change_override(v.flag);
    switch (v.kind) {
      case toolpath::ValueKind::Integer: return interpreter_.assign_integer(id, v.integer, change);
      case toolpath::ValueKind::Numeric: return interpreter_.assign_numeric(id, v.numeric, change);
      case toolpath::ValueKind::Logical: return interpreter_.assign_logical(id, v.logical, change);
      case toolpath::ValueKind::String: return interpreter_.assign_string(id, v.text, change);
      case toolpath::ValueKind::Enum:
        if (b.slot.is_string) return interpreter_.assign_string(id, v.text, change);
        if (b.enum_word.empty() || !iequals(b.enum_word, v.text)) {  // words are looked up without case
          b.enum_code = enums_.code(v.text);
          b.enum_word = v.text;
        }
        return interpreter_.assign_integer(id, b.enum_code, change);
    }
  }

  // Optional parameters a command did not supply are inactive (gppl-language.md 1.2).
  void deactivate_missing(const toolpath::Command& command, const CommandInfo& info) {
    auto deactivate = [&](std::string_view name) {
      if (command.find(name)) return;
      if (const Slot& s = slot(name); s.id) interpreter_.set_active(*s.id, false);
    };
    if (info.calls_subroutine) {
      for (std::string_view name : {"message", "parm1", "parm2", "parm3"}) deactivate(name);
    } else if (info.drill) {
      for (const auto& name : drill_parameters_) deactivate(name);
    }
  }

  void execute(toolpath::Command& command, std::string_view previous, std::string_view next, RunSummary& summary) {
    CommandInfo& command_info = info(command.name);
    structure_.before(command);
    if (command_info.start_of_file) start_of_file(command);
    if (options_.posted) options_.posted(command);
    bool reset = engine_.options().reset_modal_memory_at_subroutines;
    if (reset && command_info.starts_body) interpreter_.reset_change_memory();

    for (std::size_t i = 0; i < command.parameters.size(); ++i) {
      const toolpath::Parameter& p = command.parameters[i];
      Bound& b = bound_at(command_info, i, p.name);
      if (b.slot.id) assign(b, p.value);
    }
    deactivate_missing(command, command_info);
    set_string(prev_command_, previous);
    set_string(current_command_, command.name);
    set_string(next_command_, next);

    if (!command_info.procedure) {
      ++summary.skipped;
      if (uses_line_functions_) line_numbers_.command_without_procedure(command.name);
      interpreter_.trace_unhandled(command.name);
    } else if (interpreter_.call(*command_info.procedure) == gppl::RunResult::Abort) {
      throw std::runtime_error("the post stopped the run (`abort` in " + command.name + ")");
    }
    if (reset && command_info.calls_subroutine) interpreter_.reset_change_memory();
  }

  // Names the main file, and completes the subroutine numbers the stream left out.
  void start_of_file(toolpath::Command& command) {
    const toolpath::Value* name = command.find("g_file_name");
    std::string base = name && !name->text.empty() ? name->text : input_stem();
    name_main_file(default_main_name(base, engine_.file_extension()));
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
  Sink sink_;
  bool uses_line_functions_;
  gppl::Interpreter interpreter_;
  LineNumbers line_numbers_;
  ProgramStructure structure_;
  std::optional<gppl::VariableId> prev_command_, current_command_, next_command_;
  std::vector<std::string> drill_parameters_;
  std::unordered_map<std::string, Slot, TransparentHash, std::equal_to<>> slots_;
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
  program_ = gppl::compile_file(options_.post, compile);
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
  Session session(*this, program_, output, options);
  return session.run(input);
}

}  // namespace postproc
