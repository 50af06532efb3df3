// Static declarations (spec 3.2-3.4): the system variables every post has, `global` and `local`
// declarations with their types and dimensions, procedure parameters. Declarations are collected
// before any statement is compiled, so a name is known in its whole procedure (docs/gppl-language.md).
#include "gppl/compile/compiler.hpp"

#include <fmt/format.h>

#include "gppl/error_codes.hpp"
#include "gppl/compile/system_variables.hpp"

namespace gppl {

namespace {

constexpr std::uint64_t kMaxArrayCells = 1'000'000;

Type type_of(std::string_view word) {
  if (same_name(word, "integer")) return Type::Integer;
  if (same_name(word, "numeric")) return Type::Numeric;
  if (same_name(word, "logical")) return Type::Logical;
  return Type::String;
}

// A post's global declaration of a system name is that variable when both hold text, or both
// hold numbers (integer, numeric and logical convert into one another, spec 4.5).
bool same_kind(Type a, Type b) { return (a == Type::String) == (b == Type::String); }

bool inferred(TypeBasis b) { return b != TypeBasis::Manual && b != TypeBasis::Catalogue; }

// PI, TRUE and FALSE (the manual's variables with special values) cannot be redeclared at all.
bool special_value(const GlobalVariable& g) {
  const SystemVariable* s = g.group == Group::System ? find_system_variable(g.name) : nullptr;
  return s && s->source == VariableSource::Constant && s->basis == TypeBasis::Manual;
}

Value zero_of(Type t) {
  switch (t) {
    case Type::Integer: return Value::of_integer(0);
    case Type::Numeric: return Value::of_numeric(0.0);
    case Type::Logical: return Value::of_logical(false);
    case Type::String: break;
  }
  return Value::of_string({});
}

}  // namespace

void Compiler::declare_builtins() {
  for (const SystemVariable& s : system_variables()) {
    if (line_function_named(s.name)) continue;  // start_line/end_line: generate items, not variables
    GlobalVariable v;
    v.name = std::string(s.name);
    v.type = s.type;
    v.group = Group::System;
    v.read_only = s.read_only;
    if (s.rows > 0) v.dimensions.push_back(s.rows);
    if (s.columns > 0) v.dimensions.push_back(s.columns);
    for (int d : v.dimensions) v.cell_count *= std::uint32_t(d);
    v.initial = default_value(s);
    // An inferred type of a value the job supplies is only the default's: the job's first value
    // types the variable (a trace that sends text where we guessed a number is still right).
    v.typed = s.rows > 0 || !(inferred(s.basis) && (s.source == VariableSource::Trace || s.source == VariableSource::Machine));
    add_global(std::move(v));
  }
  for (const HostVariable& h : options_.host_variables) {
    if (globals_.count(lower(h.name)) != 0) continue;  // a system variable, or listed twice
    GlobalVariable v;
    v.name = h.name;
    v.type = h.type;
    v.group = Group::Host;
    v.read_only = h.read_only;
    v.dimensions = h.dimensions;
    std::uint64_t cells = 1;
    for (int d : h.dimensions) cells *= std::uint64_t(std::max(d, 1));
    v.cell_count = std::uint32_t(std::min<std::uint64_t>(cells, kMaxArrayCells));
    v.initial = zero_of(h.type);
    add_global(std::move(v));
  }
  auto slot = [&](std::string_view name) { return program_->globals[globals_.at(std::string(name))].first_cell; };
  SystemSlots& s = program_->slots;
  s.skipline = slot("skipline");
  s.blknum = slot("blknum");
  s.blknum_delta = slot("blknum_delta");
  s.blknum_max = slot("blknum_max");
  s.blknum_exist = slot("blknum_exist");
  s.blknum_gen = slot("blknum_gen");
  s.blknum_letter = slot("blknum_letter");
  s.blknum_f = slot("blknum_f");
  s.integer_def_f = slot("integer_def_f");
  s.numeric_def_f = slot("numeric_def_f");
  s.remove_blanks = slot("remove_blanks");
  s.end_block_text = slot("end_block_text");
  s.gcode_space = slot("gcode_space");
  s.clear_change_after_gen = slot("clear_change_after_gen");
  s.gcode = globals_.at("gcode");
}

void Compiler::declare_all() {
  for (std::uint32_t p = 0; p < procedure_sources_.size(); ++p) {
    if (procedure_sources_[p].header) declare_parameters(*procedure_sources_[p].header, p);
    for (const ParsedLine& line : procedure_sources_[p].body)
      if (line.kind == LineKind::Declaration) declare(line, p);
  }
}

void Compiler::declare_parameters(const ParsedLine& header, std::uint32_t procedure) {
  const auto& children = header.statement().children;
  if (children.size() < 2) return;
  for (const auto& parameter : children[1]->children) {
    const SyntaxNode& name = *parameter->children[1];
    const SourcePos pos = node_pos(name, header.pos.file);
    const std::string key = lower(name.string_view());
    if (line_function_named(key)) {
      error(ErrorCode::InvalidLocal, pos, {}, fmt::format("'{}' is the name of a built-in function", name.string_view()));
      continue;
    }
    if (globals_.count(key) != 0) {  // a system name as a parameter is a local copy, as with `local`
      const GlobalVariable& g = program_->globals[globals_.at(key)];
      if (g.group == Group::Global || special_value(g)) {
        error(g.group == Group::Global ? ErrorCode::AlreadyGlobal : ErrorCode::SystemDeclared, pos, g.name);
        continue;
      }
    }
    declare_local(procedure, name.string_view(), type_of(parameter->children[0]->string_view()), {}, pos,
                  ErrorCode::LocalRedefined);
  }
}

void Compiler::declare(const ParsedLine& line, std::uint32_t procedure) {
  const auto& children = line.statement().children;
  const bool global = same_name(children[0]->string_view(), "global");
  const ErrorCode invalid = global ? ErrorCode::InvalidGlobal : ErrorCode::InvalidLocal;
  const Type type = type_of(children[1]->string_view());
  for (std::size_t i = 2; i < children.size(); ++i) {
    const SyntaxNode& decl = *children[i];
    const SyntaxNode& name_node = *decl.children[0];
    const std::string_view name = name_node.string_view();
    const SourcePos pos = node_pos(name_node, line.pos.file);
    const std::string key = lower(name);
    std::vector<int> dims;
    std::uint64_t cells = 1;
    bool bad = false;
    if (decl.children.size() > 1) {
      for (const auto& d : decl.children[1]->children) {
        long long v = 0;
        const std::string_view text = d->string_view();
        if (text.size() > 5) v = 100000;
        else
          for (char c : text) v = v * 10 + (c - '0');
        if (v <= 0 || v >= 10000) {
          error(invalid, node_pos(*d, line.pos.file), {}, fmt::format("array size {} is not in 1..9999", text));
          bad = true;
        }
        dims.push_back(int(v));
        cells *= std::uint64_t(std::max<long long>(v, 1));
      }
    }
    if (bad) continue;
    if (cells > kMaxArrayCells) {
      error(ErrorCode::SymbolTableFull, pos, {}, fmt::format("array '{}' has more than {} elements", name, kMaxArrayCells));
      continue;
    }
    if (name.size() > 60) {
      error(invalid, pos, {}, "a name has at most 60 characters");
      continue;
    }
    if (find_function(name) != nullptr || line_function_named(name)) {
      error(invalid, pos, {}, fmt::format("'{}' is the name of a built-in function", name));
      continue;
    }
    const auto existing = globals_.find(key);
    if (existing != globals_.end() && program_->globals[existing->second].group != Group::Global) {
      // A name the system (or the host) defines: SolidCAM accepts a local copy of it and a global
      // declaration that matches it; only a global of another kind of value is refused.
      const GlobalVariable& g = program_->globals[existing->second];
      if (special_value(g)) {
        error(ErrorCode::SystemDeclared, pos, g.name);
      } else if (!global) {
        declare_local(procedure, name, type, std::move(dims), pos, ErrorCode::LocalRedefined);
      } else if (!same_kind(g.type, type) || g.dimensions.size() != dims.size()) {
        error(ErrorCode::SystemDeclared, pos, g.name,
              fmt::format("it is {}{}, declared here as {}{}", name_of(g.type), g.dimensions.empty() ? "" : " array",
                          name_of(type), dims.empty() ? "" : " array"));
      } else {
        record(SymbolOf::Global, existing->second, 0, pos, name.size(), false);  // the system's name, agreed to
      }
      continue;
    }
    if (global) {
      if (local_names_.count(key) != 0) {
        error(ErrorCode::AlreadyLocal, pos, name);
        continue;
      }
      if (existing != globals_.end()) {
        const GlobalVariable& g = program_->globals[existing->second];
        if (g.type != type || g.dimensions != dims) error(ErrorCode::GlobalRedefined, pos, name);
        else record(SymbolOf::Global, existing->second, 0, pos, name.size(), true);  // declared again, alike
        continue;
      }
      GlobalVariable v;
      v.name = std::string(name);
      v.type = type;
      v.dimensions = dims;
      v.cell_count = std::uint32_t(cells);
      v.initial = zero_of(type);
      v.declared = pos;
      record(SymbolOf::Global, add_global(std::move(v)), 0, pos, name.size(), true);
    } else {
      if (existing != globals_.end()) {
        error(ErrorCode::AlreadyGlobal, pos, name);
        continue;
      }
      declare_local(procedure, name, type, std::move(dims), pos, ErrorCode::LocalRedefined);
    }
  }
}

void Compiler::declare_local(std::uint32_t procedure, std::string_view name, Type type, std::vector<int> dims,
                             SourcePos pos, ErrorCode redefined) {
  ProcedureSource& source = procedure_sources_[procedure];
  Procedure& proc = program_->procedures[procedure];
  const std::string key = lower(name);
  if (auto it = source.locals.find(key); it != source.locals.end()) {
    const LocalVariable& l = proc.locals[it->second];
    if (l.type != type || l.dimensions != dims) error(redefined, pos, name);
    else record(SymbolOf::Local, it->second, procedure, pos, name.size(), true);
    return;
  }
  LocalVariable l;
  l.name = std::string(name);
  l.type = type;
  l.cell_count = 1;
  for (int d : dims) l.cell_count *= std::uint32_t(d);
  l.dimensions = std::move(dims);
  l.offset = proc.frame_size;
  proc.frame_size += l.cell_count;
  source.locals.emplace(key, std::uint32_t(proc.locals.size()));
  proc.locals.push_back(std::move(l));
  local_names_.emplace(key, pos);
  record(SymbolOf::Local, std::uint32_t(proc.locals.size() - 1), procedure, pos, name.size(), true);
}

std::optional<std::uint32_t> Compiler::lookup_global(std::string_view name) const {
  const auto it = globals_.find(lower(name));
  if (it == globals_.end()) return std::nullopt;
  return it->second;
}

}  // namespace gppl
