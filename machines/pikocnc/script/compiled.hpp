// The compiled script: the parse tree turned into expressions and statements whose names are
// resolved to slots and built-ins, with static types checked (compiler.cpp). The interpreter
// (interpreter.cpp) walks it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "machines/pikocnc/script/value.hpp"

namespace pikocnc::script {

struct Pos {
  std::uint32_t line = 0, column = 0;
};

enum class Op : std::uint8_t {
  Literal, Global, Local, RefParam, Predefined, Field, Index, Call, Builtin, Unary, Binary, Convert,
};
enum class Bin : std::uint8_t { Add, Sub, Mul, Div, IntDiv, Mod, And, Or, Xor, Shl, Shr, Eq, Ne, Lt, Le, Gt, Ge };
enum class Un : std::uint8_t { Neg, Pos, Not };

struct Expr {
  Op op = Op::Literal;
  Pos pos;
  Type type;                 // static type of the result
  Value literal;             // Literal
  std::int32_t slot = 0;     // Global/Local/RefParam slot, Predefined index, Field index, routine, builtin id
  std::uint8_t sub = 0;      // Bin / Un
  std::vector<std::unique_ptr<Expr>> kids;  // operands, base of Field/Index, arguments
  bool readonly = false;   // a constant, or part of one
  bool lvalue() const { return op == Op::Global || op == Op::Local || op == Op::RefParam || op == Op::Field || op == Op::Index; }
};

enum class St : std::uint8_t { Empty, Assign, Call, Block, If, Case, ForUp, ForDown, While, Repeat, Break, Continue, Exit };

struct Stmt {
  St kind = St::Empty;
  Pos pos;
  std::unique_ptr<Expr> target;   // Assign target, For variable
  std::unique_ptr<Expr> value;    // Assign value, call, condition, For start, Case selector
  std::unique_ptr<Expr> limit;    // For end
  std::vector<std::unique_ptr<Stmt>> body;  // Block/Repeat statements; If then [else]; For/While body
  // Case: one label list per arm (arm i -> body[i]); the else part is body.back() when has_else.
  std::vector<std::vector<std::unique_ptr<Expr>>> labels;
  bool has_else = false;
};

struct Routine {
  std::string name;
  Pos pos;
  bool is_function = false;
  Type result;
  std::vector<Type> params;
  std::vector<bool> by_ref;
  std::vector<Type> locals;     // slot types: [Result,] params, then local variables
  std::int32_t first_param = 0; // 1 for functions (slot 0 is Result)
  std::vector<std::pair<std::int32_t, std::unique_ptr<Expr>>> const_inits;  // local constants
  std::unique_ptr<Stmt> body;
  bool defined = false;
};

struct Program {
  std::string file;
  std::vector<Shape> shapes;
  std::vector<Type> globals;
  std::vector<std::pair<std::int32_t, std::unique_ptr<Expr>>> const_inits;  // global constants, in order
  std::vector<Routine> routines;
  std::unique_ptr<Stmt> main;
};

// The shapes every program starts with.
inline constexpr std::int32_t kTPoint = 0;
inline constexpr std::int32_t kTLine = 1;

}  // namespace pikocnc::script
