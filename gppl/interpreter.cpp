// The public API: compile entry points and the Interpreter facade over Interpreter::State.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>

#include "gppl/compile/compiler.hpp"
#include "gppl/run/machine.hpp"

namespace gppl {

namespace {

constexpr int kMaxCallDepthLimit = 1000;  // deeper would risk the native stack

// The typed host assignments' way out (conversion, untyped variable, error): kept out of line so
// that their fast path needs no stack frame for a Value.
template <typename T, typename Make>
[[gnu::noinline]] void assign_slowly(Interpreter& run, VariableId id, T value, Make make, ChangeOverride change) {
  run.assign(id, make(value), change);
}

}  // namespace

std::shared_ptr<const Program> compile_file(const std::string& path, const CompileOptions& options) {
  return Compiler(options).compile_file(path);
}

std::shared_ptr<const Program> compile_source(std::string_view text, const std::string& file_name,
                                              const CompileOptions& options) {
  return Compiler(options).compile_source(text, file_name);
}

const std::vector<std::string>& warnings(const Program& program) { return program.warnings; }
const std::vector<Error>& warning_details(const Program& program) { return program.warning_details; }

std::vector<ProcedureInfo> procedures(const Program& program) {
  std::vector<ProcedureInfo> out;
  for (const Procedure& p : program.procedures)
    if (p.defined) out.push_back({p.name, program.position(p.pos), p.called});
  return out;
}

std::string_view nearest_name(std::string_view name, std::span<const std::string_view> candidates) {
  auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
  // Edit distance with transpositions (a swapped pair is one mistake: mvoe for move), one row each.
  auto distance = [&](std::string_view a, std::string_view b) {
    std::vector<std::size_t> before(b.size() + 1), row(b.size() + 1), next(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      next[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j) {
        const bool same = lower(a[i - 1]) == lower(b[j - 1]);
        next[j] = std::min({row[j] + 1, next[j - 1] + 1, row[j - 1] + (same ? 0 : 1)});
        if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
          next[j] = std::min(next[j], before[j - 2] + 1);
      }
      before.swap(row);
      row.swap(next);
    }
    return row[b.size()];
  };
  const std::size_t limit = std::min<std::size_t>(2, std::max<std::size_t>(1, name.size() / 3));
  std::string_view best;
  std::size_t best_distance = limit + 1;
  for (std::string_view c : candidates) {
    if (c.size() + limit < name.size() || name.size() + limit < c.size()) continue;
    const std::size_t d = distance(name, c);
    if (d > 0 && d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

Interpreter::Interpreter(std::shared_ptr<const Program> program, OutputSink& sink) {
  if (!program) throw std::invalid_argument("gppl::Interpreter needs a compiled program");
  state_ = std::make_unique<State>(std::move(program), sink);
}

Interpreter::~Interpreter() = default;

std::optional<VariableId> Interpreter::find_variable(std::string_view name) const {
  const auto& index = state_->program.global_index;
  const auto it = index.find(lower(name));
  if (it == index.end()) return std::nullopt;
  return it->second;
}

std::optional<ProcedureId> Interpreter::find_procedure(std::string_view name) const {
  std::string key = lower(name);
  if (key.empty() || key.front() != '@') key.insert(key.begin(), '@');
  const auto& index = state_->program.procedure_index;
  const auto it = index.find(key);
  if (it == index.end()) return std::nullopt;
  return it->second;
}

VariableId Interpreter::add_variable(std::string_view name) {
  if (auto id = find_variable(name)) return *id;
  State& s = *state_;
  std::string key = lower(name);
  if (auto it = s.extra_index.find(key); it != s.extra_index.end()) return it->second;
  const auto id = VariableId(s.program.globals.size() + s.extra_names.size());
  s.extra_names.emplace_back(name);
  s.extra_index.emplace(std::move(key), id);
  Cell c;
  c.typed = false;
  s.globals.push_back(std::move(c));
  s.host_cells.push_back(std::uint32_t(s.globals.size() - 1));
  return id;
}

void Interpreter::assign(VariableId id, const Value& value, ChangeOverride change) {
  State& s = *state_;
  s.current = nullptr;
  // The engine calls this for every parameter of every command: the declared variable is looked
  // up once, and the VarRef (for error messages only) costs nothing to build.
  if (id < s.program.globals.size()) {
    const GlobalVariable& var = s.program.globals[id];
    Cell& c = s.globals[var.first_cell];
    if (var.group == Group::Implicit && c.typed && c.value.type != value.type) c.typed = false;  // re-typed by the host
    const VarRef ref{false, id, var.first_cell, kNone, 0};
    s.assign(c, value, change, &ref);
  } else {
    Cell& c = s.host_cell(id);  // a variable the host declared at run time: always implicit
    if (c.typed && c.value.type != value.type) c.typed = false;
    s.assign(c, value, change, nullptr);
  }
  s.note_host_assignment(id);
}

void Interpreter::assign_integer(VariableId id, std::int64_t value, ChangeOverride change) {
  State& s = *state_;
  if (!s.assign_in_place<&Value::integer>(s.typed_host_cell(id, Type::Integer), id, value, change))
    assign_slowly(*this, id, value, Value::of_integer, change);
}

void Interpreter::assign_numeric(VariableId id, double value, ChangeOverride change) {
  State& s = *state_;
  if (!s.assign_in_place<&Value::numeric>(s.typed_host_cell(id, Type::Numeric), id, value, change))
    assign_slowly(*this, id, value, Value::of_numeric, change);
}

void Interpreter::assign_logical(VariableId id, bool value, ChangeOverride change) {
  State& s = *state_;
  if (!s.assign_in_place<&Value::logical>(s.typed_host_cell(id, Type::Logical), id, value, change))
    assign_slowly(*this, id, value, Value::of_logical, change);
}

Interpreter::HostSlot Interpreter::host_slot(VariableId id) const {
  const State& s = *state_;
  if (id >= s.host_cells.size()) throw std::out_of_range(fmt::format("no variable with id {}", id));
  HostSlot slot;
  slot.id_ = id;
  slot.cell_ = s.host_cells[id];
  return slot;
}

void Interpreter::assign_integer(HostSlot slot, std::int64_t value, ChangeOverride change) {
  State& s = *state_;
  if (!s.assign_in_place<&Value::integer>(s.typed_cell(slot.cell_, Type::Integer), slot.id_, value, change))
    assign_slowly(*this, slot.id_, value, Value::of_integer, change);
}

void Interpreter::assign_numeric(HostSlot slot, double value, ChangeOverride change) {
  State& s = *state_;
  if (!s.assign_in_place<&Value::numeric>(s.typed_cell(slot.cell_, Type::Numeric), slot.id_, value, change))
    assign_slowly(*this, slot.id_, value, Value::of_numeric, change);
}

void Interpreter::assign_string(VariableId id, std::string_view value, ChangeOverride change) {
  State& s = *state_;
  Cell* c = s.typed_host_cell(id, Type::String);
  if (!c) return assign_slowly(*this, id, value, [](std::string_view v) { return Value::of_string(std::string(v)); }, change);
  const bool differs = !same_text(c->value.text, value);
  if (differs) c->value.text.assign(value);
  State::mark_assigned(*c, differs, change);
  s.note_host_assignment(id);
}

void Interpreter::assign_strings(std::span<const VariableId> ids, std::span<const std::string_view> texts) {
  State& s = *state_;
  const std::size_t n = std::min(ids.size(), texts.size());
  for (std::size_t i = 0; i < n; ++i) {
    Cell* c = s.typed_host_cell(ids[i], Type::String);
    if (!c) {
      assign_string(ids[i], texts[i]);
      continue;
    }
    const bool differs = !same_text(c->value.text, texts[i]);
    if (differs) c->value.text.assign(texts[i].data(), texts[i].size());
    State::mark_assigned(*c, differs, ChangeOverride::Compute);
    s.note_host_assignment(ids[i]);
  }
}

void Interpreter::assign_element(VariableId id, std::span<const int> indices, const Value& value, ChangeOverride change) {
  State& s = *state_;
  const GlobalVariable& var = s.program.globals.at(id);
  // As in a post (codegen): a system array's trailing indices of 1 may be left out.
  std::array<int, 8> padded{};
  if (var.group == Group::System && !indices.empty() && indices.size() < var.dimensions.size() &&
      var.dimensions.size() <= padded.size()) {
    std::fill(padded.begin(), padded.end(), 1);
    std::copy(indices.begin(), indices.end(), padded.begin());
    indices = std::span<const int>(padded.data(), var.dimensions.size());
  }
  if (indices.size() != var.dimensions.size())
    throw std::out_of_range(fmt::format("{} has {} dimension(s), {} indices given", var.name, var.dimensions.size(),
                                        indices.size()));
  std::uint32_t offset = 0;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] < 1 || indices[i] > var.dimensions[i])
      throw std::out_of_range(fmt::format("index {} of {} is {}, outside 1..{}", i + 1, var.name, indices[i],
                                          var.dimensions[i]));
    offset = offset * std::uint32_t(var.dimensions[i]) + std::uint32_t(indices[i] - 1);
  }
  const VarRef ref{false, id, var.first_cell, kNone, 0};
  s.current = nullptr;
  s.assign(s.globals[var.first_cell + offset], value, change, &ref);
}

void Interpreter::set_active(VariableId id, bool active) {
  state_->host_cell(id).active = active;
}

void Interpreter::set_changed(VariableId id, bool changed) {
  state_->host_cell(id).changed = changed;
}

void Interpreter::reset_change_memory() {
  for (auto& cell : state_->globals) cell.assigned = false;
}

const Value& Interpreter::value(VariableId id) const {
  return state_->host_cell(id).value;
}

bool Interpreter::active(VariableId id) const { return state_->host_cell(id).active; }

std::optional<Type> Interpreter::unread_type(VariableId id) const {
  const State& s = *state_;
  if (s.trace != nullptr || id >= s.program.globals.size() || s.named_by_program[id]) return std::nullopt;
  const GlobalVariable& var = s.program.globals[id];
  // An implicit host variable takes the type of what the host gives it (Interpreter::assign).
  if (var.group == Group::Implicit || var.cell_count != 1) return std::nullopt;
  const Cell& c = s.globals[var.first_cell];
  if (!c.typed) return std::nullopt;
  return c.value.type;
}

bool Interpreter::changed(VariableId id) const {
  return state_->host_cell(id).changed;
}

RunResult Interpreter::start() {
  State& s = *state_;
  struct InitGuard {
    State& s;
    ~InitGuard() { s.in_init = false; }
  } guard{s};
  s.in_init = true;  // @init_post is never traced (8.1); exit ends only the init procedure (5.9)
  if (s.program.init_post && s.top_level(*s.program.init_post) == RunResult::Abort) return RunResult::Abort;
  s.in_init = false;
  for (std::uint32_t id : s.program.init_inc)
    if (s.top_level(id) == RunResult::Abort) return RunResult::Abort;
  return RunResult::Normal;
}

RunResult Interpreter::call(ProcedureId id) {
  State& s = *state_;
  if (id >= s.program.procedures.size() || !s.program.procedures[id].defined)
    throw std::out_of_range(fmt::format("no procedure with id {}", id));
  return s.top_level(id);
}

void Interpreter::finish() {
  state_->current = nullptr;
  state_->flush();
}

void Interpreter::set_trace_stream(std::ostream* trace) { state_->trace = trace; }

void Interpreter::trace_all(int level) { state_->trace_statement("all", level); }

void Interpreter::trace_unhandled(std::string_view command) {
  State& s = *state_;
  if (s.trace == nullptr) return;
  std::string key = lower(command);
  if (key.empty() || key.front() != '@') key.insert(key.begin(), '@');
  const auto it = s.command_trace_level.find(key);
  const int level = it != s.command_trace_level.end() ? it->second : s.default_trace_level;
  if (level >= 1) s.trace_enter(!command.empty() && command.front() == '@' ? std::string(command) : std::string("@").append(command), 0, level);
  s.host_assigned.clear();
}

void Interpreter::set_limits(std::uint64_t max_loop_iterations, int max_call_depth) {
  state_->max_loop_iterations = std::max<std::uint64_t>(max_loop_iterations, 1);
  state_->max_call_depth = std::clamp(max_call_depth, 1, kMaxCallDepthLimit);
}

}  // namespace gppl
