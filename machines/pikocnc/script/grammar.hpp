// PEGTL grammar of the PikoCNC script language (spec section 2): a Pascal subset. Every token
// swallows the blanks and comments after it, so a node starts where its first token starts.
#pragma once

#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/parse_tree.hpp>

#include <string>
#include <string_view>

namespace pikocnc::script::grammar {

namespace p = tao::pegtl;

// --- blanks and comments ---------------------------------------------------------------------
struct line_comment : p::seq<p::two<'/'>, p::until<p::eolf>> {};
struct brace_close : p::one<'}'> {};
struct brace_comment : p::if_must<p::one<'{'>, p::until<brace_close>> {};
struct paren_close : p::string<'*', ')'> {};
struct paren_comment : p::if_must<p::string<'(', '*'>, p::until<paren_close>> {};
struct sp : p::star<p::sor<p::plus<p::space>, line_comment, brace_comment, paren_comment>> {};

template <typename R>
struct tok : p::seq<R, sp> {};
template <char... C>
struct sym : tok<p::string<C...>> {};

struct ident_other : p::sor<p::ascii::alnum, p::one<'_'>> {};
template <typename Word>
struct kw : tok<p::seq<Word, p::not_at<ident_other>>> {};
#define PIKO_KW(name) struct kw_##name : kw<TAO_PEGTL_ISTRING(#name)> {}
PIKO_KW(and); PIKO_KW(array); PIKO_KW(begin); PIKO_KW(case); PIKO_KW(const); PIKO_KW(div);
PIKO_KW(do); PIKO_KW(downto); PIKO_KW(else); PIKO_KW(end); PIKO_KW(for); PIKO_KW(function);
PIKO_KW(if); PIKO_KW(mod); PIKO_KW(not); PIKO_KW(of); PIKO_KW(or); PIKO_KW(procedure);
PIKO_KW(program); PIKO_KW(record); PIKO_KW(repeat); PIKO_KW(then); PIKO_KW(to); PIKO_KW(type);
PIKO_KW(until); PIKO_KW(var); PIKO_KW(while); PIKO_KW(xor); PIKO_KW(break); PIKO_KW(continue);
PIKO_KW(exit); PIKO_KW(shl); PIKO_KW(shr);
#undef PIKO_KW
struct reserved_word
    : p::seq<p::sor<TAO_PEGTL_ISTRING("and"), TAO_PEGTL_ISTRING("array"), TAO_PEGTL_ISTRING("begin"),
                    TAO_PEGTL_ISTRING("case"), TAO_PEGTL_ISTRING("const"), TAO_PEGTL_ISTRING("div"),
                    TAO_PEGTL_ISTRING("downto"), TAO_PEGTL_ISTRING("do"), TAO_PEGTL_ISTRING("else"),
                    TAO_PEGTL_ISTRING("end"), TAO_PEGTL_ISTRING("for"), TAO_PEGTL_ISTRING("function"),
                    TAO_PEGTL_ISTRING("if"), TAO_PEGTL_ISTRING("mod"), TAO_PEGTL_ISTRING("not"),
                    TAO_PEGTL_ISTRING("of"), TAO_PEGTL_ISTRING("or"), TAO_PEGTL_ISTRING("procedure"),
                    TAO_PEGTL_ISTRING("program"), TAO_PEGTL_ISTRING("record"), TAO_PEGTL_ISTRING("repeat"),
                    TAO_PEGTL_ISTRING("then"), TAO_PEGTL_ISTRING("to"), TAO_PEGTL_ISTRING("type"),
                    TAO_PEGTL_ISTRING("until"), TAO_PEGTL_ISTRING("var"), TAO_PEGTL_ISTRING("while"),
                    TAO_PEGTL_ISTRING("xor"), TAO_PEGTL_ISTRING("break"), TAO_PEGTL_ISTRING("continue"),
                    TAO_PEGTL_ISTRING("exit"), TAO_PEGTL_ISTRING("shl"), TAO_PEGTL_ISTRING("shr")>,
             p::not_at<ident_other>> {};
struct ident_text : p::seq<p::not_at<reserved_word>, p::sor<p::ascii::alpha, p::one<'_'>>, p::star<ident_other>> {};
struct ident : tok<ident_text> {};

// --- nesting guard: deep nesting must end in an error, never in a stack overflow ---------------
inline constexpr int kMaxNesting = 200;
inline thread_local int nesting = 0;
template <typename Rule>
struct nested {
  using rule_t = nested;
  using subs_t = p::type_list<Rule>;
  template <p::apply_mode A, p::rewind_mode M, template <typename...> class Action,
            template <typename...> class Control, typename ParseInput, typename... States>
  static bool match(ParseInput& in, States&&... st) {
    struct Guard {
      Guard() { ++nesting; }
      ~Guard() { --nesting; }
    } guard;
    if (nesting > kMaxNesting) throw p::parse_error("nesting too deep (more than 200 levels)", in);
    return Control<Rule>::template match<A, M, Action, Control>(in, st...);
  }
};

// --- literals ---------------------------------------------------------------------------------
struct digits : p::plus<p::ascii::digit> {};
struct exponent : p::seq<p::one<'e', 'E'>, p::opt<p::one<'+', '-'>>, p::must<digits>> {};
struct real_text : p::sor<p::seq<digits, p::one<'.'>, p::not_at<p::one<'.'>>, p::opt<digits>, p::opt<exponent>>,
                          p::seq<digits, exponent>> {};
struct real_lit : tok<real_text> {};
struct hex_digits : p::plus<p::ascii::xdigit> {};
struct hex_lit : tok<p::seq<p::one<'$'>, p::must<hex_digits>>> {};
struct int_lit : tok<p::seq<digits, p::not_at<ident_other>>> {};
struct sq_end : p::one<'\''> {};
struct dq_end : p::one<'"'> {};
struct sq_body : p::star<p::sor<p::two<'\''>, p::seq<p::not_one<'\'', '\n'>>>> {};
struct dq_body : p::star<p::not_one<'"', '\n'>> {};
struct sq_string : p::seq<p::one<'\''>, sq_body, p::must<sq_end>> {};
struct dq_string : p::seq<p::one<'"'>, dq_body, p::must<dq_end>> {};
// #65 character codes join quoted parts as in Delphi: 'a'#13#10'b'.
struct char_code : p::seq<p::one<'#'>, p::must<digits>> {};
struct string_lit : tok<p::plus<p::sor<sq_string, dq_string, char_code>>> {};
struct true_lit : kw<TAO_PEGTL_ISTRING("true")> {};
struct false_lit : kw<TAO_PEGTL_ISTRING("false")> {};

// --- expressions (2.4) ------------------------------------------------------------------------
struct expr;
struct close_paren : sym<')'> {};
struct close_bracket : sym<']'> {};
struct colon : tok<p::seq<p::one<':'>, p::not_at<p::one<'='>>>> {};
struct semi : sym<';'> {};
struct comma : sym<','> {};
struct assign_op : sym<':', '='> {};
struct dot : tok<p::seq<p::one<'.'>, p::not_at<p::one<'.'>>>> {};
struct args : p::seq<sym<'('>, p::opt<expr, p::star<comma, p::must<expr>>>, p::must<close_paren>> {};
struct field_sel : p::seq<dot, p::must<ident>> {};
struct index_sel : p::seq<sym<'['>, p::must<expr>, p::must<close_bracket>> {};
struct designator : p::seq<ident, p::star<p::sor<field_sel, index_sel, args>>> {};
struct paren_expr : p::seq<sym<'('>, p::must<expr>, p::must<close_paren>> {};

struct op_not : kw_not {};
struct op_neg : sym<'-'> {};
struct op_pos : sym<'+'> {};
struct factor;
struct unary : p::seq<p::sor<op_not, op_neg, op_pos>, p::must<factor>> {};
struct factor_body : p::sor<real_lit, hex_lit, int_lit, string_lit, true_lit, false_lit, unary, paren_expr, designator> {};
struct factor : nested<factor_body> {};
struct op_mul : p::sor<sym<'*'>, sym<'/'>, kw_div, kw_mod, kw_and, kw_shl, kw_shr> {};
struct op_add : p::sor<sym<'+'>, sym<'-'>, kw_or, kw_xor> {};
struct op_rel : p::sor<sym<'<', '>'>, sym<'<', '='>, sym<'>', '='>, sym<'='>, sym<'<'>, sym<'>'>> {};
struct term : p::seq<factor, p::star<op_mul, p::must<factor>>> {};
struct simple : p::seq<term, p::star<op_add, p::must<term>>> {};
struct expr_body : p::seq<simple, p::opt<op_rel, p::must<simple>>> {};
struct expr : nested<expr_body> {};

// --- types and declarations -------------------------------------------------------------------
struct type;
struct idents : p::seq<ident, p::star<comma, p::must<ident>>> {};
struct field_decl : p::seq<idents, p::must<colon>, p::must<type>, p::must<semi>> {};
struct record_type : p::seq<kw_record, p::star<field_decl>, p::must<kw_end>> {};
struct range : p::seq<expr, p::must<sym<'.', '.'>>, p::must<expr>> {};
struct array_type : p::seq<kw_array, p::opt<sym<'['>, p::must<range>, p::must<close_bracket>>, p::must<kw_of>, p::must<type>> {};
struct type_name : ident {};
struct type_body : p::sor<record_type, array_type, type_name> {};
struct type : nested<type_body> {};

struct const_def : p::seq<ident, p::must<sym<'='>>, p::must<expr>, p::must<semi>> {};
struct const_sec : p::seq<kw_const, p::must<const_def>, p::star<const_def>> {};
struct type_def : p::seq<ident, p::must<sym<'='>>, p::must<type>, p::must<semi>> {};
struct type_sec : p::seq<kw_type, p::must<type_def>, p::star<type_def>> {};
struct var_decl : p::seq<idents, colon, p::must<type>, p::must<semi>> {};
struct var_sec : p::seq<kw_var, p::must<var_decl>, p::star<var_decl>> {};

// --- statements -------------------------------------------------------------------------------
struct stmt;
struct stmt_list : p::seq<stmt, p::star<semi, stmt>> {};
struct block_end : kw_end {};
struct block : p::seq<kw_begin, stmt_list, p::must<block_end>> {};
struct then_kw : kw_then {};
struct do_kw : kw_do {};
struct of_kw : kw_of {};
struct until_kw : kw_until {};
struct if_stmt : p::seq<kw_if, p::must<expr>, p::must<then_kw>, stmt, p::opt<kw_else, stmt>> {};
struct case_labels : p::seq<expr, p::star<comma, p::must<expr>>> {};
struct case_arm : p::seq<case_labels, p::must<colon>, stmt, p::opt<semi>> {};
struct case_else : p::seq<kw_else, stmt_list> {};
struct case_stmt : p::seq<kw_case, p::must<expr>, p::must<of_kw>, p::star<case_arm>, p::opt<case_else>, p::must<block_end>> {};
struct dir_to : kw_to {};
struct dir_downto : kw_downto {};
struct for_dir : p::sor<dir_to, dir_downto> {};
struct for_stmt : p::seq<kw_for, p::must<ident>, p::must<assign_op>, p::must<expr>, p::must<for_dir>, p::must<expr>,
                         p::must<do_kw>, stmt> {};
struct while_stmt : p::seq<kw_while, p::must<expr>, p::must<do_kw>, stmt> {};
struct repeat_stmt : p::seq<kw_repeat, stmt_list, p::must<until_kw>, p::must<expr>> {};
struct break_stmt : kw_break {};
struct continue_stmt : kw_continue {};
struct exit_stmt : kw_exit {};
struct assignment : p::seq<designator, assign_op, p::must<expr>> {};
struct call_stmt : designator {};
struct stmt_body : p::opt<p::sor<block, if_stmt, case_stmt, for_stmt, while_stmt, repeat_stmt, break_stmt,
                                 continue_stmt, exit_stmt, assignment, call_stmt>> {};
struct stmt : nested<stmt_body> {};

// --- routines and the script (2.2) --------------------------------------------------------------
struct by_ref : kw_var {};
struct by_const : kw_const {};
struct param : p::seq<p::opt<p::sor<by_ref, by_const>>, p::must<idents>, p::must<colon>, p::must<type>> {};
struct params : p::seq<sym<'('>, p::opt<param, p::star<semi, p::must<param>>>, p::must<close_paren>> {};
struct proc_head : p::seq<kw_procedure, p::must<ident>, p::opt<params>> {};
struct result_type : type {};
struct func_head : p::seq<kw_function, p::must<ident>, p::opt<params>, p::must<colon>, p::must<result_type>> {};
struct routine_body : block {};
struct routine : p::seq<p::sor<proc_head, func_head>, p::must<semi>, p::star<p::sor<const_sec, var_sec>>,
                        p::must<routine_body>, p::must<semi>> {};
struct decl : p::sor<const_sec, type_sec, var_sec, routine> {};
struct program_head : p::seq<kw_program, p::must<ident>, p::must<semi>> {};
struct main_block : p::seq<block, sym<'.'>, p::eof> {};
struct script_end : p::eof {};
// A declaration after the statements of a fragment: say so rather than "expected ';'".
struct decl_first : p::failure {};
struct late_decl : p::seq<p::at<p::sor<kw_var, kw_const, kw_type, kw_procedure, kw_function>>, p::must<decl_first>> {};
struct fragment : p::seq<stmt_list, p::opt<late_decl>, p::must<script_end>> {};
struct script : p::seq<sp, p::opt<program_head>, p::star<decl>, p::sor<main_block, fragment>> {};

// --- the parse tree ---------------------------------------------------------------------------
template <typename Rule>
struct selector
    : p::parse_tree::selector<
          Rule,
          p::parse_tree::store_content::on<ident, real_lit, hex_lit, int_lit, string_lit, true_lit, false_lit, op_not,
                                           op_neg, op_pos, op_mul, op_add, op_rel, type_name, by_ref, by_const,
                                           dir_to, dir_downto, break_stmt, continue_stmt, exit_stmt>,
          p::parse_tree::remove_content::on<args, field_sel, index_sel, designator, unary, term, simple, expr_body,
                                            idents, field_decl, record_type, range, array_type, const_def, type_def,
                                            var_decl, stmt_list, block, if_stmt, case_labels, case_arm, case_else,
                                            case_stmt, for_stmt, while_stmt, repeat_stmt, assignment, call_stmt,
                                            param, params, proc_head, func_head, result_type, routine_body,
                                            routine, const_sec, type_sec, var_sec, program_head, main_block,
                                            fragment, stmt_body>> {};

// What a failing must<Rule> reports as expected.
template <typename Rule>
inline constexpr std::string_view expected = "valid syntax";
template <> inline constexpr std::string_view expected<expr> = "an expression";
template <> inline constexpr std::string_view expected<factor> = "an operand";
template <> inline constexpr std::string_view expected<term> = "an operand";
template <> inline constexpr std::string_view expected<simple> = "an operand";
template <> inline constexpr std::string_view expected<ident> = "an identifier";
template <> inline constexpr std::string_view expected<idents> = "an identifier";
template <> inline constexpr std::string_view expected<close_paren> = "')'";
template <> inline constexpr std::string_view expected<close_bracket> = "']'";
template <> inline constexpr std::string_view expected<colon> = "':'";
template <> inline constexpr std::string_view expected<semi> = "';'";
template <> inline constexpr std::string_view expected<assign_op> = "':='";
template <> inline constexpr std::string_view expected<sym<'='>> = "'='";
template <> inline constexpr std::string_view expected<sym<'.', '.'>> = "'..'";
template <> inline constexpr std::string_view expected<type> = "a type";
template <> inline constexpr std::string_view expected<result_type> = "the function's result type";
template <> inline constexpr std::string_view expected<range> = "an index range (low..high)";
template <> inline constexpr std::string_view expected<kw_end> = "'end'";
template <> inline constexpr std::string_view expected<block_end> = "';' or 'end'";
template <> inline constexpr std::string_view expected<kw_of> = "'of'";
template <> inline constexpr std::string_view expected<of_kw> = "'of'";
template <> inline constexpr std::string_view expected<then_kw> = "'then'";
template <> inline constexpr std::string_view expected<do_kw> = "'do'";
template <> inline constexpr std::string_view expected<until_kw> = "';' or 'until'";
template <> inline constexpr std::string_view expected<for_dir> = "'to' or 'downto'";
template <> inline constexpr std::string_view expected<const_def> = "a constant definition (name = value;)";
template <> inline constexpr std::string_view expected<type_def> = "a type definition (name = type;)";
template <> inline constexpr std::string_view expected<var_decl> = "a variable declaration (names: type;)";
template <> inline constexpr std::string_view expected<param> = "a parameter (name: type)";
template <> inline constexpr std::string_view expected<routine_body> = "'begin' of the routine's body";
template <> inline constexpr std::string_view expected<decl_first> =
    "every declaration (var, const, type, procedure, function) before the first statement";
template <> inline constexpr std::string_view expected<script_end> = "';' or the end of the script";
template <> inline constexpr std::string_view expected<sq_end> = "a closing ' (unterminated string)";
template <> inline constexpr std::string_view expected<dq_end> = "a closing \" (unterminated string)";
template <> inline constexpr std::string_view expected<p::until<brace_close>> = "'}' closing the comment";
template <> inline constexpr std::string_view expected<p::until<paren_close>> = "'*)' closing the comment";
template <> inline constexpr std::string_view expected<brace_close> = "'}' closing the comment";
template <> inline constexpr std::string_view expected<paren_close> = "'*)' closing the comment";
template <> inline constexpr std::string_view expected<digits> = "digits";
template <> inline constexpr std::string_view expected<hex_digits> = "hexadecimal digits";

template <typename Rule>
struct control : p::normal<Rule> {
  template <typename ParseInput, typename... States>
  [[noreturn]] static void raise(const ParseInput& in, States&&...) {
    throw p::parse_error("expected " + std::string(expected<Rule>), in);
  }
};

}  // namespace pikocnc::script::grammar
