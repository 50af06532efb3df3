// The public entry points (script.hpp) and the parameters file of spec 10.1.
#include <fmt/format.h>

#include "machines/pikocnc/script/compiler.hpp"
#include "machines/pikocnc/script/script.hpp"

namespace pikocnc::script {

std::shared_ptr<const Program> parse_script(std::string_view text, const std::string& file_name) {
  return compile_script(text, file_name);
}

RunResult run_script_text(std::string_view text, const std::string& file_name, const RunInputs& inputs,
                          std::ostream& gcode, std::ostream& diagnostics) {
  const auto program = parse_script(text, file_name);
  return run_script(*program, inputs, gcode, diagnostics);
}

namespace {

std::string_view strip(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// A comment starts at # or ; outside double quotes.
std::string_view without_comment(std::string_view line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    else if (!quoted && (line[i] == '#' || line[i] == ';')) return line.substr(0, i);
  }
  return line;
}

}  // namespace

std::optional<bool> parse_answer(std::string_view text) {
  std::string t(text);
  for (char& c : t)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  if (t == "yes" || t == "true" || t == "1") return true;
  if (t == "no" || t == "false" || t == "0") return false;
  return std::nullopt;
}

void read_parameters(std::string_view text, const std::string& file_name, RunInputs& inputs) {
  enum class Section { None, Constants, Args, Answers } section = Section::None;
  std::size_t number = 0, start = 0;
  // Values from the file must not replace the command line's: collect, then merge under.
  RunInputs file;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view raw = text.substr(start, end - start);
    start = end + 1;
    ++number;
    if (number == 1 && raw.substr(0, 3) == "\xEF\xBB\xBF") raw.remove_prefix(3);  // UTF-8 BOM
    const std::string_view line = strip(without_comment(raw));
    auto error = [&](const std::string& message) {
      throw toolpath::InputError({file_name, number, std::size_t(line.data() - raw.data()) + 1}, message);
    };
    if (line.empty()) {
      if (end == text.size()) break;
      continue;
    }
    if (line.front() == '[') {
      if (line.back() != ']') error("expected ']' closing the section name");
      const std::string name(strip(line.substr(1, line.size() - 2)));
      if (name == "constants") section = Section::Constants;
      else if (name == "args") section = Section::Args;
      else if (name == "answers") section = Section::Answers;
      else error(fmt::format("unknown section [{}] (expected [constants], [args] or [answers])", name));
      continue;
    }
    std::size_t eq = std::string_view::npos;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size() && eq == std::string_view::npos; ++i) {
      if (line[i] == '"') quoted = !quoted;
      else if (!quoted && line[i] == '=') eq = i;
    }
    if (eq == std::string_view::npos) error("expected `key = value`");
    std::string key(strip(line.substr(0, eq)));
    const std::string value(strip(line.substr(eq + 1)));
    switch (section) {
      case Section::None: error("a value before any section ([constants], [args] or [answers])"); break;
      case Section::Constants: file.constants[key] = value; break;
      case Section::Args: file.args[key] = value; break;
      case Section::Answers: {
        const auto answer = parse_answer(value);
        if (!answer) error(fmt::format("answer `{}`: expected yes or no", value));
        if (key == "*") file.default_answer = answer;
        else {
          if (key.size() >= 2 && key.front() == '"' && key.back() == '"') key = key.substr(1, key.size() - 2);
          file.answers[key] = *answer;
        }
        break;
      }
    }
    if (end == text.size()) break;
  }
  for (auto& [k, v] : file.constants) inputs.constants.emplace(k, v);
  for (auto& [k, v] : file.args) inputs.args.emplace(k, v);
  for (auto& [k, v] : file.answers) inputs.answers.emplace(k, v);
  if (!inputs.default_answer) inputs.default_answer = file.default_answer;
}

}  // namespace pikocnc::script
