// Variable cells, the conversion table of spec 4.5 and assignment with the change/active rules
// of 3.5. These run for every assignment: no allocation once string capacities have grown.
#include "gppl/run/machine.hpp"

#include <fmt/format.h>

#include <cmath>

#include "gppl/error_codes.hpp"

namespace gppl {

namespace {

constexpr std::int64_t kIntegerLimit = 999'999'999;

void set_zero(Value& v, Type t) {
  v.type = t;
  v.integer = 0;
  v.numeric = 0.0;
  v.logical = false;
  v.text.clear();
}

}  // namespace

Interpreter::State::State(std::shared_ptr<const Program> p, OutputSink& s)
    : owner(std::move(p)), program(*owner), sink(s) {
  globals.resize(program.global_cells);
  for (const GlobalVariable& v : program.globals) {
    for (std::uint32_t i = 0; i < v.cell_count; ++i) {
      Cell& c = globals[v.first_cell + i];
      c.value = v.initial;
      c.active = v.initially_active;
      c.typed = v.typed;
    }
  }
  for (const GlobalVariable& v : program.globals) host_cells.push_back(v.first_cell);
  // Every read of a global goes through a VarRef (expressions, conditions, items, name_f formats,
  // group requirements, input targets) or a generator slot; writes are counted too, which is safe.
  named_by_program.assign(program.globals.size(), false);
  for (const VarRef& r : program.refs)
    if (!r.local && r.id < named_by_program.size()) named_by_program[r.id] = true;
  const SystemSlots& sl = program.slots;
  const std::uint32_t slot_cells[] = {sl.skipline,      sl.blknum,        sl.blknum_delta, sl.blknum_max,
                                      sl.blknum_exist,  sl.blknum_gen,    sl.blknum_letter, sl.blknum_f,
                                      sl.integer_def_f, sl.numeric_def_f, sl.remove_blanks, sl.end_block_text,
                                      sl.gcode_space,   sl.clear_change_after_gen};
  for (std::size_t id = 0; id < program.globals.size(); ++id) {
    const GlobalVariable& v = program.globals[id];
    for (std::uint32_t cell : slot_cells)
      if (cell >= v.first_cell && cell < v.first_cell + v.cell_count) named_by_program[id] = true;
  }
  if (sl.gcode < named_by_program.size()) named_by_program[sl.gcode] = true;
  format_sites.resize(program.format_sites + 3);
  constant_formats.resize(program.format_specs.size());
  procedure_trace_level.assign(program.procedures.size(), -1);
}

void Interpreter::State::fail(ErrorCode code, std::string_view name, std::string_view detail) const {
  fail_at(current ? current->pos : SourcePos{}, code, name, detail);
}

void Interpreter::State::fail_at(SourcePos pos, ErrorCode code, std::string_view name, std::string_view detail) const {
  Position where = current || pos.line != 0 ? program.position(pos) : Position{};
  throw make_error(code, std::move(where), name, detail);
}

Cell& Interpreter::State::host_cell(VariableId id) {
  if (id < program.globals.size()) return globals[program.globals[id].first_cell];
  const std::size_t extra = id - program.globals.size();
  if (extra >= extra_names.size()) throw std::out_of_range(fmt::format("no variable with id {}", id));
  return globals[program.global_cells + extra];
}

void Interpreter::State::note_traced_assignment(VariableId id) {
  if (host_assigned.size() < 10000) host_assigned.push_back(id);
}

const std::string& Interpreter::State::host_name(VariableId id) const {
  if (id < program.globals.size()) return program.globals[id].name;
  return extra_names.at(id - program.globals.size());
}

const std::string& Interpreter::State::variable_name(const VarRef& ref) const {
  if (ref.local) return program.procedures[frames.back().procedure].locals[ref.id].name;
  return program.globals[ref.id].name;
}

Cell& Interpreter::State::array_element(const VarRef& ref) {
  if (ref.indices == kUndeclared) {
    Cell& c = cell(ref);
    if (c.typed) return c;  // the host has given it a value (the job carries it)
    const auto& u = program.undeclared.at(std::uint32_t(&ref - program.refs.data()));
    fail_at(u.pos, ErrorCode(u.error), variable_name(ref));
  }
  const std::vector<int>& dims = ref.local ? program.procedures[frames.back().procedure].locals[ref.id].dimensions
                                           : program.globals[ref.id].dimensions;
  std::uint32_t offset = 0;
  for (std::uint32_t i = 0; i < ref.index_count; ++i) {
    Value& v = push_scratch();
    eval(program.lists[ref.indices + i], v);
    const std::int64_t index = to_integer(v);
    const bool integral = v.type != Type::Numeric || std::fabs(v.numeric - double(index)) < 1e-9;
    pop_scratch();
    if (!integral || index < 1 || index > dims[i])
      fail(ErrorCode::OutOfRange, {},
           fmt::format("index {} of '{}' is {}, outside 1..{}", i + 1, variable_name(ref),
                       integral ? fmt::format("{}", index) : fmt::format("{}", v.numeric), dims[i]));
    offset = offset * std::uint32_t(dims[i]) + std::uint32_t(index - 1);
  }
  return (&cell(ref))[offset];
}

void Interpreter::State::grow_scratch() { scratch.push_back(std::make_unique<Value>()); }

std::int64_t Interpreter::State::to_integer(const Value& v, const VarRef* ref) const {
  switch (v.type) {
    case Type::Integer: return v.integer;
    case Type::Logical: return v.logical ? 1 : 0;
    case Type::Numeric: {
      // Truncate toward zero, but let representation noise (2.9999999999) land on the integer (4.5).
      const double near = std::round(v.numeric);
      const double r = std::fabs(v.numeric - near) < 1e-9 ? near : std::trunc(v.numeric);
      if (!(std::fabs(r) <= double(kIntegerLimit)))
        fail(ErrorCode::ValueRange, {}, fmt::format("{} does not fit an integer (at most 999999999)", v.numeric));
      return std::int64_t(r);
    }
    case Type::String: break;
  }
  fail(ErrorCode::NotNumeric, ref ? std::string_view(variable_name(*ref)) : std::string_view{},
       fmt::format("a number is required, not the string '{}'", v.text));
}

double Interpreter::State::to_numeric(const Value& v, const VarRef* ref) const {
  switch (v.type) {
    case Type::Integer: return double(v.integer);
    case Type::Logical: return v.logical ? 1.0 : 0.0;
    case Type::Numeric: return v.numeric;
    case Type::String: break;
  }
  fail(ErrorCode::NotNumeric, ref ? std::string_view(variable_name(*ref)) : std::string_view{},
       fmt::format("a number is required, not the string '{}'", v.text));
}

bool Interpreter::State::to_logical(const Value& v) const {
  switch (v.type) {
    case Type::Logical: return v.logical;
    case Type::Integer:
      if (v.integer == 0 || v.integer == 1) return v.integer == 1;
      fail(ErrorCode::NotLogical, {}, fmt::format("the value is {}, not 0 or 1", v.integer));
    case Type::Numeric:
      if (v.numeric == 0.0 || v.numeric == 1.0) return v.numeric == 1.0;
      fail(ErrorCode::NotLogical, {}, fmt::format("the value is {}, not 0 or 1", v.numeric));
    case Type::String: break;
  }
  fail(ErrorCode::NotNumeric, {}, fmt::format("a logical value is required, not the string '{}'", v.text));
}

// Real posts test integer options directly (`if iSplit_ProgName_Num and bUseprognum` with the
// option at 2) and SolidCAM runs them: in a condition and under and/or/not a number is TRUE when
// it is not zero. Storing a number other than 0/1 in a logical variable is still error 420.
bool Interpreter::State::truth(const Value& v) const {
  switch (v.type) {
    case Type::Logical: return v.logical;
    case Type::Integer: return v.integer != 0;
    case Type::Numeric: return v.numeric != 0.0;
    case Type::String: break;
  }
  fail(ErrorCode::NotNumeric, {}, fmt::format("a logical value is required, not the string '{}'", v.text));
}

void Interpreter::State::reset_cell(Cell& c, Type type) const {
  set_zero(c.value, type);
  c.changed = false;
  c.active = true;
  c.assigned = false;
  c.typed = true;
}

void Interpreter::State::assign_converting(Cell& target, const Value& v, ChangeOverride change, const VarRef* ref) {
  Value& cur = target.value;
  bool differs = false;
  if (!target.typed) {
    // Implicit host variable: typed by its first assignment.
    differs = true;
    cur = v;
    target.typed = true;
  } else {
    switch (cur.type) {
      case Type::Integer: {
        // Same type first: the conversion functions are out of line (they may throw).
        const std::int64_t x = v.type == Type::Integer ? v.integer : to_integer(v, ref);
        differs = cur.integer != x;
        cur.integer = x;
        break;
      }
      case Type::Numeric: {
        const double x = v.type == Type::Numeric ? v.numeric : to_numeric(v, ref);
        differs = cur.numeric != x;
        cur.numeric = x;
        break;
      }
      case Type::Logical: {
        const bool x = v.type == Type::String ? (fail(ErrorCode::NotNumeric, ref ? std::string_view(variable_name(*ref)) : std::string_view{},
                                                      fmt::format("a logical value is required, not the string '{}'", v.text)), false)
                                              : v.type == Type::Logical ? v.logical
                                                                         : to_logical(v);
        differs = cur.logical != x;
        cur.logical = x;
        break;
      }
      case Type::String:
        if (v.type != Type::String)
          fail(ErrorCode::NotString, ref ? std::string_view(variable_name(*ref)) : std::string_view{},
               "a string is required, not a number");
        differs = cur.text != v.text;
        if (differs) cur.text.assign(v.text);
        break;
    }
  }
  mark_assigned(target, differs, change);
}

}  // namespace gppl
