// Code generation: statements to flat instructions with jump targets (5.5-5.9), expressions to the
// node arena (4.2), generate statements to item lists (6.1); every name resolved to a slot here.
#include <fmt/format.h>

#include <charconv>
#include <cstdlib>

#include "gppl/compile/compiler.hpp"
#include "gppl/builtins/display_format.hpp"
#include "gppl/error_codes.hpp"
#include "gppl/compile/grammar.hpp"

namespace gppl {

namespace g = gppl::grammar;

namespace {

constexpr int kMaxNesting = 8;  // if and while levels each (5.5, 5.6)

BinaryOp relation(std::string_view op) {
  if (op == "==" || op == "=" || same_name(op, "eq")) return BinaryOp::Eq;
  if (op == "!=" || op == "<>" || same_name(op, "ne")) return BinaryOp::Ne;
  if (op == "<" || same_name(op, "lt")) return BinaryOp::Lt;
  if (op == "<=" || same_name(op, "le")) return BinaryOp::Le;
  if (op == ">" || same_name(op, "gt")) return BinaryOp::Gt;
  return BinaryOp::Ge;
}

}  // namespace

std::uint32_t Compiler::emit(OpCode op, SourcePos pos, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  program_->code.push_back(Instruction{op, a, b, c, pos});
  return std::uint32_t(program_->code.size() - 1);
}

void Compiler::compile_procedure(std::uint32_t procedure) {
  ProcedureSource& source = procedure_sources_[procedure];
  Context ctx{procedure, source.file};
  std::vector<Block> blocks;
  const auto first = std::uint32_t(program_->code.size());
  for (const ParsedLine& line : source.body) compile_line(line, ctx, blocks);
  close_blocks(blocks, source.end);
  emit(OpCode::Return, source.end);
  Procedure& proc = program_->procedures[procedure];
  proc.first = first;
  proc.end = std::uint32_t(program_->code.size());
}

void Compiler::close_blocks(std::vector<Block>& blocks, SourcePos at) {
  while (!blocks.empty()) {
    const Block& b = blocks.back();
    const bool loop = b.kind == LineKind::While;
    const std::string text = fmt::format("{} statement missing: the {} at line {} is not closed",
                                         loop ? "ENDW" : "ENDIF", loop ? "WHILE" : "IF", b.pos.line);
    errors_.push_back(Error(int(ErrorCode::MissingEndif), program_->position(at), text));
    program_->code[b.jump].a = std::uint32_t(program_->code.size());
    for (std::uint32_t exit : b.exits) program_->code[exit].a = std::uint32_t(program_->code.size());
    blocks.pop_back();
  }
}

void Compiler::compile_line(const ParsedLine& line, Context& ctx, std::vector<Block>& blocks) {
  const SyntaxNode& st = line.statement();
  const SourcePos pos = line.pos;
  auto depth = [&](bool loops) {
    int n = 0;
    for (const Block& b : blocks) n += (b.kind == LineKind::While) == loops ? 1 : 0;
    return n;
  };
  auto top = [&](LineKind a, LineKind b) { return !blocks.empty() && (blocks.back().kind == a || blocks.back().kind == b); };
  switch (line.kind) {
    case LineKind::Declaration: break;  // bound statically before code generation (3.3)
    case LineKind::Assignment: {
      const std::uint32_t ref = reference(*st.children[0], ctx, true);
      const VarRef& r = program_->refs[ref];
      if (!r.local && program_->globals[r.id].read_only)
        error(ErrorCode::ReadOnly, node_pos(*st.children[0], ctx.file), program_->globals[r.id].name);
      const bool global = !r.local;
      const std::uint32_t target = r.id;  // r goes stale: the expression may add references
      const std::uint32_t value = expression(*st.children[1], ctx);
      if (options_.check_constant_assignments && global) check_constant(program_->globals[target], value);
      emit(OpCode::Assign, pos, ref, value);
      break;
    }
    case LineKind::AttrAssignment: {
      const SyntaxNode& attr = *st.children[0];
      const bool active = attr.children[0]->is_type<g::kw_active>();
      const std::uint32_t ref = reference(*attr.children[1], ctx, true);
      emit(active ? OpCode::SetActive : OpCode::SetChange, pos, ref, expression(*st.children[1], ctx));
      break;
    }
    case LineKind::If: {
      if (depth(false) >= kMaxNesting) error(ErrorCode::TooComplex, pos, {}, "IF statements nest deeper than 8 levels");
      const std::uint32_t cond = expression(*st.children[0], ctx);
      blocks.push_back(Block{LineKind::If, emit(OpCode::JumpIfFalse, pos, 0, cond), 0, pos, {}, {}});
      break;
    }
    case LineKind::Else:
      if (!top(LineKind::If, LineKind::Else)) {
        error(ErrorCode::Unrecognized, pos, {}, "ELSE without an open IF");
      } else if (blocks.back().kind == LineKind::Else) {
        error(ErrorCode::InvalidIf, pos, {}, fmt::format("second ELSE for the IF at line {}", blocks.back().pos.line));
      } else {
        const std::uint32_t jump = emit(OpCode::Jump, pos);
        program_->code[blocks.back().jump].a = std::uint32_t(program_->code.size());
        blocks.back().kind = LineKind::Else;
        blocks.back().jump = jump;
      }
      break;
    case LineKind::Endif:
      if (!top(LineKind::If, LineKind::Else)) {
        error(ErrorCode::Unrecognized, pos, {},
              blocks.empty() ? "ENDIF without an open IF"
                             : fmt::format("ENDIF inside the WHILE at line {} (ENDW missing?)", blocks.back().pos.line));
      } else {
        const auto after = std::uint32_t(program_->code.size());
        program_->code[blocks.back().jump].a = after;
        for (std::uint32_t exit : blocks.back().exits) program_->code[exit].a = after;
        blocks.pop_back();
      }
      break;
    case LineKind::Elseif: elseif_statement(st, ctx, pos, blocks); break;
    case LineKind::While: {
      if (depth(true) >= kMaxNesting) error(ErrorCode::TooComplex, pos, {}, "WHILE loops nest deeper than 8 levels");
      const auto head = std::uint32_t(program_->code.size());
      const std::uint32_t cond = expression(*st.children[0], ctx);
      blocks.push_back(Block{LineKind::While, emit(OpCode::LoopIfFalse, pos, 0, cond), head, pos, {}, {}});
      break;
    }
    case LineKind::Endw:
      if (!top(LineKind::While, LineKind::While)) {
        error(ErrorCode::Unrecognized, pos, {},
              blocks.empty() ? "ENDW without an open WHILE"
                             : fmt::format("ENDW inside the IF at line {} (ENDIF missing?)", blocks.back().pos.line));
      } else {
        emit(OpCode::Jump, pos, blocks.back().head);
        const auto after = std::uint32_t(program_->code.size());
        program_->code[blocks.back().jump].a = after;
        for (std::uint32_t b : blocks.back().breaks) program_->code[b].a = after;
        blocks.pop_back();
      }
      break;
    case LineKind::Call: {
      const SyntaxNode& name = *st.children[0];
      const auto it = procedures_.find(lower(name.string_view()));
      if (it == procedures_.end()) {
        error(ErrorCode::DoesNotExist, node_pos(name, ctx.file), name.string_view(), "no procedure of that name");
        break;
      }
      Procedure& callee = program_->procedures[it->second];
      callee.called = true;
      record(SymbolOf::Procedure, it->second, 0, node_pos(name, ctx.file), name.string_view().size(), false);
      std::vector<std::uint32_t> args;
      if (st.children.size() > 1) {
        for (const auto& arg : st.children[1]->children) {
          if (arg->children.size() > 1)
            error(ErrorCode::InvalidCall, node_pos(*arg->children[1], ctx.file), {}, "a display format is not allowed here");
          args.push_back(expression(*arg->children[0], ctx));
        }
      }
      if (args.size() != callee.parameter_count) {
        error(ErrorCode::InvalidCall, node_pos(name, ctx.file), {},
              fmt::format("{} takes {} argument(s), {} given", callee.name, callee.parameter_count, args.size()));
        break;
      }
      const auto list = std::uint32_t(program_->lists.size());
      program_->lists.insert(program_->lists.end(), args.begin(), args.end());
      emit(OpCode::Call, pos, it->second, list, std::uint32_t(args.size()));
      break;
    }
    case LineKind::Generate: generate(st, ctx, pos); break;
    case LineKind::Input: input_statement(st, ctx, pos); break;
    case LineKind::Print: print_statement(st, ctx, pos); break;
    case LineKind::Trace: {
      // The instruction holds the index of the constant, not of its node.
      const std::uint32_t node = constant(Value::of_string(literal_text(*st.children[0], ctx.file)), pos);
      emit(OpCode::Trace, pos, program_->nodes[node].a, expression(*st.children[1]->children[0], ctx));
      break;
    }
    case LineKind::Stop: {
      const std::string_view word = st.string_view();
      if (same_name(word, "abort")) emit(OpCode::Abort, pos);
      else if (same_name(word, "exit")) emit(OpCode::Exit, pos);
      else if (same_name(word, "return")) emit(OpCode::Return, pos);
      else {
        // break: to the innermost WHILE of this procedure; outside any loop it does nothing (5.9).
        for (auto b = blocks.rbegin(); b != blocks.rend(); ++b) {
          if (b->kind != LineKind::While) continue;
          b->breaks.push_back(emit(OpCode::Jump, pos));
          break;
        }
      }
      break;
    }
    default: break;
  }
}

std::uint32_t Compiler::constant(Value v, SourcePos pos) {
  program_->constants.push_back(std::move(v));
  Node n;
  n.kind = NodeKind::Constant;
  n.simple = true;
  n.a = std::uint32_t(program_->constants.size() - 1);
  n.pos = pos;
  program_->nodes.push_back(n);
  return std::uint32_t(program_->nodes.size() - 1);
}

std::string Compiler::literal_text(const SyntaxNode& literal, std::uint32_t file) {
  std::string warning, problem;
  std::string text = string_value(literal, warning, problem);
  if (!warning.empty()) warn(node_pos(literal, file), warning);
  if (!problem.empty()) error(ErrorCode::Unrecognized, node_pos(literal, file), {}, problem);
  return text;
}

std::uint32_t Compiler::expression(const SyntaxNode& n, Context& ctx) {
  const SourcePos pos = node_pos(n, ctx.file);
  auto unary = [&](NodeKind kind, const SyntaxNode& operand) {
    Node node;
    node.kind = kind;
    node.a = expression(operand, ctx);
    node.pos = pos;
    program_->nodes.push_back(node);
    return std::uint32_t(program_->nodes.size() - 1);
  };
  if (n.is_type<g::num_literal>()) return constant(Value::of_numeric(std::strtod(std::string(n.string_view()).c_str(), nullptr)), pos);
  if (n.is_type<g::int_literal>()) {
    const std::string_view text = n.string_view();
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || v > 999'999'999) {
      error(ErrorCode::Unrecognized, pos, {}, fmt::format("integer literal {} is out of range (at most 999999999)", text));
      v = 0;
    }
    return constant(Value::of_integer(v), pos);
  }
  if (n.is_type<g::string_literal>()) return constant(Value::of_string(literal_text(n, ctx.file)), pos);
  if (n.is_type<g::variable>()) {
    Node node;
    node.kind = NodeKind::Variable;
    node.a = reference(n, ctx, false);
    node.simple = program_->refs[node.a].indices == kNone;
    node.pos = pos;
    program_->nodes.push_back(node);
    return std::uint32_t(program_->nodes.size() - 1);
  }
  if (n.is_type<g::attribute>()) {
    Node node;
    node.kind = NodeKind::Attribute;
    node.active_attribute = n.children[0]->is_type<g::kw_active>();
    node.a = reference(*n.children[1], ctx, false);
    node.simple = program_->refs[node.a].indices == kNone;
    node.pos = pos;
    program_->nodes.push_back(node);
    return std::uint32_t(program_->nodes.size() - 1);
  }
  if (n.is_type<g::func_call>()) return call_node(n, ctx);
  if (n.is_type<g::paren_expr>()) return expression(*n.children[0], ctx);
  if (n.is_type<g::signed_expr>()) {
    if (n.children[0]->string_view() == "+") return expression(*n.children[1], ctx);  // unary plus [I]
    return unary(NodeKind::Negate, *n.children[1]);
  }
  if (n.is_type<g::negation>()) return unary(NodeKind::Not, *n.children[1]);
  return chain(n, ctx);
}

std::uint32_t Compiler::chain(const SyntaxNode& n, Context& ctx) {
  std::uint32_t left = expression(*n.children[0], ctx);
  for (std::size_t i = 1; i + 1 < n.children.size(); i += 2) {
    const SyntaxNode& op = *n.children[i];
    Node node;
    node.pos = node_pos(op, ctx.file);
    const std::string_view text = op.string_view();
    if (op.is_type<g::op_and>()) node.kind = NodeKind::And;
    else if (op.is_type<g::op_or>()) node.kind = NodeKind::Or;
    else {
      node.kind = NodeKind::Binary;
      if (op.is_type<g::op_rel>()) node.op = relation(text);
      else if (text == "+") node.op = BinaryOp::Add;
      else if (text == "-") node.op = BinaryOp::Sub;
      else if (text == "*") node.op = BinaryOp::Mul;
      else if (text == "/") node.op = BinaryOp::Div;
      else node.op = BinaryOp::Pow;
    }
    node.a = left;
    node.b = expression(*n.children[i + 1], ctx);
    if (node.kind == NodeKind::Binary && node.op >= BinaryOp::Eq) simple_relation(node);
    program_->nodes.push_back(node);
    left = std::uint32_t(program_->nodes.size() - 1);
  }
  return left;
}

void Compiler::simple_relation(Node& node) {
  const Node& left = program_->nodes[node.a];
  const Node& right = program_->nodes[node.b];
  if (left.kind != NodeKind::Variable || !left.simple) return;
  auto cell_of = [&](const Node& variable) {
    const VarRef& ref = program_->refs[variable.a];
    return Relation::Cell{ref.cell, ref.local};
  };
  Relation r;
  r.left = cell_of(left);
  r.op = node.op;
  if (right.kind == NodeKind::Variable && right.simple) {
    r.right_is_variable = true;
    r.right = cell_of(right);
  } else if (right.kind == NodeKind::Constant) {
    const Value& c = program_->constants[right.a];
    if (c.type == Type::String) return;  // strings compare as text (or fail): the general path
    r.numeric = c.type == Type::Numeric;
    r.integer = c.type == Type::Logical ? (c.logical ? 1 : 0) : c.integer;
    r.number = c.type == Type::Numeric ? c.numeric : static_cast<double>(r.integer);
  } else {
    return;
  }
  node.simple = true;
  node.list = std::uint32_t(program_->relations.size());
  program_->relations.push_back(r);
}

std::uint32_t Compiler::call_node(const SyntaxNode& n, Context& ctx) {
  const SyntaxNode& name = *n.children[0];
  const SourcePos pos = node_pos(n, ctx.file);
  Node node;
  node.kind = NodeKind::Call;
  node.function = find_function(name.string_view());
  node.pos = pos;
  std::vector<std::uint32_t> args;
  if (n.children.size() > 1) {
    const auto& list = n.children[1]->children;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const SyntaxNode& arg = *list[i];
      const bool shape = i == 0 && node.function->array_argument;  // adims, alen, asize
      args.push_back(shape ? array_argument(*arg.children[0], ctx) : expression(*arg.children[0], ctx));
      if (arg.children.size() < 2) continue;
      if (i != 0 || !node.function->format_argument) {
        error(ErrorCode::Unrecognized, node_pos(*arg.children[1], ctx.file), {},
              "a display format ':' is allowed only in tostr");
        continue;
      }
      node.format = expression(*arg.children[1]->children[0], ctx);
    }
  }
  // tostr's format parameter is written `x : fmt`, never as an argument of its own.
  const std::size_t most = node.function->parameters.size() - (node.function->format_argument ? 1 : 0);
  const std::size_t least = std::min(node.function->min_args, most);
  if (args.size() < least || args.size() > most) {
    error(ErrorCode::Unrecognized, pos, {},
          least == most ? fmt::format("{} takes {} argument(s), {} given", node.function->name, most, args.size())
                        : fmt::format("{} takes {} to {} arguments, {} given", node.function->name, least, most,
                                      args.size()));
  }
  node.list = std::uint32_t(program_->lists.size());
  node.count = std::uint32_t(args.size());
  program_->lists.insert(program_->lists.end(), args.begin(), args.end());
  program_->nodes.push_back(node);
  return std::uint32_t(program_->nodes.size() - 1);
}

// A constant assigned to a global, checked as the run would check it (CompileOptions::
// check_constant_assignments). A format variable is a text variable whose name ends in `_f`.
void Compiler::check_constant(const GlobalVariable& target, std::uint32_t value) {
  const Node& node = program_->nodes[value];
  if (node.kind != NodeKind::Constant || !target.typed || target.group == Group::Implicit) return;
  const Value& v = program_->constants[node.a];
  const bool text = v.type == Type::String;
  if (target.type == Type::String && !text) {
    error(ErrorCode::NotString, node.pos, target.name, "a number assigned to a text variable");
    return;
  }
  if ((target.type == Type::Numeric || target.type == Type::Integer) && text) {
    error(ErrorCode::NotNumeric, node.pos, target.name, "text assigned to a number variable");
    return;
  }
  const std::string& name = target.name;
  const bool format = name.size() > 2 && lower(name.substr(name.size() - 2)) == "_f";
  if (target.type != Type::String || !text || !format) return;
  try {
    parse_display_format(v.text);
  } catch (const Error& e) {
    // Option letters written without their parentheses ('5.3p' for '5.3(p)') are the usual slip.
    std::string hint;
    const std::size_t at = v.text.find_first_of("pPdDnNiI*/", v.text.find('.'));
    if (v.text.find('.') != std::string::npos && at != std::string::npos && v.text.find('(') == std::string::npos) {
      std::string meant = v.text.substr(0, at) + "(" + v.text.substr(at) + ")";
      try {
        parse_display_format(meant);
        hint = fmt::format("; did you mean '{}'?", meant);
      } catch (const Error&) {
      }
    }
    errors_.push_back(Error(e.number(), program_->position(node.pos), e.text() + " (the display format of " + name + ")" + hint));
  }
}

// "did you mean 'xpos'?" for a name nothing declares: the nearest local, global or system variable.
std::string Compiler::did_you_mean(std::string_view name, const Context& ctx) const {
  std::vector<std::string_view> names;
  for (const auto& local : program_->procedures[ctx.procedure].locals) names.push_back(local.name);
  for (const auto& g : program_->globals)
    if (g.group != Group::Implicit) names.push_back(g.name);
  const std::string_view guess = nearest_name(name, names);
  return guess.empty() ? std::string() : fmt::format("did you mean '{}'?", guess);
}

std::uint32_t Compiler::reference(const SyntaxNode& variable, Context& ctx, bool target) {
  const SyntaxNode& id = *variable.children[0];
  const std::string_view name = id.string_view();
  const SourcePos pos = node_pos(id, ctx.file);
  VarRef ref;
  const std::vector<int>* dims = nullptr;
  std::optional<Program::Undeclared> undeclared;
  bool resolved = true;  // false after an error: `ref` names nothing
  const auto& locals = procedure_sources_[ctx.procedure].locals;
  if (auto it = locals.find(lower(name)); it != locals.end()) {
    const LocalVariable& l = program_->procedures[ctx.procedure].locals[it->second];
    ref = VarRef{true, it->second, l.offset, kNone, 0};
    dims = &l.dimensions;
  } else if (auto g = lookup_global(name); g && program_->globals[*g].group != Group::Implicit) {
    ref = VarRef{false, *g, program_->globals[*g].first_cell, kNone, 0};
  } else if (find_function(name) != nullptr) {
    resolved = false;
    error(target ? ErrorCode::InvalidAssignment : ErrorCode::NotDefined, pos, name,
          "a built-in function cannot be used as a variable");
  } else if (line_function_named(name)) {
    resolved = false;
    error(target ? ErrorCode::InvalidAssignment : ErrorCode::NotDefined, pos, name,
          "start_line and end_line are allowed only as items of a generate statement, as in {' N1=' start_line}");
  } else if (options_.implicit_host_variables) {
    // Declared nowhere: the host may still supply it. For a job run (undeclared_from_job) every use
    // is checked when it runs: error 383/404 at this position, as `check` reports it, until the
    // host has assigned it (the job carries it: a machine's user parameter in the trace).
    if (!g) {
      GlobalVariable v;
      v.name = std::string(name);
      v.group = Group::Implicit;
      v.typed = false;
      v.initial = Value::of_integer(0);
      v.declared = pos;
      g = add_global(std::move(v));
    }
    if (options_.undeclared_from_job) {
      ref = VarRef{false, *g, program_->globals[*g].first_cell, kUndeclared, 0};
      undeclared = Program::Undeclared{pos, std::uint32_t(target ? ErrorCode::DoesNotExist : ErrorCode::NotDefined)};
    } else {
      ref = VarRef{false, *g, program_->globals[*g].first_cell, kNone, 0};
      if (program_->globals[*g].declared.line == pos.line && program_->globals[*g].declared.column == pos.column &&
          program_->globals[*g].declared.file == pos.file)
        warn(pos, fmt::format("'{}' is not declared: treated as a host variable", name));
    }
  } else {
    resolved = false;
    error(target ? ErrorCode::DoesNotExist : ErrorCode::NotDefined, pos, name, did_you_mean(name, ctx));
  }
  if (resolved) record(ref.local ? SymbolOf::Local : SymbolOf::Global, ref.id, ctx.procedure, pos, name.size(), false);
  if (!ref.local) dims = &program_->globals[ref.id].dimensions;
  // Counted now: an index expression may declare an implicit global, moving the globals (and dims).
  const std::size_t dim_count = dims->size();
  std::vector<std::uint32_t> indices;
  if (variable.children.size() > 1)
    for (const auto& e : variable.children[1]->children) indices.push_back(expression(*e, ctx));
  // A system array may leave out trailing indices of 1: real posts read SolidCAM's ang_prms both
  // as ang_prms<<i>> and as ang_prms<<1,1>> (SODICK.GPP of majeretft/Cam-posts), so the shorter
  // form names the first column (docs/gppl-language.md, "Arrays").
  if (!undeclared && !ref.local && program_->globals[ref.id].group == Group::System && !indices.empty())
    while (indices.size() < dim_count) indices.push_back(constant(Value::of_integer(1), pos));
  if (undeclared) {
    // its shape is unknown: the use is refused when it runs, whatever its indices
  } else if (dim_count == 0 && !indices.empty()) error(ErrorCode::OutOfRange, pos, {}, fmt::format("'{}' is not an array", name));
  else if (dim_count != 0 && indices.size() != dim_count)
    error(ErrorCode::OutOfRange, pos, {},
          indices.empty() ? fmt::format("array '{}' is used without indices", name)
                          : fmt::format("array '{}' has {} dimension(s)", name, dim_count));
  if (!indices.empty() && !undeclared) {
    ref.indices = std::uint32_t(program_->lists.size());
    ref.index_count = std::uint32_t(indices.size());
    program_->lists.insert(program_->lists.end(), indices.begin(), indices.end());
  }
  program_->refs.push_back(ref);
  const auto index = std::uint32_t(program_->refs.size() - 1);
  if (undeclared) program_->undeclared.emplace(index, *undeclared);
  return index;
}

}  // namespace gppl
