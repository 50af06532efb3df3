// PEGTL grammar of one GPPL statement line (spec sections 2, 4.2, 5.1, 6.1; real-post extensions of
// solidcam-behaviour.md 2a). The parser classifies a line by its first word and parses it with one
// of the `*_line` rules; the selected rules below become parse-tree nodes (the AST).
#pragma once

#include <tao/pegtl.hpp>

#include <string_view>

#include "gppl/builtins/functions.hpp"

namespace gppl::grammar {

namespace p = tao::pegtl;

// --- lexical ---------------------------------------------------------------------------------
// 0x1A is the DOS end-of-file mark some old posts still carry.
struct blank : p::one<' ', '\t', '\f', '\v', '\x1a'> {};
struct ws : p::star<blank> {};
struct comment : p::seq<p::one<';'>, p::star<p::any>> {};
struct line_end : p::seq<ws, p::opt<comment>, p::eof> {};

struct ident_first : p::sor<p::ascii::alpha, p::one<'_'>> {};
struct ident_other : p::sor<p::ascii::alnum, p::one<'_'>> {};
template <typename Word>
struct kw : p::seq<Word, p::not_at<ident_other>> {};

struct kw_global : kw<TAO_PEGTL_ISTRING("global")> {};
struct kw_local : kw<TAO_PEGTL_ISTRING("local")> {};
struct kw_integer : kw<TAO_PEGTL_ISTRING("integer")> {};
struct kw_numeric : kw<TAO_PEGTL_ISTRING("numeric")> {};
struct kw_logical : kw<TAO_PEGTL_ISTRING("logical")> {};
struct kw_string : kw<TAO_PEGTL_ISTRING("string")> {};
struct kw_if : kw<TAO_PEGTL_ISTRING("if")> {};
struct kw_then : kw<TAO_PEGTL_ISTRING("then")> {};
struct kw_else : kw<TAO_PEGTL_ISTRING("else")> {};
struct kw_elseif : kw<TAO_PEGTL_ISTRING("elseif")> {};
struct kw_endif : kw<TAO_PEGTL_ISTRING("endif")> {};
struct kw_while : kw<TAO_PEGTL_ISTRING("while")> {};
struct kw_endw : kw<TAO_PEGTL_ISTRING("endw")> {};
struct kw_call : kw<TAO_PEGTL_ISTRING("call")> {};
struct kw_endp : kw<TAO_PEGTL_ISTRING("endp")> {};
struct kw_trace : kw<TAO_PEGTL_ISTRING("trace")> {};
struct kw_abort : kw<TAO_PEGTL_ISTRING("abort")> {};
struct kw_exit : kw<TAO_PEGTL_ISTRING("exit")> {};
struct kw_break : kw<TAO_PEGTL_ISTRING("break")> {};
struct kw_return : kw<TAO_PEGTL_ISTRING("return")> {};
struct kw_and : kw<TAO_PEGTL_ISTRING("and")> {};
struct kw_or : kw<TAO_PEGTL_ISTRING("or")> {};
struct kw_not : kw<TAO_PEGTL_ISTRING("not")> {};
struct kw_eq : kw<TAO_PEGTL_ISTRING("eq")> {};
struct kw_ne : kw<TAO_PEGTL_ISTRING("ne")> {};
struct kw_lt : kw<TAO_PEGTL_ISTRING("lt")> {};
struct kw_le : kw<TAO_PEGTL_ISTRING("le")> {};
struct kw_gt : kw<TAO_PEGTL_ISTRING("gt")> {};
struct kw_ge : kw<TAO_PEGTL_ISTRING("ge")> {};
struct kw_change : kw<TAO_PEGTL_ISTRING("change")> {};
struct kw_active : kw<TAO_PEGTL_ISTRING("active")> {};
struct kw_proc : kw<TAO_PEGTL_ISTRING("proc")> {};
struct kw_inc : kw<p::sor<TAO_PEGTL_ISTRING("include"), TAO_PEGTL_ISTRING("inc")>> {};
struct kw_nb : kw<TAO_PEGTL_ISTRING("nb")> {};
struct kw_nl : kw<TAO_PEGTL_ISTRING("nl")> {};
struct kw_col : kw<TAO_PEGTL_ISTRING("col")> {};
struct kw_colrel : kw<TAO_PEGTL_ISTRING("colrel")> {};
// `input` and `print` start a statement only as the first word of a line; a variable may still be
// called so (the line classifier tells `print = 1` apart).
struct kw_input : kw<TAO_PEGTL_ISTRING("input")> {};
struct kw_print : kw<TAO_PEGTL_ISTRING("print")> {};

// Words that can never name a variable. nb/nl/col/colrel are keywords only inside `{ }`, and
// `inc` only at the start of a line followed by a string (a variable may be called `inc`).
struct reserved
    : p::sor<kw_global, kw_local, kw_integer, kw_numeric, kw_logical, kw_string, kw_if, kw_then, kw_else,
             kw_elseif, kw_endif, kw_while, kw_endw, kw_call, kw_endp, kw_trace, kw_abort, kw_exit, kw_break, kw_return,
             kw_and, kw_or, kw_not, kw_eq, kw_ne, kw_lt, kw_le, kw_gt, kw_ge, kw_change, kw_active> {};

struct identifier : p::seq<p::not_at<reserved>, ident_first, p::star<ident_other>> {};

// An identifier that names a built-in function (find_function); function names are reserved.
struct function_name {
  using rule_t = function_name;
  using subs_t = p::type_list<>;
  template <typename ParseInput>
  static bool match(ParseInput& in) {
    const char* begin = in.current();
    const std::size_t size = in.size();
    auto is_first = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    auto is_other = [&](char c) { return is_first(c) || (c >= '0' && c <= '9'); };
    if (size == 0 || !is_first(begin[0])) return false;
    std::size_t n = 1;
    while (n < size && is_other(begin[n])) ++n;
    if (find_function(std::string_view(begin, n)) == nullptr) return false;
    in.bump_in_this_line(n);
    return true;
  }
};

struct proc_name : p::seq<p::one<'@'>, ident_first, p::star<ident_other>> {};

struct digits : p::plus<p::ascii::digit> {};
struct exponent : p::seq<p::one<'e', 'E'>, p::opt<p::one<'+', '-'>>, digits> {};
// A numeric literal has a decimal point; `1E5` (exponent without point) is accepted leniently.
struct num_literal : p::sor<p::seq<digits, p::one<'.'>, p::opt<digits>, p::opt<exponent>>,
                            p::seq<p::one<'.'>, digits, p::opt<exponent>>, p::seq<digits, exponent>> {};
struct int_literal : digits {};
struct string_end_sq : p::one<'\''> {};
struct string_end_dq : p::one<'"'> {};
struct string_literal : p::sor<p::seq<p::one<'\''>, p::star<p::not_one<'\''>>, p::must<string_end_sq>>,
                               p::seq<p::one<'"'>, p::star<p::not_one<'"'>>, p::must<string_end_dq>>> {};

// --- expressions (4.2) -----------------------------------------------------------------------
struct expr;
struct close_paren : p::one<')'> {};
struct close_index : p::string<'>', '>'> {};
struct open_paren : p::one<'('> {};
struct comma : p::one<','> {};
struct paren_expr : p::seq<open_paren, ws, p::must<expr>, ws, p::must<close_paren>> {};
struct index_list
    : p::seq<p::string<'<', '<'>, ws, p::must<expr>, p::star<ws, comma, ws, p::must<expr>>, ws, p::must<close_index>> {};
struct variable : p::seq<identifier, p::opt<ws, index_list>> {};

struct format_ref : p::sor<string_literal, variable, paren_expr> {};
struct format_spec : p::seq<p::one<':'>, ws, p::must<format_ref>> {};
struct argument : p::seq<expr, p::opt<ws, format_spec>> {};
struct arguments : p::seq<open_paren, ws, p::opt<argument, p::star<ws, comma, ws, p::must<argument>>>, ws,
                          p::must<close_paren>> {};
struct func_call : p::seq<function_name, p::opt<ws, arguments>> {};
struct attribute : p::seq<p::sor<kw_change, kw_active>, ws, p::must<open_paren>, ws, p::must<variable>, ws,
                          p::must<close_paren>> {};

struct op_or : kw_or {};
struct op_and : kw_and {};
struct op_not : p::sor<kw_not, p::seq<p::one<'!'>, p::not_at<p::one<'='>>>> {};
struct op_rel : p::sor<p::string<'=', '='>, p::string<'!', '='>, p::string<'<', '>'>, p::string<'<', '='>,
                       p::string<'>', '='>, p::seq<p::one<'<'>, p::not_at<p::one<'<'>>>,
                       p::seq<p::one<'>'>, p::not_at<p::one<'>'>>>, p::one<'='>, kw_eq, kw_ne, kw_lt, kw_le,
                       kw_gt, kw_ge> {};
struct op_add : p::one<'+', '-'> {};
struct op_mul : p::one<'*', '/'> {};
struct op_pow : p::one<'^'> {};
struct op_sign : p::one<'-', '+'> {};

struct primary : p::sor<num_literal, int_literal, string_literal, attribute, func_call, variable, paren_expr> {};
struct unary;
struct pow_expr : p::seq<primary, p::opt<ws, op_pow, ws, p::must<unary>>> {};
struct signed_expr : p::seq<op_sign, ws, p::must<unary>> {};
struct unary : p::sor<signed_expr, pow_expr> {};
struct mul_expr : p::seq<unary, p::star<ws, op_mul, ws, p::must<unary>>> {};
struct add_expr : p::seq<mul_expr, p::star<ws, op_add, ws, p::must<mul_expr>>> {};
struct rel_expr : p::seq<add_expr, p::opt<ws, op_rel, ws, p::must<add_expr>>> {};
struct not_expr;
struct negation : p::seq<op_not, ws, p::must<not_expr>> {};
struct not_expr : p::sor<negation, rel_expr> {};
struct and_expr : p::seq<not_expr, p::star<ws, op_and, ws, p::must<not_expr>>> {};
struct or_expr : p::seq<and_expr, p::star<ws, op_or, ws, p::must<and_expr>>> {};
struct expr : p::seq<or_expr> {};

// --- generate statement (6.1) ----------------------------------------------------------------
struct gen_nb : kw_nb {};
struct gen_nl : kw_nl {};
struct gen_col : p::seq<kw_col, ws, open_paren, ws, p::must<expr>, ws, p::must<close_paren>> {};
struct gen_colrel : p::seq<kw_colrel, ws, open_paren, ws, p::must<expr>, ws, p::must<close_paren>> {};
struct gen_operand : p::sor<string_literal, num_literal, int_literal, func_call, variable, paren_expr> {};
// Items joined by `+` (string concatenation in real posts: `'CYCLE832(' + s + ',1)'`).
struct gen_plus : p::one<'+'> {};
struct gen_sum : p::seq<gen_operand, p::star<ws, gen_plus, ws, p::must<gen_operand>>> {};
struct gen_value : p::seq<p::not_at<p::sor<kw_nb, kw_nl>>, gen_sum, p::opt<ws, format_spec>> {};
struct close_group : p::one<']'> {};
struct close_generate : p::one<'}'> {};
// Commas are optional, and real posts also write a leading or a doubled one: `{,x}`, `{a,,b}`.
struct gen_group
    : p::seq<p::one<'['>, ws, p::star<p::sor<comma, gen_colrel, gen_col, gen_value>, ws>, p::must<close_group>> {};
struct gen_item : p::sor<gen_nb, gen_nl, gen_colrel, gen_col, gen_group, gen_value> {};
struct generate : p::seq<p::one<'{'>, ws, p::star<p::sor<comma, gen_item>, ws>, p::must<close_generate>> {};

// --- statements (5.1) ------------------------------------------------------------------------
struct type_name : p::sor<kw_integer, kw_numeric, kw_logical, kw_string> {};
struct dimension : digits {};
struct dimensions : p::seq<p::string<'<', '<'>, ws, p::must<dimension>, p::star<ws, comma, ws, p::must<dimension>>,
                           ws, p::must<close_index>> {};
struct var_decl : p::seq<identifier, p::opt<ws, dimensions>> {};
struct scope : p::sor<kw_global, kw_local> {};
struct declaration
    : p::seq<scope, ws, p::must<type_name>, ws, p::must<var_decl>, p::star<ws, p::opt<comma, ws>, var_decl>> {};

struct assign_op : p::one<'='> {};
struct assignment : p::seq<variable, ws, p::must<assign_op>, ws, p::must<expr>> {};
struct attr_assignment : p::seq<attribute, ws, p::must<assign_op>, ws, p::must<expr>> {};
struct if_statement : p::seq<kw_if, ws, p::must<expr>, p::opt<ws, kw_then>> {};
struct elseif_statement : p::seq<kw_elseif, ws, p::must<expr>, p::opt<ws, kw_then>> {};
struct else_statement : kw_else {};
struct endif_statement : kw_endif {};
struct while_statement : p::seq<kw_while, ws, p::must<expr>> {};
struct endw_statement : kw_endw {};
struct endp_statement : kw_endp {};
struct call_statement : p::seq<kw_call, ws, p::must<proc_name>, p::opt<ws, arguments>> {};
struct trace_level : p::seq<expr> {};
struct trace_statement
    : p::seq<kw_trace, ws, p::must<string_literal>, ws, p::must<p::one<':'>>, ws, p::must<trace_level>> {};
// `input 'prompt' var` / `Input "prompt", var`; `print item, ...` (items: expressions, `:format`).
struct input_prompt : p::seq<expr> {};
struct input_target : p::seq<variable> {};
struct input_statement
    : p::seq<kw_input, ws, p::must<input_prompt>, ws, p::opt<comma, ws>, p::must<input_target>> {};
struct print_statement : p::seq<kw_print, ws, p::star<p::sor<comma, argument>, ws>> {};
struct stop_statement : p::sor<kw_abort, kw_exit, kw_break, kw_return> {};
struct include_statement : p::seq<kw_inc, ws, p::must<string_literal>> {};
struct parameter : p::seq<type_name, ws, p::must<identifier>> {};
struct parameters
    : p::seq<open_paren, ws, p::opt<parameter, p::star<ws, comma, ws, p::must<parameter>>>, ws, p::must<close_paren>> {};
struct proc_header : p::seq<p::opt<kw_proc, ws>, proc_name, p::opt<ws, parameters>> {};

// One whole line holding statement S.
template <typename S>
struct line : p::seq<ws, S, p::must<line_end>> {};

// --- what the parse tree keeps -----------------------------------------------------------------
template <typename Rule>
struct selector
    : p::parse_tree::selector<
          Rule,
          p::parse_tree::store_content::on<identifier, function_name, proc_name, num_literal, int_literal,
                                           string_literal, op_or, op_and, op_not, op_rel, op_add, op_mul, op_pow,
                                           op_sign, type_name, dimension, scope, stop_statement, kw_change,
                                           kw_active, gen_nb, gen_nl, gen_plus>,
          p::parse_tree::remove_content::on<paren_expr, index_list, variable, format_spec, argument, arguments,
                                            func_call, attribute, signed_expr, negation, gen_col, gen_colrel,
                                            gen_value, gen_group, generate, dimensions, var_decl, declaration,
                                            assignment, attr_assignment, if_statement, elseif_statement, else_statement,
                                            endif_statement, while_statement, endw_statement, endp_statement,
                                            call_statement, trace_statement, trace_level, include_statement,
                                            parameter, parameters, proc_header, input_prompt, input_statement,
                                            print_statement>,
          p::parse_tree::fold_one::on<or_expr, and_expr, rel_expr, add_expr, mul_expr, pow_expr, gen_sum>> {};

// What a failing `must<Rule>` reports as expected.
template <typename Rule>
inline constexpr std::string_view expected = "";
template <> inline constexpr std::string_view expected<expr> = "an expression";
template <> inline constexpr std::string_view expected<trace_level> = "a trace level";
template <> inline constexpr std::string_view expected<unary> = "an operand";
template <> inline constexpr std::string_view expected<mul_expr> = "an operand";
template <> inline constexpr std::string_view expected<add_expr> = "an operand";
template <> inline constexpr std::string_view expected<not_expr> = "an operand";
template <> inline constexpr std::string_view expected<and_expr> = "an operand";
template <> inline constexpr std::string_view expected<close_paren> = "')'";
template <> inline constexpr std::string_view expected<open_paren> = "'('";
template <> inline constexpr std::string_view expected<close_index> = "'>>'";
template <> inline constexpr std::string_view expected<close_group> = "']' closing the modal group";
template <> inline constexpr std::string_view expected<close_generate> = "'}' or a generate item";
template <> inline constexpr std::string_view expected<string_end_sq> = "a closing ' (unterminated string)";
template <> inline constexpr std::string_view expected<string_end_dq> = "a closing \" (unterminated string)";
template <> inline constexpr std::string_view expected<format_ref> = "a display format (string, variable or (expression))";
template <> inline constexpr std::string_view expected<argument> = "an argument";
template <> inline constexpr std::string_view expected<variable> = "a variable (only variables have attributes)";
template <> inline constexpr std::string_view expected<type_name> = "a type (integer, numeric, logical or string)";
template <> inline constexpr std::string_view expected<var_decl> = "a variable name";
template <> inline constexpr std::string_view expected<dimension> = "an array size";
template <> inline constexpr std::string_view expected<assign_op> = "'='";
template <> inline constexpr std::string_view expected<proc_name> = "a procedure name (@name)";
template <> inline constexpr std::string_view expected<p::one<':'>> = "':' and a trace level";
template <> inline constexpr std::string_view expected<string_literal> = "a string literal";
template <> inline constexpr std::string_view expected<parameter> = "a parameter (type name)";
template <> inline constexpr std::string_view expected<identifier> = "a parameter name";
template <> inline constexpr std::string_view expected<gen_operand> = "an item after '+'";
template <> inline constexpr std::string_view expected<input_target> = "the variable that receives the answer";
template <> inline constexpr std::string_view expected<input_prompt> = "a prompt (a string or an expression)";
template <> inline constexpr std::string_view expected<line_end> = "end of statement (or a ';' comment)";

template <typename Rule>
struct control : p::normal<Rule> {
  template <typename ParseInput, typename... States>
  [[noreturn]] static void raise(const ParseInput& in, States&&...) {
    std::string_view what = expected<Rule>;
    if (what.empty()) what = "valid syntax";
    throw p::parse_error("expected " + std::string(what), in);
  }
};

}  // namespace gppl::grammar
