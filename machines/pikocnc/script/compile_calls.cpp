// Designators (variables, fields, elements, constants) and calls of the script's routines and of
// the built-ins, with their argument counts and types checked.
#include "machines/pikocnc/script/compile_support.hpp"

namespace pikocnc::script {

namespace g = grammar;

namespace {

ExprPtr make(Op op, Pos pos, Type type) {
  auto e = std::make_unique<Expr>();
  e->op = op;
  e->pos = pos;
  e->type = type;
  return e;
}

std::vector<const Node*> arg_nodes(const Node* args) {
  std::vector<const Node*> out;
  if (args)
    for (const auto& a : args->children) out.push_back(a.get());
  return out;
}

}  // namespace

ExprPtr Compiler::designator(const Node& node, bool assign_target) {
  const Node& first = *node.children.front();
  const std::string_view name = token(first);
  const std::string key = fold(name);
  const Pos at = pos(first);
  const Node* args = node.children.size() > 1 && is<g::args>(*node.children[1]) ? node.children[1].get() : nullptr;
  std::size_t next = 1;
  ExprPtr e;
  const auto local = current_ ? locals_.find(key) : locals_.end();
  const Symbol* symbol = lookup(key);
  if (assign_target && current_ && current_->is_function && key == fold(current_->name) && !args) {
    e = make(Op::Local, at, current_->result);
    e->slot = 0;
  } else if (symbol && (symbol->what == Symbol::What::Var || symbol->what == Symbol::What::Const)) {
    const bool is_local = current_ && local != locals_.end();
    if (symbol->what == Symbol::What::Const) {
      const auto& folded = folded_[is_local ? 1 : 0];
      if (auto it = folded.find(key); it != folded.end() && !assign_target) {
        e = make(Op::Literal, at, symbol->type);
        e->literal = it->second;
        e->readonly = true;
      }
    }
    if (!e) {
      e = make(is_local ? (symbol->by_ref ? Op::RefParam : Op::Local) : Op::Global, at, symbol->type);
      e->slot = symbol->slot;
      e->readonly = symbol->what == Symbol::What::Const;
    }
  } else if (symbol && symbol->what == Symbol::What::Routine) {
    e = call(first, symbol->slot, args);
    if (args) next = 2;
  } else if (symbol && symbol->what == Symbol::What::TypeName) {
    fail(first, fmt::format("`{}` is a type, not a value", name));
  } else if (const Builtin* b = find_builtin(key)) {
    e = builtin_call(first, *b, args);
    if (args) next = 2;
  } else if (const int pre = find_predefined(key); pre >= 0) {
    e = make(Op::Predefined, at, {predefined_constants()[std::size_t(pre)].integer ? Kind::Integer : Kind::Float});
    e->slot = pre;
    e->readonly = true;
  } else {
    fail(first, fmt::format("unknown identifier `{}`", name));
  }
  for (std::size_t i = next; i < node.children.size(); ++i) {
    const Node& suffix = *node.children[i];
    if (is<g::field_sel>(suffix)) {
      const Node& field = *suffix.children.front();
      if (e->type.kind != Kind::Record)
        fail(field, fmt::format("`.{}`: {} is not a record", token(field), describe(e->type)));
      const Shape& shape = program_->shapes[std::size_t(e->type.shape)];
      const std::string f = fold(token(field));
      std::size_t index = 0;
      while (index < shape.fields.size() && shape.fields[index] != f) ++index;
      if (index == shape.fields.size()) fail(field, fmt::format("{} has no field `{}`", shape.name, token(field)));
      auto x = make(Op::Field, pos(field), shape.field_types[index]);
      x->slot = std::int32_t(index);
      x->readonly = e->readonly;
      x->kids.push_back(std::move(e));
      e = std::move(x);
    } else if (is<g::index_sel>(suffix)) {
      if (e->type.kind != Kind::Array) fail(suffix, fmt::format("{} is not an array", describe(e->type)));
      const Shape& shape = program_->shapes[std::size_t(e->type.shape)];
      auto x = make(Op::Index, pos(suffix), shape.element);
      x->readonly = e->readonly;
      x->kids.push_back(std::move(e));
      x->kids.push_back(convert(expr(*suffix.children.front()), {Kind::Integer}, suffix, "an array index"));
      e = std::move(x);
    } else {
      fail(suffix, "this value cannot be called: it is not a routine");
    }
  }
  return e;
}

ExprPtr Compiler::call(const Node& at, std::int32_t index, const Node* args) {
  const Routine& r = program_->routines[std::size_t(index)];
  const auto given = arg_nodes(args);
  if (given.size() != r.params.size())
    fail(at, fmt::format("`{}` takes {} argument(s), {} given", r.name, r.params.size(), given.size()));
  auto e = make(Op::Call, pos(at), r.is_function ? r.result : Type{Kind::Void});
  e->slot = index;
  for (std::size_t i = 0; i < given.size(); ++i) {
    ExprPtr a = expr(*given[i]);
    const std::string what = fmt::format("argument {} of `{}`", i + 1, r.name);
    if (r.by_ref[i]) {
      if (!a->lvalue() || a->readonly) fail(*given[i], what + " must be a variable (it is a var parameter)");
      if (!(a->type == r.params[i])) fail(*given[i], fmt::format("type mismatch: {} expects a {} variable, got {}", what, describe(r.params[i]), describe(a->type)));
    } else {
      a = convert(std::move(a), r.params[i], *given[i], what);
    }
    e->kids.push_back(std::move(a));
  }
  return e;
}

ExprPtr Compiler::builtin_call(const Node& at, const Builtin& b, const Node* args) {
  const auto given = arg_nodes(args);
  if (given.size() < b.min_args || given.size() > b.params.size()) {
    std::string count = b.min_args == b.params.size() ? fmt::format("{}", b.params.size())
                                                       : fmt::format("{} to {}", b.min_args, b.params.size());
    std::string hint = b.id == B::Write ? " (Write writes the G-code line set up by SetX, SetG, ...; there is no text output)" : "";
    fail(at, fmt::format("`{}` takes {} argument(s), {} given{}", b.name, count, given.size(), hint));
  }
  Type result = b.result;
  auto e = make(Op::Builtin, pos(at), result);
  e->slot = std::int32_t(b.id);
  bool all_integer = true;
  for (std::size_t i = 0; i < given.size(); ++i) {
    ExprPtr a = expr(*given[i]);
    const std::string what = fmt::format("argument {} of `{}`", i + 1, b.name);
    const Type& want = b.params[i];
    const bool by_ref = (b.last_by_ref && i + 1 == b.params.size()) || ((b.id == B::Inc || b.id == B::Dec) && i == 0);
    if (by_ref) {
      if (!a->lvalue() || a->readonly) fail(*given[i], what + " must be a variable (it is a var parameter)");
      if (a->type.kind != want.kind || a->type.shape != want.shape)
        fail(*given[i], fmt::format("type mismatch: {} expects a {} variable, got {}", what, describe(want), describe(a->type)));
    } else if (b.numeric_same) {
      if (a->type.kind != Kind::Integer && a->type.kind != Kind::Float && a->type.kind != Kind::Variant)
        fail(*given[i], fmt::format("type mismatch: {} expects a number, got {}", what, describe(a->type)));
      if (a->type.kind != Kind::Integer) all_integer = false;
    } else if (want.kind == Kind::Variant) {
      if (a->type.kind == Kind::Record || a->type.kind == Kind::Array || a->type.kind == Kind::Void)
        fail(*given[i], fmt::format("type mismatch: {} expects a simple value, got {}", what, describe(a->type)));
    } else {
      a = convert(std::move(a), want, *given[i], what);
    }
    e->kids.push_back(std::move(a));
  }
  if (b.numeric_same) {
    // Delphi's Abs/Sqr/Min/Max keep integers integral.
    if (!all_integer) for (auto& k : e->kids) k = convert(std::move(k), {Kind::Float}, at, "argument");
    e->type = {all_integer ? Kind::Integer : Kind::Float};
  }
  return e;
}

}  // namespace pikocnc::script
