#include "lsp/features.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <stdexcept>

#include "gppl/builtins/display_format.hpp"
#include "gppl/builtins/functions.hpp"
#include "gppl/compile/system_variables.hpp"
#include "postproc/engine/command_names.hpp"
#include "toolpath/value.hpp"

namespace lsp {
namespace {

// LSP's CompletionItemKind, SymbolKind, DiagnosticSeverity values used here.
constexpr int kCompletionFunction = 3, kCompletionVariable = 6, kCompletionKeyword = 14, kCompletionSnippet = 15;
constexpr int kSymbolFunction = 12, kSymbolVariable = 13;

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = toolpath::ascii_lower(c);
  return out;
}

struct Word {
  std::uint32_t column = 0;  // 1-based byte column of its first character
  std::string_view text;
};

// The name at or just before byte column `column` of `line` (a procedure name keeps its '@').
Word word_at(std::string_view line, std::uint32_t column) {
  std::size_t i = std::min<std::size_t>(column - 1, line.size());
  if (i > 0 && (i == line.size() || !ident_char(line[i])) && ident_char(line[i - 1])) --i;
  if (i >= line.size() || (!ident_char(line[i]) && line[i] != '@')) return {column, {}};
  std::size_t begin = i, end = i + 1;
  while (begin > 0 && ident_char(line[begin - 1])) --begin;
  if (begin > 0 && line[begin - 1] == '@') --begin;
  while (end < line.size() && ident_char(line[end])) ++end;
  return {static_cast<std::uint32_t>(begin + 1), line.substr(begin, end - begin)};
}

std::string_view kind_word(gppl::SymbolKind k) {
  switch (k) {
    case gppl::SymbolKind::System: return "system variable";
    case gppl::SymbolKind::Host: return "host variable (a command parameter or a machine file's external variable)";
    case gppl::SymbolKind::Global: return "global";
    case gppl::SymbolKind::Local: return "local";
    case gppl::SymbolKind::Procedure: return "procedure";
  }
  return "";
}

std::string type_text(const gppl::Symbol& s) {
  std::string t(gppl::name_of(s.type));
  if (!s.dimensions.empty()) {
    t += " array<<";
    for (std::size_t i = 0; i < s.dimensions.size(); ++i) t += fmt::format("{}{}", i ? "," : "", s.dimensions[i]);
    t += ">>";
  }
  return t;
}

std::string signature(const gppl::FunctionSignature& f) {
  std::string params;
  for (std::size_t i = 0; i < f.parameters.size(); ++i) {
    if (i) params += f.format_argument && i + 1 == f.parameters.size() ? " : " : ", ";
    if (i >= f.min_args) params += "[";
    params += gppl::name_of(f.parameters[i]);
    if (i >= f.min_args) params += "]";
  }
  if (f.no_parentheses) return fmt::format("{} {}", gppl::name_of(f.result), f.name);
  return fmt::format("{} {}({})", gppl::name_of(f.result), f.name, params);
}

std::string system_documentation(const gppl::SystemVariable& v) {
  std::string doc = fmt::format("{}{} · from the {} · default {}", v.read_only ? "read-only " : "",
                                gppl::name_of(v.type), gppl::name_of(v.source),
                                v.default_text.empty() ? "none" : std::string(v.default_text));
  if (!v.meaning.empty()) doc += fmt::format("\n\n{}", v.meaning);
  return doc;
}

// The file index of the document in its own index (its main file), or nullopt when it has none.
std::optional<std::uint32_t> own_file(const Document& doc) {
  for (std::uint32_t i = 0; i < doc.symbols.files.size(); ++i)
    if (doc.symbols.files[i] == doc.path) return i;
  return std::nullopt;
}

const gppl::SymbolUse* use_at(const Document& doc, std::uint32_t line, std::uint32_t column) {
  const auto file = own_file(doc);
  if (!file) return nullptr;
  for (const auto& u : doc.symbols.uses)
    if (u.file == *file && u.line == line && column >= u.column && column <= u.column + u.length) return &u;
  return nullptr;
}

const gppl::SymbolUse* use_at(const Document& doc, const json& params) {
  const auto [line, column] = doc.lines.from_protocol(params.at("position"));
  return use_at(doc, line, column);
}

json location(Workspace& workspace, const std::string& path, std::uint32_t line, std::uint32_t column,
              std::uint32_t length) {
  return {{"uri", path_to_uri(path)}, {"range", workspace.lines_of(path).range(line, column, length)}};
}

// The procedure whose body holds `line` of the document: the last one declared above it.
std::optional<std::uint32_t> enclosing_procedure(const Document& doc, std::uint32_t line) {
  const auto file = own_file(doc);
  std::optional<std::uint32_t> best;
  std::uint32_t best_line = 0;
  if (!file) return best;
  for (const auto& u : doc.symbols.uses) {
    const gppl::Symbol& s = doc.symbols.symbols[u.symbol];
    if (s.kind == gppl::SymbolKind::Procedure && u.declaration && u.file == *file && u.line <= line &&
        u.line >= best_line) {
      best = u.symbol;
      best_line = u.line;
    }
  }
  return best;
}

// A line's first word in lower case, with its '@' for a procedure header ("@line", "endp", "if");
// empty for a blank line. What the block structure of a post hangs on.
std::string leading_word(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const std::string_view t = line.substr(first);
  std::size_t n = t[0] == '@' ? 1 : 0;
  while (n < t.size() && ident_char(t[n])) ++n;
  return lower(t.substr(0, n));
}

bool starts_with_ci(std::string_view text, std::string_view prefix) {
  return text.size() >= prefix.size() && toolpath::iequals(text.substr(0, prefix.size()), prefix);
}

// A display format applied to sample values, as a markdown table (hover, completion).
std::optional<std::string> format_samples(std::string_view spec) {
  try {
    const gppl::DisplayFormat f = gppl::parse_display_format(spec);
    std::string markdown = fmt::format("display format `'{}'`\n\n| value | printed |\n|---|---|\n", spec);
    for (double v : {12.5, -0.125, 3.0, 1234.56789, 0.0})
      markdown += fmt::format("| {} | `{}` |\n", v, gppl::format_value(f, gppl::Value::of_numeric(v)));
    return markdown;
  } catch (const std::exception&) {
    return std::nullopt;  // not a display format
  }
}

// Inside the string of a format assignment (`xpos_f = '5.`) or of an item's format (`xpos:'5.`):
// the byte column just after its opening quote.
std::optional<std::size_t> format_string_start(std::string_view before_cursor) {
  if (std::count(before_cursor.begin(), before_cursor.end(), '\'') % 2 == 0) return std::nullopt;
  const std::size_t quote = before_cursor.rfind('\'');
  std::string_view head = before_cursor.substr(0, quote);
  while (!head.empty() && (head.back() == ' ' || head.back() == '\t')) head.remove_suffix(1);
  if (!head.empty() && head.back() == ':') return quote + 1;
  if (head.empty() || head.back() != '=') return std::nullopt;
  head.remove_suffix(1);
  while (!head.empty() && (head.back() == ' ' || head.back() == '\t')) head.remove_suffix(1);
  return head.size() >= 2 && toolpath::iequals(head.substr(head.size() - 2), "_f") ? std::optional(quote + 1) : std::nullopt;
}

}  // namespace

std::vector<json> diagnostics_by_file(Workspace& workspace, const Document& doc) {
  std::map<std::string, json> by_file;
  by_file[doc.path] = json::array();
  for (const auto& d : doc.diagnostics) {
    const std::string& path = d.where.file.empty() ? doc.path : d.where.file;
    const Lines& lines = path == doc.path ? doc.lines : workspace.lines_of(path);
    const auto line = static_cast<std::uint32_t>(std::max<std::size_t>(d.where.line, 1));
    const auto column = static_cast<std::uint32_t>(std::max<std::size_t>(d.where.column, 1));
    const Word w = word_at(lines.line(line), column);
    const auto length = static_cast<std::uint32_t>(
        w.column == column && !w.text.empty() ? w.text.size() : d.where.line == 0 ? lines.line(1).size() : 1);
    json item = {{"range", lines.range(line, column, length)},
                 {"severity", d.error() ? 1 : 2},
                 {"source", "postproc check"},
                 {"message", d.message}};
    if (d.number) item["code"] = d.number;
    by_file[path].push_back(std::move(item));
  }
  std::vector<json> out;
  out.push_back({{"uri", doc.uri}, {"version", doc.version}, {"diagnostics", by_file[doc.path]}});
  for (auto& [path, items] : by_file)
    if (path != doc.path) out.push_back({{"uri", path_to_uri(path)}, {"diagnostics", std::move(items)}});
  return out;
}

json completion(Workspace&, const Document& doc, const json& params) {
  const auto [line, column] = doc.lines.from_protocol(params.at("position"));
  const std::string_view text = doc.lines.line(line).substr(0, column - 1);
  std::size_t begin = text.size();
  while (begin > 0 && ident_char(text[begin - 1])) --begin;
  const bool at = begin > 0 && text[begin - 1] == '@';
  const std::string_view prefix = text.substr(begin);
  std::string before(text.substr(0, at ? begin - 1 : begin));
  while (!before.empty() && (before.back() == ' ' || before.back() == '\t')) before.pop_back();
  const bool after_call = before.size() >= 4 && toolpath::iequals(std::string_view(before).substr(before.size() - 4), "call");
  json items = json::array();
  if (const auto start = format_string_start(text)) {  // display-format snippets, with what they print
    static constexpr std::pair<std::string_view, std::string_view> kFormats[] = {
        {"5.3", "up to 5 integer and 3 decimal digits, trailing zeros dropped"},
        {"5.3(p)", "the same, a decimal point only when there is a fraction"},
        {"4.3(p)", "feeds"},
        {"5.0(p)", "whole numbers: block numbers, tool numbers"},
        {"2.0(p)", "G and M codes"},
        {"5.3/1", "at least one decimal digit kept"},
        {"<X> 5.3 <>", "with an affix written before the number"},
    };
    for (const auto& [spec, what] : kFormats)
      if (auto samples = format_samples(spec))
        items.push_back({{"label", spec},
                         {"kind", kCompletionSnippet},
                         {"detail", what},
                         {"documentation", {{"kind", "markdown"}, {"value", *samples}}},
                         {"textEdit", {{"range", doc.lines.range(line, static_cast<std::uint32_t>(*start + 1),
                                                                 static_cast<std::uint32_t>(text.size() - *start))},
                                       {"newText", spec}}}});
    return {{"isIncomplete", false}, {"items", std::move(items)}};
  }
  std::set<std::string> seen;
  auto add = [&](std::string label, int kind, std::string detail, std::string documentation = {}) {
    if (!starts_with_ci(label, (at ? "@" : "") + std::string(prefix)) || !seen.insert(lower(label)).second) return;
    json item = {{"label", label}, {"kind", kind}, {"detail", std::move(detail)}};
    if (at) item["insertText"] = label.substr(1);  // the '@' is typed already
    if (!documentation.empty()) item["documentation"] = {{"kind", "markdown"}, {"value", std::move(documentation)}};
    items.push_back(std::move(item));
  };
  if (at || after_call) {  // procedures: the post's own, and (heading a new one) the stream's commands
    for (const auto& s : doc.symbols.symbols)
      if (s.kind == gppl::SymbolKind::Procedure) add(s.name, kCompletionFunction, "procedure of this post");
    if (!after_call)
      for (std::string_view name : postproc::stream_command_names())
        add(std::string(name), kCompletionFunction, "toolpath command");
    return {{"isIncomplete", false}, {"items", std::move(items)}};
  }
  // The post's own names first: locals of the procedure the cursor is in, then globals.
  const auto procedure = enclosing_procedure(doc, line);
  for (const auto& s : doc.symbols.symbols) {
    if (s.kind == gppl::SymbolKind::Local && procedure && s.procedure == *procedure)
      add(s.name, kCompletionVariable, fmt::format("local {}", type_text(s)));
    else if (s.kind == gppl::SymbolKind::Global || s.kind == gppl::SymbolKind::Host)
      add(s.name, kCompletionVariable, fmt::format("{} {}", s.kind == gppl::SymbolKind::Global ? "global" : "host", type_text(s)));
  }
  for (const auto& v : gppl::system_variables())
    add(std::string(v.name), kCompletionVariable, fmt::format("system {}", gppl::name_of(v.type)), system_documentation(v));
  for (const auto& f : gppl::all_functions()) add(std::string(f.name), kCompletionFunction, signature(f));
  for (std::string_view k : {"if", "else", "elseif", "endif", "while", "endw", "call", "endp", "global", "local",
                             "integer", "numeric", "logical", "string", "trace", "input", "print", "exit", "abort",
                             "include", "and", "or", "not", "eq", "ne", "lt", "le", "gt", "ge"})
    add(std::string(k), kCompletionKeyword, "keyword");
  return {{"isIncomplete", false}, {"items", std::move(items)}};
}

json hover(Workspace& workspace, const Document& doc, const json& params) {
  const auto [line, column] = doc.lines.from_protocol(params.at("position"));
  std::string markdown;
  std::optional<json> range;
  if (const gppl::SymbolUse* u = use_at(doc, line, column)) {
    const gppl::Symbol& s = doc.symbols.symbols[u->symbol];
    range = doc.lines.range(u->line, u->column, u->length);
    if (s.kind == gppl::SymbolKind::Procedure) {
      const std::string_view header =
          s.declared ? workspace.lines_of(s.where.file).line(static_cast<std::size_t>(s.where.line)) : std::string_view(s.name);
      markdown = fmt::format("```gppl\n{}\n```\nprocedure, {}:{}", header, s.where.file, s.where.line);
      if (postproc::is_stream_command_name(s.name)) markdown += " · runs for each toolpath command of that name";
    } else if (s.kind == gppl::SymbolKind::System) {
      markdown = fmt::format("```gppl\n{} {}\n```\n", type_text(s), s.name);
      if (const gppl::SystemVariable* v = gppl::find_system_variable(s.name)) markdown += system_documentation(*v);
    } else {
      markdown = fmt::format("```gppl\n{} {}\n```\n{}", type_text(s), s.name, kind_word(s.kind));
      if (s.kind == gppl::SymbolKind::Local) markdown += fmt::format(" of {}", doc.symbols.symbols[s.procedure].name);
      if (s.declared) markdown += fmt::format(", declared at {}:{}", s.where.file, s.where.line);
    }
  } else {
    const std::string_view text = doc.lines.line(line);
    const Word w = word_at(text, column);
    if (const gppl::FunctionSignature* f = w.text.empty() ? nullptr : gppl::find_function(w.text)) {
      markdown = fmt::format("```gppl\n{}\n```\nbuilt-in function", signature(*f));
      range = doc.lines.range(line, w.column, static_cast<std::uint32_t>(w.text.size()));
    } else {
      // Inside a string literal that is a display format: the format applied to sample values.
      const std::size_t at = column - 1;
      const std::size_t open = text.rfind('\'', at == 0 ? 0 : at - 1);
      const std::size_t close = open == std::string_view::npos ? open : text.find('\'', open + 1);
      if (open != std::string_view::npos && close != std::string_view::npos && at > open && at <= close) {
        if (auto samples = format_samples(text.substr(open + 1, close - open - 1))) {
          markdown = std::move(*samples);
          range = doc.lines.range(line, static_cast<std::uint32_t>(open + 1), static_cast<std::uint32_t>(close - open + 1));
        }
      }
    }
  }
  if (markdown.empty()) return nullptr;
  json result = {{"contents", {{"kind", "markdown"}, {"value", markdown}}}};
  if (range) result["range"] = *range;
  return result;
}

json signature_help(const Document& doc, const json& params) {
  const auto [line, column] = doc.lines.from_protocol(params.at("position"));
  const std::string_view text = doc.lines.line(line).substr(0, column - 1);
  int depth = 0, commas = 0;
  for (std::size_t i = text.size(); i-- > 0;) {
    const char c = text[i];
    if (c == ')') ++depth;
    else if (c == ',' && depth == 0) ++commas;
    else if (c == '(' && depth-- == 0) {
      const Word w = word_at(text.substr(0, i), static_cast<std::uint32_t>(i));
      const gppl::FunctionSignature* f = w.text.empty() ? nullptr : gppl::find_function(w.text);
      if (!f) return nullptr;
      json parameters = json::array();
      for (const auto t : f->parameters) parameters.push_back({{"label", std::string(gppl::name_of(t))}});
      return {{"signatures", json::array({{{"label", signature(*f)}, {"parameters", parameters}}})},
              {"activeSignature", 0},
              {"activeParameter", commas}};
    }
  }
  return nullptr;
}

json definition(Workspace& workspace, const Document& doc, const json& params) {
  const gppl::SymbolUse* u = use_at(doc, params);
  if (!u) return nullptr;
  const gppl::Symbol& s = doc.symbols.symbols[u->symbol];
  if (!s.declared) return nullptr;  // a system or host name: declared by SolidCAM, not in a file
  return location(workspace, s.where.file, static_cast<std::uint32_t>(s.where.line),
                  static_cast<std::uint32_t>(s.where.column), static_cast<std::uint32_t>(s.name.size()));
}

json references(Workspace& workspace, const Document& doc, const json& params) {
  const gppl::SymbolUse* at = use_at(doc, params);
  if (!at) return json::array();
  const bool with_declaration = params.value("/context/includeDeclaration"_json_pointer, true);
  json out = json::array();
  for (const auto& u : doc.symbols.uses)
    if (u.symbol == at->symbol && (with_declaration || !u.declaration))
      out.push_back(location(workspace, doc.symbols.files[u.file], u.line, u.column, u.length));
  return out;
}

json rename(Workspace& workspace, const Document& doc, const json& params) {
  const gppl::SymbolUse* at = use_at(doc, params);
  if (!at) throw std::invalid_argument("no variable or procedure of the post here");
  const gppl::Symbol& s = doc.symbols.symbols[at->symbol];
  const std::string name = params.at("newName").get<std::string>();
  if (s.kind == gppl::SymbolKind::System || s.kind == gppl::SymbolKind::Host)
    throw std::invalid_argument(fmt::format("'{}' is SolidCAM's name: the post cannot rename it", s.name));
  const bool procedure = s.kind == gppl::SymbolKind::Procedure;
  if (procedure && postproc::is_stream_command_name(s.name))
    throw std::invalid_argument(fmt::format("{} runs for the toolpath's {} commands: renamed, it would never run", s.name, s.name));
  const std::string_view body = procedure && !name.empty() && name[0] == '@' ? std::string_view(name).substr(1) : name;
  if (body.empty() || body.size() > 60 || std::isdigit(static_cast<unsigned char>(body[0])) ||
      !std::all_of(body.begin(), body.end(), ident_char) || (procedure && name[0] != '@'))
    throw std::invalid_argument(fmt::format("'{}' is no {} name", name, procedure ? "procedure (@name)" : "variable"));
  json changes = json::object();
  for (const auto& u : doc.symbols.uses) {
    if (u.symbol != at->symbol) continue;
    const std::string& path = doc.symbols.files[u.file];
    changes[path_to_uri(path)].push_back({{"range", workspace.lines_of(path).range(u.line, u.column, u.length)},
                                         {"newText", name}});
  }
  return {{"changes", std::move(changes)}};
}

json document_symbols(const Document& doc) {
  json out = json::array();
  const auto file = own_file(doc);
  if (!file) return out;
  for (const auto& u : doc.symbols.uses) {
    const gppl::Symbol& s = doc.symbols.symbols[u.symbol];
    if (!u.declaration || u.file != *file ||
        (s.kind != gppl::SymbolKind::Procedure && s.kind != gppl::SymbolKind::Global))
      continue;
    const bool procedure = s.kind == gppl::SymbolKind::Procedure;
    std::uint32_t last = u.line;  // a procedure reaches its ENDP
    if (procedure)
      for (std::uint32_t l = u.line + 1; l <= doc.lines.count(); ++l) {
        const std::string word = leading_word(doc.lines.line(l));
        if (word == "endp") {
          last = l;
          break;
        }
        if (!word.empty() && word[0] == '@') break;
      }
    const json selection = doc.lines.range(u.line, u.column, u.length);
    out.push_back({{"name", s.name},
                   {"detail", procedure ? "" : type_text(s)},
                   {"kind", procedure ? kSymbolFunction : kSymbolVariable},
                   {"range", {{"start", doc.lines.to_protocol(u.line, 1)},
                              {"end", doc.lines.to_protocol(last, static_cast<std::uint32_t>(doc.lines.line(last).size() + 1))}}},
                   {"selectionRange", selection}});
  }
  return out;
}

json code_actions(const Document& doc, const json& params) {
  json out = json::array();
  for (const json& d : params.at("context").at("diagnostics")) {
    const int code = d.contains("code") && d["code"].is_number_integer() ? d["code"].get<int>() : 0;
    const std::string message = d.value("message", "");
    // "... did you mean 'blknum'?" (a name), "...; did you mean @rapid_move?" (a procedure)
    if (const std::size_t at = message.rfind("did you mean "); at != std::string::npos) {
      std::string guess = message.substr(at + 13);
      if (!guess.empty() && guess.back() == '?') guess.pop_back();
      if (guess.size() > 2 && guess.front() == '\'' && guess.back() == '\'') guess = guess.substr(1, guess.size() - 2);
      if (!guess.empty() && std::all_of(guess.begin() + (guess[0] == '@'), guess.end(), ident_char))
        out.push_back({{"title", fmt::format("Change to {}", guess)},
                       {"kind", "quickfix"},
                       {"diagnostics", json::array({d})},
                       {"isPreferred", true},
                       {"edit", {{"changes", {{doc.uri, json::array({{{"range", d["range"]}, {"newText", guess}}})}}}}}});
    }
    if (code != 383 && code != 404) continue;
    // Declare it in the procedure it is used in, after the header: the user picks the type.
    const auto [line, column] = doc.lines.from_protocol(d.at("range").at("start"));
    const Word w = word_at(doc.lines.line(line), column);
    const auto procedure = enclosing_procedure(doc, line);
    if (w.text.empty() || w.text[0] == '@' || !procedure) continue;
    const gppl::Symbol& p = doc.symbols.symbols[*procedure];
    const auto header = static_cast<std::uint32_t>(p.where.line);
    for (std::string_view type : {"numeric", "integer", "string", "logical"})
      out.push_back({{"title", fmt::format("Declare '{}' as a local {} of {}", w.text, type, p.name)},
                     {"kind", "quickfix"},
                     {"diagnostics", json::array({d})},
                     {"edit", {{"changes", {{doc.uri, json::array({{{"range", doc.lines.range(header + 1, 1, 0)},
                                                                   {"newText", fmt::format("  local {} {}\n", type, w.text)}}})}}}}}});
  }
  return out;
}

json formatting(const Document& doc, const json& params) {
  const json& options = params.at("options");
  // A tab size the client may send as anything: 1 to 16 blanks.
  const auto tab = static_cast<std::size_t>(std::clamp<std::int64_t>(options.value("tabSize", std::int64_t{2}), 1, 16));
  const std::string unit = options.value("insertSpaces", true) ? std::string(tab, ' ') : "\t";
  json edits = json::array();
  int depth = 0;
  bool in_procedure = false;
  for (std::uint32_t l = 1; l <= doc.lines.count(); ++l) {
    const std::string_view text = doc.lines.line(l);
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) continue;  // blank: as it is
    const std::string word = leading_word(text);
    int level = in_procedure ? 1 + depth : 0;
    if (word.size() > 1 && word[0] == '@') {
      in_procedure = true;
      depth = 0;
      level = 0;
    } else if (word == "endp") {
      in_procedure = false;
      depth = 0;
      level = 0;
    } else if (word == "endif" || word == "endw") {
      depth = std::max(0, depth - 1);
      level = in_procedure ? 1 + depth : 0;
    } else if (word == "else" || word == "elseif") {
      level = in_procedure ? std::max(1, depth) : 0;
    }
    std::string indent;
    for (int i = 0; i < level; ++i) indent += unit;
    if (text.substr(0, first) != indent)
      edits.push_back({{"range", {{"start", {{"line", l - 1}, {"character", 0}}},
                                  {"end", doc.lines.to_protocol(l, static_cast<std::uint32_t>(first + 1))}}},
                       {"newText", indent}});
    if (word == "if" || word == "while") ++depth;
  }
  return edits;
}

json folding_ranges(const Document& doc) {
  json out = json::array();
  std::vector<std::pair<std::string, std::uint32_t>> open;  // what opened, on which line
  auto close = [&](std::string_view what, std::uint32_t line) {
    for (std::size_t i = open.size(); i-- > 0;)
      if (open[i].first == what) {
        if (line > open[i].second + 1) out.push_back({{"startLine", open[i].second - 1}, {"endLine", line - 2}});
        open.resize(i);
        return;
      }
  };
  for (std::uint32_t l = 1; l <= doc.lines.count(); ++l) {
    const std::string word = leading_word(doc.lines.line(l));
    if (word.size() > 1 && word[0] == '@') open.emplace_back("@", l);
    else if (word == "if" || word == "while") open.emplace_back(word, l);
    else if (word == "endp") close("@", l + 1);
    else if (word == "endif") close("if", l);
    else if (word == "endw") close("while", l);
  }
  return out;
}

}  // namespace lsp
