// Statements (spec 2.2): assignments, calls, blocks and the control structures.
#include "machines/pikocnc/script/compile_support.hpp"

namespace pikocnc::script {

namespace g = grammar;

namespace {

StmtPtr make(St kind, Pos pos) {
  auto s = std::make_unique<Stmt>();
  s->kind = kind;
  s->pos = pos;
  return s;
}

}  // namespace

StmtPtr Compiler::statements(const Node& list, St kind) {
  auto s = make(kind, pos(list));
  for (const auto& child : list.children) {
    auto st = statement(*child);
    if (st->kind != St::Empty) s->body.push_back(std::move(st));
  }
  return s;
}

StmtPtr Compiler::statement(const Node& body) {
  if (body.children.empty()) return make(St::Empty, pos(body));
  const Node& n = *body.children.front();
  const Pos at = pos(n);
  auto condition = [&](const Node& e) { return convert(expr(e), {Kind::Boolean}, e, "a condition"); };
  auto loop_body = [&](const Node& b) {
    ++loops_;
    auto s = statement(b);
    --loops_;
    return s;
  };
  if (is<g::block>(n)) return statements(*n.children.front(), St::Block);
  if (is<g::if_stmt>(n)) {
    auto s = make(St::If, at);
    s->value = condition(*n.children[0]);
    s->body.push_back(statement(*n.children[1]));
    if (n.children.size() > 2) s->body.push_back(statement(*n.children[2]));
    return s;
  }
  if (is<g::while_stmt>(n)) {
    auto s = make(St::While, at);
    s->value = condition(*n.children[0]);
    s->body.push_back(loop_body(*n.children[1]));
    return s;
  }
  if (is<g::repeat_stmt>(n)) {
    ++loops_;
    auto s = statements(*n.children[0], St::Repeat);
    --loops_;
    s->pos = at;
    s->value = condition(*n.children[1]);
    return s;
  }
  if (is<g::for_stmt>(n)) {
    const Node& var = *n.children[0];
    const Symbol* sym = lookup(fold(token(var)));
    if (!sym || sym->what != Symbol::What::Var)
      fail(var, fmt::format("`{}`: a for loop needs a variable to count with", token(var)));
    if (sym->type.kind != Kind::Integer)
      fail(var, fmt::format("`{}` is {}: a for loop counts with an Integer variable", token(var), describe(sym->type)));
    auto s = make(is<g::dir_downto>(*n.children[2]) ? St::ForDown : St::ForUp, at);
    s->target = std::make_unique<Expr>();
    const bool is_local = current_ && locals_.count(fold(token(var)));
    s->target->op = is_local ? (sym->by_ref ? Op::RefParam : Op::Local) : Op::Global;
    s->target->slot = sym->slot;
    s->target->type = sym->type;
    s->target->pos = pos(var);
    s->value = convert(expr(*n.children[1]), {Kind::Integer}, *n.children[1], "the for loop's start");
    s->limit = convert(expr(*n.children[3]), {Kind::Integer}, *n.children[3], "the for loop's end");
    s->body.push_back(loop_body(*n.children[4]));
    return s;
  }
  if (is<g::case_stmt>(n)) {
    auto s = make(St::Case, at);
    s->value = expr(*n.children[0]);
    const Kind k = s->value->type.kind;
    if (k != Kind::Integer && k != Kind::String && k != Kind::Boolean && k != Kind::Variant)
      fail(*n.children[0], fmt::format("case needs an Integer, String or Boolean selector, got {}", describe(s->value->type)));
    for (std::size_t i = 1; i < n.children.size(); ++i) {
      const Node& arm = *n.children[i];
      if (is<g::case_else>(arm)) {
        s->body.push_back(statements(*arm.children.front(), St::Block));
        s->has_else = true;
        continue;
      }
      std::vector<ExprPtr> labels;
      for (const auto& l : arm.children[0]->children) {
        auto x = expr(*l);
        if (x->op != Op::Literal) fail(*l, "a case label must be a constant");
        const Kind lk = x->type.kind;
        if (k != Kind::Variant && lk != k) fail(*l, fmt::format("case label is {}, the selector {}", describe(x->type), describe(s->value->type)));
        labels.push_back(std::move(x));
      }
      s->labels.push_back(std::move(labels));
      s->body.push_back(statement(*arm.children[1]));
    }
    return s;
  }
  if (is<g::break_stmt>(n) || is<g::continue_stmt>(n)) {
    if (loops_ == 0) fail(n, fmt::format("`{}` outside a loop", token(n)));
    return make(is<g::break_stmt>(n) ? St::Break : St::Continue, at);
  }
  if (is<g::exit_stmt>(n)) return make(St::Exit, at);
  if (is<g::assignment>(n)) {
    auto s = make(St::Assign, at);
    s->target = designator(*n.children[0], true);
    const std::string_view name = token(*n.children[0]->children.front());
    if (s->target->readonly) fail(n, fmt::format("cannot assign to `{}`: it is a constant", name));
    if (!s->target->lvalue()) fail(n, fmt::format("cannot assign to `{}`", name));
    s->value = convert(expr(*n.children[1]), s->target->type, *n.children[1], fmt::format("assignment to `{}`", name));
    return s;
  }
  // call_stmt: a designator that must end in a call.
  auto s = make(St::Call, at);
  s->value = designator(n, false);
  if (s->value->op != Op::Call && s->value->op != Op::Builtin)
    fail(n, fmt::format("a statement cannot be just a value: `{}` is not a routine (did you mean `:=`?)", token(*n.children.front())));
  return s;
}

}  // namespace pikocnc::script
