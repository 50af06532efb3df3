// The compiler: loads the main file and its includes, checks the procedure structure, binds
// declarations statically (spec 3.3), resolves every name to a slot and emits the Program.
// Load-time errors are collected and thrown together as gppl::Errors.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "gppl/error_codes.hpp"
#include "gppl/compile/parser.hpp"
#include "gppl/program.hpp"

namespace gppl {

// Copies the bodies of small leaf procedures into their callers (inline_calls.cpp).
void inline_leaf_calls(Program& program);

class Compiler {
public:
  explicit Compiler(const CompileOptions& options);
  std::shared_ptr<const Program> compile_file(const std::string& path);
  std::shared_ptr<const Program> compile_source(std::string_view text, const std::string& name);

private:
  struct ProcedureSource {
    std::uint32_t file = 0;
    std::unique_ptr<ParsedLine> header;  // null when the header line had a syntax error
    std::vector<ParsedLine> body;
    SourcePos end;  // the ENDP line (or where the procedure was found unterminated)
    std::unordered_map<std::string, std::uint32_t> locals;  // lower-case name -> local index
  };
  struct Block {
    LineKind kind;  // If, Else or While
    std::uint32_t jump = 0;  // instruction to patch (JumpIfFalse, else's Jump, or LoopIfFalse)
    std::uint32_t head = 0;  // While: the loop test
    SourcePos pos;
    std::vector<std::uint32_t> breaks;
    std::vector<std::uint32_t> exits;  // If: the jumps to ENDIF at the end of each ELSEIF branch
  };
  struct Context {
    std::uint32_t procedure = 0;
    std::uint32_t file = 0;
  };

  // compiler.cpp: loading, structure, declarations
  std::shared_ptr<const Program> finish();
  void declare_builtins();
  std::uint32_t add_global(GlobalVariable v);
  void load(std::unique_ptr<SourceText> source, int depth);
  void load_include(const ParsedLine& line, const SourceText& from, int depth);
  void start_procedure(ParsedLine& header, std::uint32_t file);
  void declare_all();
  void declare(const ParsedLine& line, std::uint32_t procedure);
  void declare_parameters(const ParsedLine& header, std::uint32_t procedure);
  void declare_local(std::uint32_t procedure, std::string_view name, Type type, std::vector<int> dims,
                     SourcePos pos, ErrorCode redefined);
  void error(ErrorCode code, SourcePos pos, std::string_view name = {}, std::string_view detail = {});
  // The editor's index (CompileOptions::symbols): a declaration or use of a global (by id), a local
  // (procedure, index) or a procedure (id) at `pos`, `length` bytes long.
  enum class SymbolOf : std::uint8_t { Global, Local, Procedure };
  void record(SymbolOf of, std::uint32_t id, std::uint32_t procedure, SourcePos pos, std::size_t length,
              bool declaration);
  void warn(SourcePos pos, std::string_view text);

  // codegen.cpp: statements, expressions, generate
  void compile_procedure(std::uint32_t procedure);
  void compile_line(const ParsedLine& line, Context& ctx, std::vector<Block>& blocks);
  void close_blocks(std::vector<Block>& blocks, SourcePos at);
  std::uint32_t emit(OpCode op, SourcePos pos, std::uint32_t a = 0, std::uint32_t b = 0, std::uint32_t c = 0);
  std::uint32_t expression(const SyntaxNode& n, Context& ctx);
  std::uint32_t chain(const SyntaxNode& n, Context& ctx);
  void simple_relation(Node& node);  // marks `variable op number` comparisons (Program::relations)
  std::uint32_t constant(Value v, SourcePos pos);
  std::uint32_t call_node(const SyntaxNode& n, Context& ctx);
  std::uint32_t reference(const SyntaxNode& variable, Context& ctx, bool target);
  std::string did_you_mean(std::string_view name, const Context& ctx) const;
  void check_constant(const GlobalVariable& target, std::uint32_t value);
  void generate(const SyntaxNode& n, Context& ctx, SourcePos pos);
  // codegen_extensions.cpp: what real posts use beyond the manual (input, print, elseif, adims...)
  void input_statement(const SyntaxNode& st, Context& ctx, SourcePos pos);
  void print_statement(const SyntaxNode& st, Context& ctx, SourcePos pos);
  bool message_item(const SyntaxNode& n, Context& ctx);  // false (and an error) for start_line/end_line
  void elseif_statement(const SyntaxNode& st, Context& ctx, SourcePos pos, std::vector<Block>& blocks);
  std::uint32_t array_argument(const SyntaxNode& arg, Context& ctx);
  void generate_item(const SyntaxNode& n, Context& ctx, bool in_group);
  void collect_refs(std::uint32_t node, std::vector<std::uint32_t>& out) const;
  std::optional<LineFunction> line_function_of(const SyntaxNode& operand) const;
  std::string literal_text(const SyntaxNode& literal, std::uint32_t file);
  std::optional<std::uint32_t> lookup_global(std::string_view name) const;

  CompileOptions options_;
  std::shared_ptr<Program> program_;
  std::vector<Error> errors_;
  std::vector<std::unique_ptr<SourceText>> sources_;
  std::vector<ProcedureSource> procedure_sources_;
  std::vector<std::string> include_chain_;
  std::unordered_map<std::string, std::uint32_t> globals_;     // lower-case name -> GlobalVariable
  std::unordered_map<std::string, std::uint32_t> procedures_;  // lower-case name -> Procedure
  std::unordered_map<std::string, SourcePos> local_names_;     // any procedure's locals, first declaration
  std::unordered_map<std::uint64_t, std::uint32_t> symbol_ids_;  // (SymbolOf, procedure, id) -> symbols
};

// start_line / end_line (case-insensitive): names reserved for the host item functions.
std::optional<LineFunction> line_function_named(std::string_view name);

}  // namespace gppl
