// Code generation of what real posts use beyond the manual (solidcam-behaviour.md 2a; documented
// in docs/gppl-language.md): `elseif`, `input`, `print`, and the array argument of adims, alen
// and asize.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "gppl/compile/compiler.hpp"
#include "gppl/error_codes.hpp"
#include "gppl/compile/grammar.hpp"

namespace gppl {

namespace g = gppl::grammar;

// `elseif` continues the open IF at the same depth: it does not count towards the 8 levels.
void Compiler::elseif_statement(const SyntaxNode& st, Context& ctx, SourcePos pos, std::vector<Block>& blocks) {
  if (blocks.empty() || blocks.back().kind == LineKind::While) {
    error(ErrorCode::Unrecognized, pos, {},
          blocks.empty() ? "ELSEIF without an open IF"
                         : fmt::format("ELSEIF inside the WHILE at line {} (ENDW missing?)", blocks.back().pos.line));
    return;
  }
  Block& block = blocks.back();
  if (block.kind == LineKind::Else) {
    error(ErrorCode::InvalidIf, pos, {}, fmt::format("ELSEIF after the ELSE of the IF at line {}", block.pos.line));
    return;
  }
  // The branch before ends with a jump to ENDIF; the previous test, when false, comes here.
  block.exits.push_back(emit(OpCode::Jump, pos));
  program_->code[block.jump].a = std::uint32_t(program_->code.size());
  const std::uint32_t cond = expression(*st.children[0], ctx);
  block.jump = emit(OpCode::JumpIfFalse, pos, 0, cond);
}

bool Compiler::message_item(const SyntaxNode& n, Context& ctx) {
  const auto index = std::uint32_t(program_->items.size());
  generate_item(n, ctx, false);
  if (program_->items[index].kind != ItemKind::LineFunction) return true;
  error(ErrorCode::NotDefined, program_->items[index].pos, {},
        "start_line and end_line are allowed only as items of a generate statement");
  return false;
}

void Compiler::input_statement(const SyntaxNode& st, Context& ctx, SourcePos pos) {
  InputStatement input;
  input.pos = pos;
  input.prompt = std::uint32_t(program_->items.size());
  if (!message_item(*st.children[0], ctx)) return;
  const SyntaxNode& variable = *st.children[1];
  input.target = reference(variable, ctx, true);
  input.name = std::string(variable.children[0]->string_view());
  const VarRef& r = program_->refs[input.target];
  if (r.local) {
    input.type = program_->procedures[ctx.procedure].locals[r.id].type;
  } else {
    const GlobalVariable& v = program_->globals[r.id];
    if (v.read_only) error(ErrorCode::ReadOnly, node_pos(variable, ctx.file), v.name);
    if (v.typed) input.type = v.type;
  }
  program_->inputs.push_back(std::move(input));
  emit(OpCode::Input, pos, std::uint32_t(program_->inputs.size() - 1));
}

void Compiler::print_statement(const SyntaxNode& st, Context& ctx, SourcePos pos) {
  const auto first = std::uint32_t(program_->items.size());
  for (const auto& item : st.children)
    if (!message_item(*item, ctx)) return;
  emit(OpCode::Print, pos, first, std::uint32_t(program_->items.size()) - first);
}

// The shape of the array named by `arg`, as the constant text "3,4" ("" for a scalar).
std::uint32_t Compiler::array_argument(const SyntaxNode& arg, Context& ctx) {
  const SourcePos pos = node_pos(arg, ctx.file);
  if (!arg.is_type<g::variable>() || arg.children.size() != 1) {
    error(ErrorCode::Unrecognized, pos, {}, "the argument must name an array variable, without indices");
    return constant(Value::of_string({}), pos);
  }
  const std::string_view name = arg.children[0]->string_view();
  const std::vector<int>* dims = nullptr;
  const auto& locals = procedure_sources_[ctx.procedure].locals;
  if (auto it = locals.find(lower(name)); it != locals.end())
    dims = &program_->procedures[ctx.procedure].locals[it->second].dimensions;
  else if (auto id = lookup_global(name))
    dims = &program_->globals[*id].dimensions;
  if (!dims) {
    error(ErrorCode::NotDefined, pos, name);
    return constant(Value::of_string({}), pos);
  }
  return constant(Value::of_string(fmt::format("{}", fmt::join(*dims, ","))), pos);
}

}  // namespace gppl
