// Loading and procedure structure (spec 1.1, 5.8, 10); the declarations are in declarations.cpp.
#include "gppl/compile/compiler.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "gppl/error_codes.hpp"
#include "gppl/symbols.hpp"
#include "gppl/compile/grammar.hpp"

namespace gppl {

namespace g = gppl::grammar;
namespace fs = std::filesystem;

namespace {

constexpr int kMaxIncludeDepth = 16;

// Posts are kilobytes: reading stops at 64 MiB (a wrong file, /dev/zero as an include) with an
// error rather than taking memory without bound.
constexpr std::size_t kMaxSource = std::size_t{64} << 20;

// Ok, or why the file is not read: it cannot be opened (error 399), or it was opened but is too
// large or failed while being read (error 426, `detail` saying which).
enum class ReadResult { Ok, CannotOpen, Failed };

ReadResult read_bytes(const std::string& path, std::string& out, std::string& detail) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return ReadResult::CannotOpen;
  out.clear();
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    out.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (out.size() > kMaxSource) {
      detail = "larger than 64 MiB: not a GPPL post?";
      return ReadResult::Failed;
    }
  }
  if (!in.bad()) return ReadResult::Ok;
  detail = std::string("read error: ") + std::strerror(errno);  // a folder: "Is a directory"
  return ReadResult::Failed;
}

}  // namespace

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
  program_->warning_details.emplace_back(0, p, std::string(text));
}

void Compiler::record(SymbolOf of, std::uint32_t id, std::uint32_t procedure, SourcePos pos, std::size_t length,
                      bool declaration) {
  SymbolIndex* index = options_.symbols;
  if (!index) return;
  std::uint32_t owner = 0;  // a local's procedure
  if (of == SymbolOf::Local) {
    const auto it = symbol_ids_.find(std::uint64_t(SymbolOf::Procedure) << 62 | procedure);
    if (it == symbol_ids_.end()) return;  // a procedure whose header did not parse
    owner = it->second;
  }
  while (index->files.size() < program_->files.size()) index->files.push_back(program_->files[index->files.size()]);
  const std::uint64_t key = (std::uint64_t(of) << 62) | (std::uint64_t(of == SymbolOf::Local ? procedure : 0) << 32) | id;
  auto [it, added] = symbol_ids_.emplace(key, std::uint32_t(index->symbols.size()));
  if (added) {
    Symbol s;
    s.where = program_->position(pos);
    s.declared = declaration;
    if (of == SymbolOf::Procedure) {
      s.kind = SymbolKind::Procedure;
      s.name = program_->procedures[id].name;
    } else if (of == SymbolOf::Local) {
      const LocalVariable& l = program_->procedures[procedure].locals[id];
      s.kind = SymbolKind::Local;
      s.name = l.name;
      s.type = l.type;
      s.dimensions = l.dimensions;
      s.procedure = owner;
    } else {
      const GlobalVariable& g = program_->globals[id];
      s.kind = g.group == Group::System ? SymbolKind::System
               : g.group == Group::Global ? SymbolKind::Global
                                          : SymbolKind::Host;
      s.name = g.name;
      s.type = g.type;
      s.dimensions = g.dimensions;
      if (g.group == Group::Global) {  // its declaration, wherever the first use is
        s.where = program_->position(g.declared);
        s.declared = true;
      }
    }
    index->symbols.push_back(std::move(s));
  } else if (declaration && !index->symbols[it->second].declared) {
    index->symbols[it->second].where = program_->position(pos);
    index->symbols[it->second].declared = true;
  }
  index->uses.push_back({it->second, pos.file, pos.line, pos.column, std::uint32_t(length), declaration});
}

std::uint32_t Compiler::add_global(GlobalVariable v) {
  v.first_cell = program_->global_cells;
  program_->global_cells += v.cell_count;
  const auto id = std::uint32_t(program_->globals.size());
  globals_.emplace(lower(v.name), id);
  program_->globals.push_back(std::move(v));
  return id;
}

std::shared_ptr<const Program> Compiler::compile_file(const std::string& path) {
  auto source = std::make_unique<SourceText>();
  source->name = path;
  std::string detail;
  if (const ReadResult r = read_bytes(path, source->bytes, detail); r != ReadResult::Ok) {
    program_->files.push_back(path);
    errors_.push_back(r == ReadResult::CannotOpen ? make_error(ErrorCode::CantOpen, Position{path, 1, 1}, path)
                                                  : make_error(ErrorCode::ReadError, Position{path, 1, 1}, path, detail));
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
  const bool named = source.header != nullptr;
  program_->procedures.push_back(std::move(proc));
  procedure_sources_.push_back(std::move(source));
  if (named) {
    const auto id = std::uint32_t(program_->procedures.size() - 1);
    record(SymbolOf::Procedure, id, 0, program_->procedures[id].pos, program_->procedures[id].name.size(), true);
  }
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
    std::string detail;
    if (const ReadResult r = read_bytes(source->name, source->bytes, detail); r != ReadResult::Ok) {
      if (r == ReadResult::CannotOpen)
        error(ErrorCode::CantOpen, line.pos, source->name);
      else
        error(ErrorCode::ReadError, line.pos, source->name, detail);
      return;
    }
    include_chain_.push_back(canonical);
    load(std::move(source), depth + 1);
    include_chain_.pop_back();
    return;
  }
  error(ErrorCode::CantOpen, line.pos, file);
}

std::shared_ptr<const Program> Compiler::finish() {
  declare_all();
  for (std::uint32_t p = 0; p < procedure_sources_.size(); ++p) compile_procedure(p);
  if (!errors_.empty()) throw Errors(std::move(errors_));
  if (options_.inline_leaf_calls) inline_leaf_calls(*program_);
  for (const auto& [key, id] : globals_) program_->global_index.emplace(key, id);
  for (const auto& [key, id] : procedures_) program_->procedure_index.emplace(key, id);
  return program_;
}

}  // namespace gppl
