// Parsing with the PEGTL grammar, then one pass over the parse tree that builds the compiled
// statements and expressions with every name resolved and every type checked.
#include "machines/pikocnc/script/compiler.hpp"

#include <fmt/format.h>

#include <map>

#include "machines/pikocnc/script/builtins.hpp"
#include "machines/pikocnc/script/compile_support.hpp"
#include "machines/pikocnc/script/grammar.hpp"
#include "toolpath/error.hpp"

namespace pikocnc::script {

namespace g = grammar;
namespace p = tao::pegtl;

std::unique_ptr<Program> compile_script(std::string_view text, const std::string& file_name) {
  // A NUL byte would end nothing in PEGTL but would confuse editors and messages: refuse it.
  if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < nul; ++i) {
      if (text[i] == '\n') ++line, column = 1;
      else ++column;
    }
    throw toolpath::InputError({file_name, line, column}, "unexpected NUL byte in the script");
  }
  p::memory_input<> in(text.data(), text.size(), file_name);
  std::unique_ptr<Node> root;
  try {
    root = p::parse_tree::parse<p::seq<g::script, p::eof>, g::selector, p::nothing, g::control>(in);
  } catch (const p::parse_error& e) {
    const auto& at = e.positions().front();
    throw toolpath::InputError({file_name, at.line, at.column}, std::string(e.message()));
  }
  if (!root) throw toolpath::InputError({file_name, 1, 1}, "expected a script");
  Compiler compiler(file_name);
  return compiler.compile(*root);
}

}  // namespace pikocnc::script
