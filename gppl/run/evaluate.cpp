// Expression evaluation (spec 4): operators with the type rules of 4.5, attributes, built-ins.
// Results are written into caller-owned Values so that string capacity is reused.
#include <fmt/format.h>

#include <cmath>
#include <span>

#include "gppl/run/machine.hpp"

namespace gppl {

namespace {

constexpr std::int64_t kIntegerLimit = 999'999'999;

void set_integer(Value& v, std::int64_t x) {
  v.type = Type::Integer;
  v.integer = x;
  v.numeric = 0.0;
  v.logical = false;
  v.text.clear();
}
void set_numeric(Value& v, double x) {
  v.type = Type::Numeric;
  v.integer = 0;
  v.numeric = x;
  v.logical = false;
  v.text.clear();
}
void set_logical(Value& v, bool x) {
  v.type = Type::Logical;
  v.integer = 0;
  v.numeric = 0.0;
  v.logical = x;
  v.text.clear();
}

const char* type_name(Type t) {
  switch (t) {
    case Type::Integer: return "integer";
    case Type::Numeric: return "numeric";
    case Type::Logical: return "logical";
    case Type::String: break;
  }
  return "string";
}

bool is_relation(BinaryOp op) { return op >= BinaryOp::Eq; }


}  // namespace

void Interpreter::State::eval(std::uint32_t index, Value& out) {
  const Node& n = program.nodes[index];
  switch (n.kind) {
    case NodeKind::Constant: copy_value(out, program.constants[n.a]); return;
    case NodeKind::Variable: copy_value(out, element(program.refs[n.a]).value); return;
    case NodeKind::Attribute: {
      const Cell& c = element(program.refs[n.a]);
      set_logical(out, n.active_attribute ? c.active : c.changed);
      return;
    }
    case NodeKind::Negate:
      eval(n.a, out);
      switch (out.type) {
        case Type::Integer: out.integer = -out.integer; return;
        case Type::Numeric: out.numeric = -out.numeric; return;
        case Type::Logical: set_integer(out, out.logical ? -1 : 0); return;
        case Type::String: fail_at(n.pos, ErrorCode::NotNumeric, {}, "unary minus needs a number, not a string");
      }
      return;
    case NodeKind::Not: eval(n.a, out); set_logical(out, !truth(out)); return;
    case NodeKind::And:
    case NodeKind::Or: {
      // Short-circuit: the right side is evaluated only when it decides the result (4.2 allows either).
      eval(n.a, out);
      const bool left = truth(out);
      if (left == (n.kind == NodeKind::Or)) {
        set_logical(out, left);
        return;
      }
      eval(n.b, out);
      set_logical(out, truth(out));
      return;
    }
    case NodeKind::Binary: {
      eval(n.a, out);
      Value& right = push_scratch();
      eval(n.b, right);
      binary(n, out, right);
      pop_scratch();
      return;
    }
    case NodeKind::Call: call_builtin(n, out); return;
  }
}

bool Interpreter::State::condition_slowly(std::uint32_t node) {
  // Operands still read in place where they can be: `if a + 1 gt b` is not, `if flag ne 1` is.
  const Node& n = program.nodes[node];
  switch (n.kind) {
    case NodeKind::Binary: {
      if (!is_relation(n.op) || n.simple) break;  // simple: a string side, which eval() compares
      const Value* left = operand(program.nodes[n.a]);
      const Value* right = left ? operand(program.nodes[n.b]) : nullptr;
      if (!right || left->type == Type::String || right->type == Type::String) break;
      // The type rules of binary(): numeric when either side is; else integers (a logical is 0 or 1).
      if (left->type == Type::Numeric || right->type == Type::Numeric)
        return holds(n.op, operand_number(*left), operand_number(*right));
      return holds(n.op, operand_integer(*left), operand_integer(*right));
    }
    case NodeKind::Variable:
      if (n.simple) return truth(cell(program.refs[n.a]).value);
      break;
    // What eval gives them, without a scratch value: `if change(xpos) or change(ypos)`.
    case NodeKind::And: return condition(n.a) && condition(n.b);
    case NodeKind::Or: return condition(n.a) || condition(n.b);
    case NodeKind::Not: return !condition(n.a);
    default: break;
  }
  Value& v = push_scratch();
  eval(node, v);
  const bool result = truth(v);
  pop_scratch();
  return result;
}

void Interpreter::State::binary(const Node& n, Value& left, const Value& right) {
  const bool left_string = left.type == Type::String;
  const bool right_string = right.type == Type::String;
  if (left_string || right_string) {
    if (!(left_string && right_string))
      fail_at(n.pos, ErrorCode::NotString, {},
              fmt::format("cannot combine {} and {}", type_name(left.type), type_name(right.type)));
    if (n.op == BinaryOp::Add) {
      left.text += right.text;
      return;
    }
    if (!is_relation(n.op)) fail_at(n.pos, ErrorCode::NotNumeric, {}, "only + and comparisons apply to strings");
    const bool r = holds(n.op, std::string_view(left.text), std::string_view(right.text));
    set_logical(left, r);
    return;
  }
  const bool numeric = left.type == Type::Numeric || right.type == Type::Numeric || n.op == BinaryOp::Pow;
  if (numeric) {
    const double a = to_numeric(left), b = to_numeric(right);
    if (is_relation(n.op)) return set_logical(left, holds(n.op, a, b));
    double r = 0.0;
    switch (n.op) {
      case BinaryOp::Add: r = a + b; break;
      case BinaryOp::Sub: r = a - b; break;
      case BinaryOp::Mul: r = a * b; break;
      case BinaryOp::Div:
        if (b == 0.0) fail_at(n.pos, ErrorCode::ZeroDivide);
        r = a / b;
        break;
      default:
        if ((a == 0.0 && b <= 0.0) || (a < 0.0 && b != std::trunc(b)))
          fail_at(n.pos, ErrorCode::OutOfRange, {}, fmt::format("{} ^ {} is undefined", a, b));
        r = std::pow(a, b);
        break;
    }
    if (!std::isfinite(r)) fail_at(n.pos, ErrorCode::ValueRange, {}, "the result is too large");
    return set_numeric(left, r);
  }
  const std::int64_t a = to_integer(left), b = to_integer(right);
  if (is_relation(n.op)) return set_logical(left, holds(n.op, a, b));
  std::int64_t r = 0;
  switch (n.op) {
    case BinaryOp::Add: r = a + b; break;
    case BinaryOp::Sub: r = a - b; break;
    case BinaryOp::Mul: r = a * b; break;
    default:
      if (b == 0) fail_at(n.pos, ErrorCode::ZeroDivide);
      r = a / b;  // integer / integer truncates toward zero (4.3)
      break;
  }
  if (r > kIntegerLimit || r < -kIntegerLimit)
    fail_at(n.pos, ErrorCode::ValueRange, {}, fmt::format("integer result {} is beyond 999999999", r));
  set_integer(left, r);
}

void Interpreter::State::call_builtin(const Node& n, Value& out) {
  const FunctionSignature& f = *n.function;
  const std::uint32_t base = argument_top;
  // Given arguments, plus tostr's format (written `x : fmt`; numeric_def_f when absent, 9.3).
  const std::uint32_t count = n.count + (f.format_argument ? 1 : 0);
  argument_top += count;
  if (arguments.size() < argument_top) arguments.resize(argument_top);
  bool all_integer = true;
  for (std::uint32_t i = 0; i < count; ++i) {
    Value& v = push_scratch();
    if (i < n.count) eval(program.lists[n.list + i], v);
    else if (n.format != kNone) eval(n.format, v);
    else v = globals[program.slots.numeric_def_f].value;
    all_integer = all_integer && (v.type == Type::Integer || v.type == Type::Logical);
    std::swap(arguments[base + i], v);
    pop_scratch();
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    Value& v = arguments[base + i];
    Type want = f.parameters[i];
    if (f.integer_if_integer_args && want == Type::Numeric && all_integer) want = Type::Integer;
    switch (want) {
      case Type::Integer: {
        const std::int64_t x = to_integer(v);
        set_integer(v, x);
        break;
      }
      case Type::Numeric:
        if (v.type != Type::Integer) set_numeric(v, to_numeric(v));
        break;
      case Type::Logical: set_logical(v, to_logical(v)); break;
      case Type::String:
        if (v.type != Type::String)
          fail_at(n.pos, ErrorCode::NotString, {},
                  fmt::format("argument {} of {} must be a string", i + 1, f.name));
        break;
    }
  }
  try {
    out = call_function(f, std::span<const Value>(arguments.data() + base, count));
  } catch (const Error& e) {
    argument_top = base;
    throw Error(e.number(), program.position(n.pos), e.text());
  }
  argument_top = base;
}

}  // namespace gppl
