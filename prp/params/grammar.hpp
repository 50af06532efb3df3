// PEGTL grammar of PRP lines and of the value forms (spec 1.2). The loader classifies each line
// with these rules and checks every value token against the value rules.
#pragma once

#include <string_view>

#include <tao/pegtl.hpp>

namespace prp::grammar {

namespace pegtl = tao::pegtl;

// Values
struct sign : pegtl::one<'+', '-'> {};
struct digits : pegtl::plus<pegtl::digit> {};
struct integer : pegtl::seq<pegtl::opt<sign>, digits> {};
struct mantissa : pegtl::sor<pegtl::seq<digits, pegtl::opt<pegtl::one<'.'>, pegtl::star<pegtl::digit>>>,
                             pegtl::seq<pegtl::one<'.'>, digits>> {};
struct exponent : pegtl::seq<pegtl::one<'e', 'E'>, pegtl::opt<sign>, digits> {};
struct number : pegtl::seq<pegtl::opt<sign>, mantissa, pegtl::opt<exponent>> {};
// GPPL identifiers: a letter first (record names and parameters become variables).
struct identifier : pegtl::seq<pegtl::alpha, pegtl::star<pegtl::identifier_other>> {};

// Lines (after non-breaking spaces were turned into blanks)
struct ws : pegtl::star<pegtl::blank> {};
struct comment : pegtl::seq<pegtl::one<';'>, pegtl::star<pegtl::any>> {};
struct empty_line : pegtl::seq<ws, pegtl::opt<comment>, pegtl::eof> {};
struct header_rest : pegtl::star<pegtl::any> {};
struct header : pegtl::seq<ws, TAO_PEGTL_ISTRING("@pre_processor"), header_rest> {};
struct end_line : pegtl::seq<ws, TAO_PEGTL_ISTRING("endp"), ws, pegtl::opt<comment>, pegtl::eof> {};
struct key : pegtl::identifier {};  // letter or '_' first: `_4th_axes_around`
struct value_text : pegtl::star<pegtl::not_one<';'>> {};
struct assignment : pegtl::seq<ws, key, ws, pegtl::one<'='>, value_text, pegtl::opt<comment>, pegtl::eof> {};

// True when `text` is exactly one `Rule`.
template <class Rule>
bool matches(std::string_view text) {
  pegtl::memory_input in(text.data(), text.size(), "");
  return pegtl::parse<pegtl::seq<Rule, pegtl::eof>>(in);
}

}  // namespace prp::grammar
