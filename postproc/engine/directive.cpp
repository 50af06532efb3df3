#include "postproc/engine/directive.hpp"

#include "toolpath/value.hpp"

namespace postproc {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

// Takes the next word (letters, digits, `_`) off the front of `s`, after blanks.
std::string_view take_word(std::string_view& s) {
  s = trim(s);
  std::size_t n = 0;
  while (n < s.size() && !is_blank(s[n]) && s[n] != '=') ++n;
  std::string_view word = s.substr(0, n);
  s.remove_prefix(n);
  return word;
}

}  // namespace

std::string_view verb_name(Directive::Verb verb) {
  switch (verb) {
    case Directive::Verb::Open: return "open";
    case Directive::Verb::Close: return "close";
    case Directive::Verb::Delete: return "delete";
    case Directive::Verb::Copy: return "copy";
    case Directive::Verb::MakeDir: return "make";
  }
  return "?";
}

std::optional<Directive> parse_directive(std::string_view line) {
  std::string_view s = trim(line);
  if (s.size() < 4 || s.substr(0, 2) != "!!" || s.substr(s.size() - 2) != "!!") return std::nullopt;
  std::string_view body = s.substr(2, s.size() - 4);
  std::string quoted(1, '`');  // built by appends: `"`" + std::string` trips GCC 12's -Wrestrict
  quoted.append(line).push_back('`');

  std::string_view verb = take_word(body);
  std::string_view object = take_word(body);
  Directive d;
  if (toolpath::iequals(verb, "open")) d.verb = Directive::Verb::Open;
  else if (toolpath::iequals(verb, "close")) d.verb = Directive::Verb::Close;
  else if (toolpath::iequals(verb, "delete")) d.verb = Directive::Verb::Delete;
  else if (toolpath::iequals(verb, "copy")) d.verb = Directive::Verb::Copy;
  else if (toolpath::iequals(verb, "make")) d.verb = Directive::Verb::MakeDir;
  else
    throw DirectiveError("unknown output directive " + quoted + ": expected open, close, delete or copy file, or make dir");

  const std::string_view expected_object = d.verb == Directive::Verb::MakeDir ? "dir" : "file";
  if (!toolpath::iequals(object, expected_object))
    throw DirectiveError("malformed output directive " + quoted + ": expected `" + std::string(verb_name(d.verb)) + " " +
                         std::string(expected_object) + " = NAME`");
  body = trim(body);
  if (body.empty() || body.front() != '=')
    throw DirectiveError("malformed output directive " + quoted + ": expected `=` after `" + std::string(object) + "`");
  body = trim(body.substr(1));
  if (body.size() >= 2 && (body.front() == '\'' || body.front() == '"') && body.back() == body.front())
    body = body.substr(1, body.size() - 2);
  if (body.empty()) throw DirectiveError("malformed output directive " + quoted + ": the name is empty");
  d.name = std::string(body);
  return d;
}

}  // namespace postproc
