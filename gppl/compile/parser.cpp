// Line classification (spec 5.1 "statement recognition") and per-line PEGTL parsing.
#include "gppl/compile/parser.hpp"

#include <fmt/format.h>

#include "gppl/error_codes.hpp"
#include "gppl/compile/grammar.hpp"

namespace gppl {

namespace p = tao::pegtl;
namespace g = gppl::grammar;

void split_lines(SourceText& source) {
  source.lines.clear();
  std::string_view all = source.bytes;
  std::size_t start = 0;
  while (start <= all.size()) {
    std::size_t end = all.find('\n', start);
    if (end == std::string_view::npos) end = all.size();
    std::string_view line = all.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (end == all.size() && line.empty()) break;  // no phantom line after the last line end
    source.lines.push_back(line);
    start = end + 1;
  }
}

SourcePos node_pos(const SyntaxNode& n, std::uint32_t file) {
  // The node's source name refers to the (gone) line input: read the iterator directly.
  return SourcePos{file, std::uint32_t(n.m_begin.line), std::uint32_t(n.m_begin.column)};
}

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\x1a'; }
bool is_word(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}
bool iequal(std::string_view a, std::string_view b) { return same_name(a, b); }

// Nesting the recursive-descent parser and the evaluator can take without exhausting the stack.
constexpr int kMaxOperators = 400;

int operator_count(std::string_view text) {
  int count = 0;
  char quote = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quote) {
      if (c == quote) quote = 0;
      continue;
    }
    if (c == '\'' || c == '"') quote = c;
    else if (c == ';') break;
    else if (c == '(' || c == '-' || c == '+' || c == '!' || c == '^' || c == '<' || c == '*' || c == '/') ++count;
    else if (is_word(c) && (i == 0 || !is_word(text[i - 1]))) {
      std::size_t n = i;
      while (n < text.size() && is_word(text[n])) ++n;
      const std::string_view word = text.substr(i, n - i);
      if (iequal(word, "not") || iequal(word, "and") || iequal(word, "or")) ++count;
    }
  }
  return count;
}

struct Classified {
  LineKind kind;
  ErrorCode error;  // reported when the line does not parse
};

Classified classify(std::string_view rest) {
  if (rest.empty() || rest[0] == ';') return {LineKind::Blank, ErrorCode::Unrecognized};
  if (rest[0] == '@') return {LineKind::Header, ErrorCode::Unrecognized};
  if (rest[0] == '{') return {LineKind::Generate, ErrorCode::InvalidGenerate};
  std::size_t n = 0;
  while (n < rest.size() && is_word(rest[n])) ++n;
  if (n == 0) return {LineKind::Invalid, ErrorCode::Unrecognized};
  const std::string_view word = rest.substr(0, n);
  std::size_t after = n;
  while (after < rest.size() && is_blank(rest[after])) ++after;
  const char next = after < rest.size() ? rest[after] : '\0';
  if (iequal(word, "if")) return {LineKind::If, ErrorCode::InvalidIf};
  if (iequal(word, "elseif")) return {LineKind::Elseif, ErrorCode::InvalidIf};
  if (iequal(word, "else")) return {LineKind::Else, ErrorCode::InvalidIf};
  if (iequal(word, "endif")) return {LineKind::Endif, ErrorCode::InvalidIf};
  if (iequal(word, "while")) return {LineKind::While, ErrorCode::Unrecognized};
  if (iequal(word, "endw")) return {LineKind::Endw, ErrorCode::Unrecognized};
  if (iequal(word, "endp")) return {LineKind::Endp, ErrorCode::Unrecognized};
  if (iequal(word, "call")) return {LineKind::Call, ErrorCode::InvalidCall};
  if (iequal(word, "trace")) return {LineKind::Trace, ErrorCode::Unrecognized};
  if (iequal(word, "global")) return {LineKind::Declaration, ErrorCode::InvalidGlobal};
  if (iequal(word, "local")) return {LineKind::Declaration, ErrorCode::InvalidLocal};
  if (iequal(word, "abort") || iequal(word, "exit") || iequal(word, "break") || iequal(word, "return"))
    return {LineKind::Stop, ErrorCode::Unrecognized};
  if (iequal(word, "proc") && next == '@') return {LineKind::Header, ErrorCode::Unrecognized};
  if ((iequal(word, "inc") || iequal(word, "include")) && (next == '\'' || next == '"'))
    return {LineKind::Include, ErrorCode::Unrecognized};
  // input/print are statements unless the line assigns a variable of that name (`print = 1`).
  const bool assigns = (next == '=' && after + 1 < rest.size() && rest[after + 1] != '=') ||
                       (next == '<' && after + 1 < rest.size() && rest[after + 1] == '<');
  if (iequal(word, "input") && !assigns) return {LineKind::Input, ErrorCode::Unrecognized};
  if (iequal(word, "print") && !assigns) return {LineKind::Print, ErrorCode::Unrecognized};
  if ((iequal(word, "change") || iequal(word, "active")) && next == '(')
    return {LineKind::AttrAssignment, ErrorCode::InvalidAssignment};
  // `name = ...` or `name<<i>> = ...`; anything else (a misspelt keyword) is unrecognized.
  if (!(word[0] >= '0' && word[0] <= '9') && (next == '=' || next == '<'))
    return {LineKind::Assignment, ErrorCode::InvalidAssignment};
  return {LineKind::Invalid, ErrorCode::Unrecognized};
}

template <typename Statement>
std::unique_ptr<SyntaxNode> parse_as(p::memory_input<>& in) {
  return p::parse_tree::parse<g::line<Statement>, g::selector, p::nothing, g::control>(in);
}

std::unique_ptr<SyntaxNode> parse_kind(LineKind kind, p::memory_input<>& in) {
  switch (kind) {
    case LineKind::Header: return parse_as<g::proc_header>(in);
    case LineKind::Endp: return parse_as<g::endp_statement>(in);
    case LineKind::Include: return parse_as<g::include_statement>(in);
    case LineKind::Declaration: return parse_as<g::declaration>(in);
    case LineKind::Assignment: return parse_as<g::assignment>(in);
    case LineKind::AttrAssignment: return parse_as<g::attr_assignment>(in);
    case LineKind::If: return parse_as<g::if_statement>(in);
    case LineKind::Elseif: return parse_as<g::elseif_statement>(in);
    case LineKind::Else: return parse_as<g::else_statement>(in);
    case LineKind::Endif: return parse_as<g::endif_statement>(in);
    case LineKind::While: return parse_as<g::while_statement>(in);
    case LineKind::Endw: return parse_as<g::endw_statement>(in);
    case LineKind::Call: return parse_as<g::call_statement>(in);
    case LineKind::Generate: return parse_as<g::generate>(in);
    case LineKind::Trace: return parse_as<g::trace_statement>(in);
    case LineKind::Stop: return parse_as<g::stop_statement>(in);
    case LineKind::Input: return parse_as<g::input_statement>(in);
    case LineKind::Print: return parse_as<g::print_statement>(in);
    default: return nullptr;
  }
}

}  // namespace

ParsedLine parse_line(const SourceText& source, std::uint32_t file, std::uint32_t line_number,
                      std::vector<Error>& errors) {
  const std::string_view text = source.lines[line_number - 1];
  std::size_t indent = 0;
  while (indent < text.size() && is_blank(text[indent])) ++indent;
  ParsedLine result;
  result.pos = SourcePos{file, line_number, std::uint32_t(indent + 1)};
  const Classified c = classify(text.substr(indent));
  result.kind = c.kind;
  auto fail = [&](ErrorCode code, std::uint32_t column, std::string_view detail) {
    errors.push_back(make_error(code, Position{source.name, int(line_number), int(column)}, {}, detail));
    result.root.reset();
    return std::move(result);
  };
  if (c.kind == LineKind::Blank) return result;
  if (c.kind == LineKind::Invalid) return fail(c.error, result.pos.column, "not a GPPL statement");
  if (operator_count(text) > kMaxOperators)
    return fail(ErrorCode::TooComplex, result.pos.column, "statement nests too deeply");
  const std::size_t offset = std::size_t(text.data() - source.bytes.data());
  p::memory_input<> in(text.data(), text.data() + text.size(), source.name, offset, line_number, 1);
  try {
    result.root = parse_kind(c.kind, in);
  } catch (const p::parse_error& e) {
    const auto& at = e.positions().front();
    return fail(c.error, std::uint32_t(at.column), e.message());
  }
  if (!result.root || result.root->children.empty()) {
    // The first token did not match its rule (e.g. `proc` not followed by a name).
    return fail(c.error, result.pos.column, "statement not recognized");
  }
  return result;
}

std::string string_value(const SyntaxNode& literal, std::string& warning, std::string& error) {
  const std::string_view raw = literal.string_view();
  const std::string_view body = raw.substr(1, raw.size() - 2);
  std::string out;
  out.reserve(body.size());
  auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  for (std::size_t i = 0; i < body.size(); ++i) {
    const char c = body[i];
    if (c != '\\' || i + 1 >= body.size()) {
      out += c;
      continue;
    }
    const char e = body[i + 1];
    switch (e) {
      case 'n': out += '\n'; ++i; continue;
      case 'r': out += '\r'; ++i; continue;
      case 't': out += '\t'; ++i; continue;
      case '\\': out += '\\'; ++i; continue;
      case 'x':
      case 'X':
        if (i + 3 < body.size() && hex(body[i + 2]) >= 0 && hex(body[i + 3]) >= 0) {
          const int v = hex(body[i + 2]) * 16 + hex(body[i + 3]);
          if (v == 0) error = "\\x00 is not allowed in a string";
          out += char(v);
          i += 3;
          continue;
        }
        break;
      default: break;
    }
    if (warning.empty()) warning = fmt::format("unknown escape '\\{}' kept as written", e);
    out += c;
  }
  return out;
}

}  // namespace gppl
