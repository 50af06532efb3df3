// Expressions: operators with Pascal's precedence (the grammar's term/simple/expr levels),
// designators, calls of routines and built-ins, static types and the implicit conversions of 2.3.
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "machines/pikocnc/script/compile_support.hpp"
#include "machines/pikocnc/script/ops.hpp"

namespace pikocnc::script {

namespace g = grammar;

namespace {

constexpr int kMaxDepth = 1000;  // evaluation recursion the interpreter may need

bool numeric(Kind k) { return k == Kind::Integer || k == Kind::Float; }
bool basic(Kind k) { return k == Kind::Integer || k == Kind::Float || k == Kind::Boolean || k == Kind::String; }

ExprPtr make(Op op, Pos pos, Type type) {
  auto e = std::make_unique<Expr>();
  e->op = op;
  e->pos = pos;
  e->type = type;
  return e;
}

Bin bin_of(std::string_view text) {
  const std::string t = fold(text);
  if (t == "+") return Bin::Add;
  if (t == "-") return Bin::Sub;
  if (t == "*") return Bin::Mul;
  if (t == "/") return Bin::Div;
  if (t == "div") return Bin::IntDiv;
  if (t == "mod") return Bin::Mod;
  if (t == "and") return Bin::And;
  if (t == "or") return Bin::Or;
  if (t == "xor") return Bin::Xor;
  if (t == "shl") return Bin::Shl;
  if (t == "shr") return Bin::Shr;
  if (t == "=") return Bin::Eq;
  if (t == "<>") return Bin::Ne;
  if (t == "<") return Bin::Lt;
  if (t == "<=") return Bin::Le;
  if (t == ">") return Bin::Gt;
  return Bin::Ge;
}

std::string trimmed(const Node& node) { return std::string(token(node)); }

}  // namespace

ExprPtr Compiler::literal(const Node& node) {
  const std::string text(node.string_view());
  const Pos at = pos(node);
  if (is<g::true_lit>(node) || is<g::false_lit>(node)) {
    auto e = make(Op::Literal, at, {Kind::Boolean});
    e->literal = Value::boolean(is<g::true_lit>(node));
    return e;
  }
  if (is<g::real_lit>(node)) {
    auto e = make(Op::Literal, at, {Kind::Float});
    e->literal = Value::real(std::strtod(text.c_str(), nullptr));
    if (!std::isfinite(e->literal.f)) fail(node, "number too large for Extended");
    return e;
  }
  if (is<g::int_lit>(node) || is<g::hex_lit>(node)) {
    const bool hex = is<g::hex_lit>(node);
    std::string digits = hex ? text.substr(1) : text;
    std::size_t end = 0;
    while (end < digits.size() && std::isxdigit(static_cast<unsigned char>(digits[end]))) ++end;
    digits.resize(end);
    const std::string shown = (hex ? "$" : "") + digits;
    while (digits.size() > 1 && digits[0] == '0') digits.erase(0, 1);
    if (digits.size() > 10) fail(node, fmt::format("integer {} is too large", shown));
    const long long v = std::strtoll(digits.c_str(), nullptr, hex ? 16 : 10);
    if (v > 2147483647LL) {
      // Too large for Integer: Delphi makes it a floating-point constant.
      auto e = make(Op::Literal, at, {Kind::Float});
      e->literal = Value::real(double(v));
      return e;
    }
    auto e = make(Op::Literal, at, {Kind::Integer});
    e->literal = Value::integer(v);
    return e;
  }
  // string_lit: quoted parts ('' is a quote) and #codes, joined.
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\'') {
      ++i;
      for (;;) {
        if (text[i] == '\'' && i + 1 < text.size() && text[i + 1] == '\'') out += '\'', i += 2;
        else if (text[i] == '\'') { ++i; break; }
        else out += text[i++];
      }
    } else if (c == '"') {
      const std::size_t end = text.find('"', i + 1);
      out.append(text, i + 1, end - i - 1);
      i = end + 1;
    } else if (c == '#') {
      std::size_t j = i + 1;
      long code = 0;
      while (j < text.size() && text[j] >= '0' && text[j] <= '9' && code < 1000) code = code * 10 + (text[j++] - '0');
      if (code > 255) fail(node, "a #character code must be 0..255");
      out += char(code);
      i = j;
    } else {
      break;  // the blanks and comments after the literal
    }
  }
  auto e = make(Op::Literal, at, {Kind::String});
  e->literal = Value::text(std::move(out));
  return e;
}

ExprPtr Compiler::convert(ExprPtr value, const Type& to, const Node& at, std::string_view what) {
  const Type& from = value->type;
  if (to.kind == Kind::Variant && (basic(from.kind) || from.kind == Kind::Variant)) return value;
  if (from == to || (from.kind == to.kind && basic(to.kind))) {
    if (to.kind == Kind::Integer && to.width != 0 && from.width != to.width) {
      auto c = make(Op::Convert, value->pos, to);  // range check of Byte/Cardinal
      c->kids.push_back(std::move(value));
      return c;
    }
    return value;
  }
  const bool ok = (to.kind == Kind::Float && from.kind == Kind::Integer) ||
                  (from.kind == Kind::Variant && basic(to.kind));
  if (!ok)
    fail(at, fmt::format("type mismatch: {} expects {}, got {}", what, describe(to), describe(from)));
  if (value->op == Op::Literal && to.kind == Kind::Float) {
    value->literal = Value::real(double(value->literal.i));
    value->type = to;
    return value;
  }
  auto c = make(Op::Convert, value->pos, to);
  c->kids.push_back(std::move(value));
  return c;
}

ExprPtr Compiler::expr(const Node& node) {
  if (++depth_ > kMaxDepth) fail(node, "expression too complex");
  struct Leave {
    int& d;
    ~Leave() { --d; }
  } leave{depth_};
  if (is<g::expr_body>(node) || is<g::simple>(node) || is<g::term>(node)) {
    ExprPtr left = expr(*node.children.front());
    for (std::size_t i = 1; i + 1 < node.children.size(); i += 2) {
      if (++depth_ > kMaxDepth) fail(*node.children[i], "expression too complex");
      left = binary(*node.children[i], std::move(left), expr(*node.children[i + 1]));
    }
    depth_ -= int(node.children.size() / 2);
    return left;
  }
  if (is<g::unary>(node)) return unary(node);
  if (is<g::designator>(node)) {
    auto e = designator(node, false);
    if (e->type.kind == Kind::Void) fail(node, fmt::format("`{}` is a procedure and has no value", token(*node.children.front())));
    return e;
  }
  return literal(node);
}

ExprPtr Compiler::unary(const Node& node) {
  const Node& op = *node.children.front();
  ExprPtr x = expr(*node.children.back());
  const Un un = is<g::op_not>(op) ? Un::Not : is<g::op_neg>(op) ? Un::Neg : Un::Pos;
  const Kind k = x->type.kind;
  Type result = x->type;
  if (un == Un::Not ? !(k == Kind::Boolean || k == Kind::Integer || k == Kind::Variant)
                    : !(numeric(k) || k == Kind::Variant))
    fail(op, fmt::format("operator `{}` cannot be applied to {}", trimmed(op), describe(x->type)));
  if (result.kind == Kind::Integer) result.width = 0;
  if (x->op == Op::Literal) {
    try {
      x->literal = apply_unary(un, x->literal);
    } catch (const OpError& e) {
      fail(op, e.what());
    }
    x->type = result;
    x->pos = pos(op);
    return x;
  }
  auto e = make(Op::Unary, pos(op), result);
  e->sub = std::uint8_t(un);
  e->kids.push_back(std::move(x));
  return e;
}

ExprPtr Compiler::binary(const Node& op_node, ExprPtr left, ExprPtr right) {
  const Bin op = bin_of(trimmed(op_node));
  const Kind a = left->type.kind, b = right->type.kind;
  const bool variant = a == Kind::Variant || b == Kind::Variant;
  auto mismatch = [&] {
    fail(op_node, fmt::format("operator `{}` cannot be applied to {} and {}", trimmed(op_node),
                              describe(left->type), describe(right->type)));
  };
  auto operand_ok = [&](auto pred) { return (a == Kind::Variant || pred(a)) && (b == Kind::Variant || pred(b)); };
  Type result;
  switch (op) {
    case Bin::Add:
      if (operand_ok([](Kind k) { return k == Kind::String; }) && (a == Kind::String || b == Kind::String)) {
        result = {Kind::String};
        break;
      }
      [[fallthrough]];
    case Bin::Sub:
    case Bin::Mul:
      if (!operand_ok(numeric)) mismatch();
      result = {variant ? Kind::Variant : (a == Kind::Integer && b == Kind::Integer) ? Kind::Integer : Kind::Float};
      break;
    case Bin::Div:
      if (!operand_ok(numeric)) mismatch();
      result = {Kind::Float};
      break;
    case Bin::IntDiv:
    case Bin::Mod:
    case Bin::Shl:
    case Bin::Shr:
      if (!operand_ok([](Kind k) { return k == Kind::Integer; })) mismatch();
      result = {Kind::Integer};
      break;
    case Bin::And:
    case Bin::Or:
    case Bin::Xor:
      if (operand_ok([](Kind k) { return k == Kind::Boolean; })) result = {variant ? Kind::Variant : Kind::Boolean};
      else if (operand_ok([](Kind k) { return k == Kind::Integer; })) result = {Kind::Integer};
      else mismatch();
      break;
    default:
      if (!variant && !(numeric(a) && numeric(b)) && !(a == b && (a == Kind::String || a == Kind::Boolean))) mismatch();
      result = {Kind::Boolean};
  }
  if (left->op == Op::Literal && right->op == Op::Literal) {
    try {
      left->literal = apply_binary(op, left->literal, right->literal);
    } catch (const OpError& e) {
      fail(op_node, e.what());
    }
    left->type = result;
    return left;
  }
  auto e = make(Op::Binary, pos(op_node), result);
  e->sub = std::uint8_t(op);
  e->kids.push_back(std::move(left));
  e->kids.push_back(std::move(right));
  return e;
}

}  // namespace pikocnc::script
