// Line parser: classifies one source line by its first word and parses it with the grammar into a
// parse tree (the AST of that statement), or reports the GPPTool error of that statement kind.
#pragma once

#include <tao/pegtl/contrib/parse_tree.hpp>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "gppl/program.hpp"

namespace gppl {

using SyntaxNode = tao::pegtl::parse_tree::node;

enum class LineKind : std::uint8_t {
  Blank, Header, Endp, Include, Declaration, Assignment, AttrAssignment, If, Elseif, Else, Endif, While, Endw,
  Call, Generate, Trace, Stop, Input, Print, Invalid
};

struct ParsedLine {
  LineKind kind = LineKind::Blank;   // kept when the line has a syntax error (the structure still counts)
  SourcePos pos;                     // first character of the statement
  std::unique_ptr<SyntaxNode> root;  // null for blank lines and syntax errors
  bool valid() const { return root != nullptr; }
  const SyntaxNode& statement() const { return *root->children.front(); }
};

// A source file's bytes and its split lines (CR LF or LF; bytes kept as they are).
struct SourceText {
  std::string name;
  std::string bytes;
  std::vector<std::string_view> lines;
};
void split_lines(SourceText& source);

// Parses line `line_number` (1-based) of `source`. On a syntax error, appends the error (with its
// GPPTool number for the statement kind) and returns a line without a tree.
ParsedLine parse_line(const SourceText& source, std::uint32_t file, std::uint32_t line_number,
                      std::vector<Error>& errors);

// The text of a string literal node with its escapes applied (\n \r \t \\ \xNN). Unknown or
// malformed escapes are kept verbatim and described in `warning`; `\x00` is described in `error`.
std::string string_value(const SyntaxNode& literal, std::string& warning, std::string& error);

// Position of a node's first character.
SourcePos node_pos(const SyntaxNode& n, std::uint32_t file);

}  // namespace gppl
