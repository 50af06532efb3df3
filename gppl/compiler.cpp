// Loading, procedure structure (spec 1.1, 5.8, 10) and static declarations (3.2-3.4).
#include "gppl/compiler.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "gppl/display_format.hpp"
#include "gppl/error_codes.hpp"
#include "gppl/grammar.hpp"
#include "gppl/system_variables.hpp"

namespace gppl {

namespace g = gppl::grammar;
namespace fs = std::filesystem;

namespace {

constexpr int kMaxIncludeDepth = 16;
constexpr std::uint64_t kMaxArrayCells = 1'000'000;

bool read_bytes(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

Type type_of(std::string_view word) {
  if (same_name(word, "integer")) return Type::Integer;
  if (same_name(word, "numeric")) return Type::Numeric;
  if (same_name(word, "logical")) return Type::Logical;
  return Type::String;
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

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return r;
}

bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = char(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = char(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

Compiler::Compiler(const CompileOptions& options) : options_(options), program_(std::make_shared<Program>()) {
  declare_builtins();
}

void Compiler::error(ErrorCode code, SourcePos pos, std::string_view name, std::string_view detail) {
  errors_.push_back(make_error(code, program_->position(pos), name, detail));
}

void Compiler::warn(SourcePos pos, std::string_view text) {
  const Position p = program_->position(pos);
  program_->warnings.push_back(fmt::format("{}:{}:{}: warning: {}", p.file, p.line, p.column, text));
}

std::uint32_t Compiler::add_global(GlobalVariable v) {
  v.first_cell = program_->global_cells;
  program_->global_cells += v.cell_count;
  const auto id = std::uint32_t(program_->globals.size());
  globals_.emplace(lower(v.name), id);
  program_->globals.push_back(std::move(v));
  return id;
}

void Compiler::declare_builtins() {
  for (const SystemVariable& s : system_variables()) {
    GlobalVariable v;
    v.name = std::string(s.name);
    v.type = s.type;
    v.group = Group::System;
    v.read_only = s.read_only;
    switch (s.type) {
      case Type::Integer: v.initial = Value::of_integer(std::int64_t(s.number)); break;
      case Type::Numeric: v.initial = Value::of_numeric(s.number); break;
      case Type::Logical: v.initial = Value::of_logical(s.number != 0); break;
      case Type::String: v.initial = Value::of_string(std::string(s.text)); break;
    }
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

std::shared_ptr<const Program> Compiler::compile_file(const std::string& path) {
  auto source = std::make_unique<SourceText>();
  source->name = path;
  if (!read_bytes(path, source->bytes)) {
    program_->files.push_back(path);
    errors_.push_back(make_error(ErrorCode::CantOpen, Position{path, 1, 1}, path));
    throw Errors(std::move(errors_));
  }
  std::error_code ec;
  include_chain_.push_back(fs::weakly_canonical(path, ec).string());
  load(std::move(source), 0);
  return finish();
}

std::shared_ptr<const Program> Compiler::compile_source(std::string_view text, const std::string& name) {
  auto source = std::make_unique<SourceText>();
  source->name = name;
  source->bytes = std::string(text);
  include_chain_.push_back(name);
  load(std::move(source), 0);
  return finish();
}

void Compiler::load(std::unique_ptr<SourceText> source, int depth) {
  split_lines(*source);
  const auto file = std::uint32_t(program_->files.size());
  program_->files.push_back(source->name);
  const SourceText& src = *source;
  sources_.push_back(std::move(source));
  std::optional<std::uint32_t> open;  // procedure being read
  bool init_inc_seen = false;
  for (std::uint32_t n = 1; n <= src.lines.size(); ++n) {
    ParsedLine line = parse_line(src, file, n, errors_);
    if (line.kind == LineKind::Blank) continue;
    if (!open) {
      if (line.kind == LineKind::Header) {
        if (line.valid()) {
          const std::string name = lower(line.statement().children.front()->string_view());
          if (name == "@init_inc") {
            if (init_inc_seen) {
              error(ErrorCode::ProcDefined, line.pos, "@init_inc", "a file may define @init_inc only once");
              line.root.reset();
            }
            init_inc_seen = true;
          }
        }
        open = std::uint32_t(procedure_sources_.size());
        start_procedure(line, file);
      } else if (line.kind == LineKind::Include) {
        if (line.valid()) load_include(line, src, depth);
      } else if (line.kind == LineKind::Endp) {
        error(ErrorCode::Unrecognized, line.pos, {}, "ENDP without a procedure header");
      } else if (line.valid()) {
        error(ErrorCode::Unrecognized, line.pos, {},
              "statements are allowed only inside a procedure (between @name and ENDP)");
      }
      continue;
    }
    ProcedureSource& current = procedure_sources_[*open];
    const Procedure& proc = program_->procedures[*open];
    switch (line.kind) {
      case LineKind::Header:
        error(ErrorCode::MissingEndp, line.pos, {},
              fmt::format("procedure {} opened at line {} has no ENDP", proc.name, proc.pos.line));
        current.end = line.pos;
        open = std::uint32_t(procedure_sources_.size());
        start_procedure(line, file);
        break;
      case LineKind::Endp: current.end = line.pos; open.reset(); break;
      case LineKind::Include:
        error(ErrorCode::Unrecognized, line.pos, {}, "INC is allowed only between procedures");
        break;
      default:
        if (line.valid()) current.body.push_back(std::move(line));
        break;
    }
  }
  if (open) {
    const Procedure& proc = program_->procedures[*open];
    const SourcePos at{file, std::uint32_t(std::max<std::size_t>(src.lines.size(), 1)), 1};
    procedure_sources_[*open].end = at;
    error(ErrorCode::MissingEndp, at, {},
          fmt::format("procedure {} opened at line {} has no ENDP", proc.name, proc.pos.line));
  }
}

void Compiler::start_procedure(ParsedLine& header, std::uint32_t file) {
  Procedure proc;
  proc.pos = header.pos;
  ProcedureSource source;
  source.file = file;
  if (header.valid()) {
    const SyntaxNode& name = *header.statement().children.front();
    proc.name = std::string(name.string_view());
    proc.pos = node_pos(name, file);
    const std::string key = lower(proc.name);
    const auto id = std::uint32_t(program_->procedures.size());
    if (key == "@init_inc") {
      program_->init_inc.push_back(id);
    } else if (auto it = procedures_.find(key); it != procedures_.end()) {
      const Procedure& first = program_->procedures[it->second];
      const Position p = program_->position(first.pos);
      error(ErrorCode::ProcDefined, proc.pos, proc.name, fmt::format("first defined at {}:{}", p.file, p.line));
      proc.defined = false;
    } else {
      procedures_.emplace(key, id);
      if (key == "@init_post") program_->init_post = id;
    }
    if (header.statement().children.size() > 1)
      proc.parameter_count = std::uint32_t(header.statement().children[1]->children.size());
    source.header = std::make_unique<ParsedLine>(std::move(header));
  } else {
    proc.defined = false;  // a broken header: its body is still read so that ENDP pairs up
  }
  program_->procedures.push_back(std::move(proc));
  procedure_sources_.push_back(std::move(source));
}

void Compiler::load_include(const ParsedLine& line, const SourceText& from, int depth) {
  const SyntaxNode& literal = *line.statement().children.front();
  std::string file = literal_text(literal, line.pos.file);
  if (fs::path(file).extension().empty()) file += ".gpp";
  if (depth + 1 > kMaxIncludeDepth) {
    error(ErrorCode::Unrecognized, line.pos, {}, fmt::format("includes nest deeper than {} levels", kMaxIncludeDepth));
    return;
  }
  std::vector<fs::path> candidates{fs::path(from.name).parent_path() / file};
  for (const std::string& dir : options_.include_paths) candidates.push_back(fs::path(dir) / file);
  for (const fs::path& candidate : candidates) {
    std::error_code ec;
    if (!fs::is_regular_file(candidate, ec)) continue;
    const std::string canonical = fs::weakly_canonical(candidate, ec).string();
    if (std::find(include_chain_.begin(), include_chain_.end(), canonical) != include_chain_.end()) {
      error(ErrorCode::Unrecognized, line.pos, {},
            fmt::format("'{}' includes itself (directly or through other files)", file));
      return;
    }
    auto source = std::make_unique<SourceText>();
    source->name = candidate.lexically_normal().string();
    if (!read_bytes(source->name, source->bytes)) {
      error(ErrorCode::ReadError, line.pos, source->name);
      return;
    }
    include_chain_.push_back(canonical);
    load(std::move(source), depth + 1);
    include_chain_.pop_back();
    return;
  }
  error(ErrorCode::CantOpen, line.pos, file);
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
    if (globals_.count(key) != 0) {
      const GlobalVariable& g = program_->globals[globals_.at(key)];
      error(g.group == Group::Global ? ErrorCode::AlreadyGlobal : ErrorCode::SystemDeclared, pos, g.name);
      continue;
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
      error(ErrorCode::SystemDeclared, pos, program_->globals[existing->second].name);
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
        continue;
      }
      GlobalVariable v;
      v.name = std::string(name);
      v.type = type;
      v.dimensions = dims;
      v.cell_count = std::uint32_t(cells);
      v.initial = zero_of(type);
      v.declared = pos;
      add_global(std::move(v));
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
}

std::optional<std::uint32_t> Compiler::lookup_global(std::string_view name) const {
  const auto it = globals_.find(lower(name));
  if (it == globals_.end()) return std::nullopt;
  return it->second;
}

std::shared_ptr<const Program> Compiler::finish() {
  declare_all();
  for (std::uint32_t p = 0; p < procedure_sources_.size(); ++p) compile_procedure(p);
  if (!errors_.empty()) throw Errors(std::move(errors_));
  for (const auto& [key, id] : globals_) program_->global_index.emplace(key, id);
  for (const auto& [key, id] : procedures_) program_->procedure_index.emplace(key, id);
  return program_;
}

}  // namespace gppl
