// The interpreter's run-time state (Interpreter::State): variable cells, the call stack, the
// expression scratch stack, the output line and the trace. Internal to gppl/.
#pragma once

#include <cstring>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <unordered_map>
#include <vector>

#include "gppl/builtins/display_format.hpp"
#include "gppl/error_codes.hpp"
#include "gppl/gppl.hpp"
#include "gppl/program.hpp"
#include "gppl/run/output_line.hpp"

namespace gppl {

// One variable or array element with its attributes (3.5).
struct Cell {
  Value value;
  bool changed = false;
  bool active = true;
  bool assigned = false;  // assigned at least once since declaration or procedure entry
  bool typed = true;      // false: implicit host variable not yet typed by an assignment
};

// An answer converted to the type of the input statement that reads it (dialog.cpp).
struct PreparedAnswer {
  Value value;
  std::string source;  // for the log: "--answer tool=3", "answers.txt:4"
};

enum class Flow : std::uint8_t { Normal, Exit, Abort };

// Equality of short texts (display formats, names) with word loads instead of a memcmp call.
inline bool same_text(std::string_view a, std::string_view b) {
  const std::size_t n = a.size();
  if (n != b.size()) return false;
  if (n > 16) return a == b;
  const char *p = a.data(), *q = b.data();
  auto word8 = [](const char* s) { std::uint64_t w; std::memcpy(&w, s, 8); return w; };
  auto word4 = [](const char* s) { std::uint32_t w; std::memcpy(&w, s, 4); return w; };
  if (n >= 8) return word8(p) == word8(q) && word8(p + n - 8) == word8(q + n - 8);
  if (n >= 4) return word4(p) == word4(q) && word4(p + n - 4) == word4(q + n - 4);
  if (n == 0) return true;
  return p[0] == q[0] && p[n / 2] == q[n / 2] && p[n - 1] == q[n - 1];  // 1 to 3 bytes: all of them
}

// The comparison rules of 4.5 for values known not to be strings: numeric when either side is,
// else integers (a logical is 0 or 1). Shared by condition() and eval(). (Names of their own: the
// display-format printer has an integer_of with other rules for other values.)
template <typename T>
bool holds(BinaryOp op, const T& a, const T& b) {
  switch (op) {
    case BinaryOp::Eq: return a == b;
    case BinaryOp::Ne: return a != b;
    case BinaryOp::Lt: return a < b;
    case BinaryOp::Le: return a <= b;
    case BinaryOp::Gt: return a > b;
    default: return a >= b;
  }
}
// to_numeric / to_integer of a value known not to be a string (they cannot fail then).
inline double operand_number(const Value& v) {
  return v.type == Type::Numeric ? v.numeric : v.type == Type::Integer ? double(v.integer) : v.logical ? 1.0 : 0.0;
}
inline std::int64_t operand_integer(const Value& v) { return v.type == Type::Integer ? v.integer : v.logical ? 1 : 0; }

struct FormatCache {
  std::string spec;
  std::optional<DisplayFormat> format;
};

struct Interpreter::State {
  State(std::shared_ptr<const Program> p, OutputSink& s);

  std::shared_ptr<const Program> owner;
  const Program& program;
  OutputSink& sink;

  std::vector<Cell> globals;  // program globals, then the host's extra variables
  std::vector<std::string> extra_names;  // variables only the host names (add_variable)
  std::unordered_map<std::string, std::uint32_t> extra_index;
  std::vector<std::uint32_t> host_cells;  // VariableId -> its (first) cell in `globals`
  std::vector<Cell> stack;  // locals of all active procedures
  std::uint32_t stack_top = 0;
  struct Frame {
    std::uint32_t procedure;
    std::uint32_t base;
  };
  std::vector<Frame> frames;
  // Expression temporaries, one heap Value each so that references stay valid while the stack
  // grows (a deque's indexing cost a division per push on the hot path).
  std::vector<std::unique_ptr<Value>> scratch;
  std::uint32_t scratch_top = 0;
  std::vector<Value> arguments;  // contiguous argument lists of built-in calls
  std::uint32_t argument_top = 0;

  std::uint64_t max_loop_iterations = 10'000'000;
  std::uint64_t loop_iterations = 0;
  int max_call_depth = 200;
  const Instruction* current = nullptr;  // statement being executed (errors, line origins)
  bool in_init = false;

  // output line model (6.2)
  OutputLine line;
  bool line_open = false;
  bool separator_pending = false;
  LineOrigin origin;
  OutputLine piece;              // an item measured or printed before it joins the line
  std::string line_function_text;  // start_line / end_line, which the host writes
  std::vector<FormatCache> format_sites;      // per generate item, then 3 defaults (integer, numeric, blknum)
  std::vector<FormatCache> constant_formats;  // per Program::format_specs entry

  // input and print (docs/gppl-language.md): the run log, and an answer per input statement
  std::ostream* log = nullptr;
  bool log_inputs = true;
  std::vector<std::optional<PreparedAnswer>> answers;  // by Program::inputs index

  // trace (8)
  std::ostream* trace = nullptr;
  int default_trace_level = 0;
  std::vector<int> procedure_trace_level;  // -1: use the default
  std::unordered_map<std::string, int> command_trace_level;  // names without a procedure
  std::vector<std::uint32_t> host_assigned;  // variables the host set since the last call (trace dump)
  std::vector<bool> named_by_program;        // per program global: a VarRef or a generator slot names it
  std::string trace_remainder;               // a long procedure name's tail, printed on the next line
  int last_header_level = 0;                 // level of the procedure whose header was written last

  // host-facing variable ids: program globals, then extra variables
  Cell& host_cell(VariableId id);
  // The host's cell of `id` when it is typed and holds a `type` (assignable without conversion).
  Cell* typed_host_cell(VariableId id, Type type) {
    if (id >= host_cells.size()) return nullptr;
    return typed_cell(host_cells[id], type);
  }
  Cell* typed_cell(std::uint32_t index, Type type) {
    Cell& c = globals[index];
    return c.typed && c.value.type == type ? &c : nullptr;
  }
  void note_host_assignment(VariableId id) {  // for the trace's dump of what the host set
    if (trace != nullptr) note_traced_assignment(id);
  }
  void note_traced_assignment(VariableId id);
  // The host's typed assignment of a number or logical (`Field` of Value) when the cell is typed
  // and holds `type`; false when the general path must do it (conversion, untyped, no such cell).
  // `c`: typed_host_cell(id, type) or the same cell found before (Interpreter::HostSlot).
  template <auto Field, typename T>
  bool assign_in_place(Cell* c, VariableId id, T value, ChangeOverride change) {
    if (!c) return false;
    const bool differs = c->value.*Field != value;
    c->value.*Field = value;
    mark_assigned(*c, differs, change);
    note_host_assignment(id);
    return true;
  }
  const std::string& host_name(VariableId id) const;

  // machine.cpp: cells, conversions, assignment
  [[noreturn]] void fail(ErrorCode code, std::string_view name = {}, std::string_view detail = {}) const;
  [[noreturn]] void fail_at(SourcePos pos, ErrorCode code, std::string_view name = {}, std::string_view detail = {}) const;
  // Scalars inline (every variable read of a procedure); arrays evaluate their indices out of line.
  Cell& cell(const VarRef& ref) { return ref.local ? stack[frames.back().base + ref.cell] : globals[ref.cell]; }
  const Cell& relation_cell(const Relation::Cell& c) { return c.local ? stack[frames.back().base + c.index] : globals[c.index]; }
  Cell& element(const VarRef& ref) { return ref.indices == kNone ? cell(ref) : array_element(ref); }
  Cell& array_element(const VarRef& ref);
  // The variable of a Value item (its global cell when the compiler resolved it).
  Cell& item_cell(const GenItem& item) {
    return item.global_cell != kNone ? globals[item.global_cell] : element(program.refs[item.ref]);
  }
  // The value of a Constant or scalar Variable node without copying it; nullptr for other nodes.
  const Value* operand(const Node& n) {
    if (n.kind == NodeKind::Constant) return &program.constants[n.a];
    if (n.kind == NodeKind::Variable && n.simple) return &cell(program.refs[n.a]).value;
    return nullptr;
  }
  // `use(value)` of expression `node`: a constant or scalar read in place (no copy), anything
  // else evaluated into a scratch value (an assignment's source, `change(x) = TRUE`).
  template <typename Use>
  void with_value(std::uint32_t node, Use&& use) {
    if (const Value* x = operand(program.nodes[node])) return use(*x);
    Value& v = push_scratch();
    eval(node, v);
    use(v);
    pop_scratch();
  }
  const std::string& variable_name(const VarRef& ref) const;
  // Assignment with the change/active rules (3.5). A number or logical of the variable's own type
  // is stored inline; conversions, strings, untyped host variables and errors go out of line.
  void assign(Cell& target, const Value& v, ChangeOverride change, const VarRef* ref) {
    if (!target.typed || target.value.type != v.type || v.type == Type::String)
      return assign_converting(target, v, change, ref);
    bool differs = false;
    switch (v.type) {
      case Type::Integer: differs = target.value.integer != v.integer, target.value.integer = v.integer; break;
      case Type::Numeric: differs = target.value.numeric != v.numeric, target.value.numeric = v.numeric; break;
      default: differs = target.value.logical != v.logical, target.value.logical = v.logical; break;
    }
    mark_assigned(target, differs, change);
  }
  static void mark_assigned(Cell& target, bool differs, ChangeOverride change) {
    // Compute tested first: a forced flag is rare (a switch tested it last).
    if (change == ChangeOverride::Compute) [[likely]]
      target.changed = differs || !target.assigned;
    else
      target.changed = change == ChangeOverride::ForceChanged;
    target.assigned = true;
    target.active = true;
  }
  void assign_converting(Cell& target, const Value& v, ChangeOverride change, const VarRef* ref);
  // out = in, copying the text only when there is one (a std::string copy costs a call).
  static void copy_value(Value& out, const Value& in) {
    out.type = in.type;
    out.integer = in.integer;
    out.numeric = in.numeric;
    out.logical = in.logical;
    if (in.text.empty()) out.text.clear();
    else out.text.assign(in.text);
  }
  std::int64_t to_integer(const Value& v, const VarRef* ref = nullptr) const;
  double to_numeric(const Value& v, const VarRef* ref = nullptr) const;
  bool to_logical(const Value& v) const;  // into a logical variable: 0 or 1, else error 420
  bool truth(const Value& v) const;       // a condition or an and/or/not operand: non-zero is TRUE
  void reset_cell(Cell& c, Type type) const;
  Value& push_scratch() {  // inline: several calls per generated item
    if (scratch_top == scratch.size()) grow_scratch();
    return *scratch[scratch_top++];
  }
  void grow_scratch();
  void pop_scratch() { --scratch_top; }

  // evaluate.cpp
  void eval(std::uint32_t node, Value& out);
  // The usual tests inline, read in place: `if x gt 5`, `if a eq b`, `if flag`, `if change(x)`.
  [[gnu::always_inline]] bool condition(std::uint32_t node) {
    const Node& n = program.nodes[node];
    if (n.simple) {
      switch (n.kind) {
        case NodeKind::Binary: {  // compiled: `variable op constant` or `variable op variable`
          const Relation& r = program.relations[n.list];
          const Value& a = relation_cell(r.left).value;
          if (a.type == Type::String) break;
          if (!r.right_is_variable) {
            if (r.numeric || a.type == Type::Numeric) return holds(r.op, operand_number(a), r.number);
            return holds(r.op, operand_integer(a), r.integer);
          }
          const Value& b = relation_cell(r.right).value;
          if (b.type == Type::String) break;
          if (a.type == Type::Numeric || b.type == Type::Numeric) return holds(r.op, operand_number(a), operand_number(b));
          return holds(r.op, operand_integer(a), operand_integer(b));
        }
        case NodeKind::Variable: {
          const Value& v = cell(program.refs[n.a]).value;
          if (v.type == Type::Logical) return v.logical;
          break;
        }
        case NodeKind::Attribute: {
          const Cell& c = cell(program.refs[n.a]);
          return n.active_attribute ? c.active : c.changed;
        }
        default: break;
      }
    }
    return condition_slowly(node);
  }
  bool condition_slowly(std::uint32_t node);  // the rest: and/or/not, expressions, strings
  void binary(const Node& n, Value& left, const Value& right);
  void call_builtin(const Node& n, Value& out);

  // execute.cpp
  Flow run(std::uint32_t procedure, std::uint32_t args_list, std::uint32_t arg_count);
  [[noreturn]] void calls_too_deep() const;  // error 405: max_call_depth frames are open
  // The new frame of a procedure with parameters or locals: arguments, fresh locals (3.4, 5.7).
  void enter(const Procedure& proc, std::uint32_t procedure, std::uint32_t args_list, std::uint32_t arg_count);
  Flow execute(std::uint32_t procedure);
  RunResult top_level(std::uint32_t procedure);

  // output.cpp
  void generate(std::uint32_t first, std::uint32_t count);
  void render(const GenItem& item, OutputLine& out);
  bool write_known_value(const GenItem& item, bool clear_change);
  const DisplayFormat& format_for(const GenItem& item, const Value& v);
  // The display format of a variable item holding `v` when it is parsed already and still applies
  // (a constant format, the `name_f` text the item's cache holds, or the default format of v's
  // type when the item has no `name_f`); nullptr: format_for() works it out.
  const DisplayFormat* known_format(const GenItem& item, const Value& v) {
    if (item.format_kind == FormatKind::Constant) {
      const FormatCache& constant = constant_formats[item.format];
      return constant.format ? &*constant.format : nullptr;
    }
    if (item.format_kind != FormatKind::Default) return nullptr;
    const FormatCache* site;
    const std::string* spec;
    if (item.name_format != kNone) {
      site = &format_sites[item.site];
      spec = &cell(program.refs[item.name_format]).value.text;
    } else {
      const bool numeric = v.type == Type::Numeric;
      site = &format_sites[program.format_sites + (numeric ? 1 : 0)];
      spec = &globals[numeric ? program.slots.numeric_def_f : program.slots.integer_def_f].value.text;
    }
    return !spec->empty() && site->format && same_text(site->spec, *spec) ? &*site->format : nullptr;
  }
  // The parsed display format of `spec`, parsed again only when the text changed since last time.
  const DisplayFormat& cached(FormatCache& cache, std::string_view spec, SourcePos pos) {
    if (cache.format && same_text(cache.spec, spec)) return *cache.format;
    return parse_format(cache, spec, pos);
  }
  const DisplayFormat& parse_format(FormatCache& cache, std::string_view spec, SourcePos pos);
  // Text onto the output line; the usual case (an open line, no separator owed) inline.
  void append(std::string_view text) {
    if (line_open && !separator_pending) line.append(text);
    else append_opening(text);
  }
  void append_opening(std::string_view text);
  void open_line(bool after_break = false);  // nl and nb pass true: they break before the line
  void flush();
  void new_block(SourcePos pos);
  void new_line();
  // A modal group prints when one of its variables is active and changed (6.5).
  bool group_required(const GenItem& group) {
    if (group.global_cell != kNone) {
      const Cell& c = globals[group.global_cell];
      return c.active && c.changed;
    }
    for (std::uint32_t i = 0; i < group.required_count; ++i) {
      const Cell& c = element(program.refs[program.lists[group.required + i]]);
      if (c.active && c.changed) return true;
    }
    return false;
  }
  void render_line_function(const GenItem& item, std::string& out);  // line_functions.cpp

  // dialog.cpp
  void input(std::uint32_t index);
  void print(std::uint32_t first, std::uint32_t count);

  // trace.cpp
  int trace_level(std::uint32_t procedure) const;
  void trace_statement(const std::string& list, std::int64_t level);
  void trace_enter(std::string_view name, int depth, int level);
  void trace_output(std::string_view text);
  void trace_line(std::string text);
};

}  // namespace gppl
