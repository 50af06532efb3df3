// The compiler's state, shared by its three files: declarations (compile_decls.cpp), expressions
// (compile_exprs.cpp) and statements (compile_stmts.cpp).
#pragma once

#include <fmt/format.h>

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/parse_tree.hpp>

#include "machines/pikocnc/script/builtins.hpp"
#include "machines/pikocnc/script/compiled.hpp"
#include "machines/pikocnc/script/grammar.hpp"
#include "toolpath/error.hpp"

namespace pikocnc::script {

using Node = tao::pegtl::parse_tree::node;
using ExprPtr = std::unique_ptr<Expr>;
using StmtPtr = std::unique_ptr<Stmt>;

// A token node's text without the blanks and comments the grammar lets it swallow.
std::string_view token(const Node& node);
// Script names are case-insensitive: every lookup uses the ASCII-lower-cased name.
std::string fold(std::string_view name);
std::string type_name(const Program& program, const Type& type);

struct Symbol {
  enum class What { Var, Const, Routine, TypeName } what = What::Var;
  std::int32_t slot = 0;
  Type type;
  bool by_ref = false;
};

class Compiler {
public:
  explicit Compiler(std::string file) : file_(std::move(file)) {}
  std::unique_ptr<Program> compile(const Node& root);

  // --- compile_decls.cpp
  void declarations(const Node& section, bool global);
  void routine(const Node& node);
  Type type_of(const Node& node);
  std::int64_t value_count(const Type& type) const;  // basic values a variable of the type holds
  void declare(const Node& name, Symbol symbol, bool global);

  // --- compile_exprs.cpp
  ExprPtr expr(const Node& node);
  ExprPtr designator(const Node& node, bool assign_target);
  ExprPtr call(const Node& at, std::int32_t routine, const Node* args);
  ExprPtr builtin_call(const Node& at, const Builtin& builtin, const Node* args);
  ExprPtr convert(ExprPtr value, const Type& to, const Node& at, std::string_view what);
  ExprPtr binary(const Node& op, ExprPtr left, ExprPtr right);
  ExprPtr unary(const Node& node);
  ExprPtr literal(const Node& node);

  // --- compile_stmts.cpp
  StmtPtr statement(const Node& node);
  StmtPtr statements(const Node& list, St kind);

  [[noreturn]] void fail(const Node& at, const std::string& message) const;
  [[noreturn]] void fail(Pos at, const std::string& message) const;
  static Pos pos(const Node& node) { return {std::uint32_t(node.begin().line), std::uint32_t(node.begin().column)}; }
  const Symbol* lookup(std::string_view folded) const;
  std::string describe(const Type& type) const { return type_name(*program_, type); }

  std::string file_;
  std::unique_ptr<Program> program_;
  std::map<std::string, Symbol> globals_;
  std::map<std::string, Symbol> locals_;
  Routine* current_ = nullptr;  // the routine being compiled, or null in the main block
  std::int32_t current_index_ = -1;
  std::map<std::string, Value> folded_[2];  // literal constants: global, local
  int loops_ = 0;               // enclosing loops (break/continue)
  int depth_ = 0;               // expression depth (left-deep chains)
};

// Node kind tests, short.
template <typename Rule>
bool is(const Node& node) {
  return node.is_type<Rule>();
}

}  // namespace pikocnc::script
