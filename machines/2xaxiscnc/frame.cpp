#include "machines/2xaxiscnc/frame.hpp"

#include "toolpath/value.hpp"

namespace twoaxis {

namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

bool starts_with(std::string_view s, std::string_view prefix, bool& case_differs) {
  if (s.size() < prefix.size()) return false;
  const std::string_view head = s.substr(0, prefix.size());
  if (head == prefix) return true;
  if (!toolpath::iequals(head, prefix)) return false;
  case_differs = true;
  return true;
}

}  // namespace

Frame split_frame(std::string_view line) {
  Frame f;
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n) {
    while (i < n && blank(line[i])) ++i;
    if (i == n) break;
    const std::size_t start = i;
    while (i < n && !blank(line[i])) ++i;
    if (f.count < Frame::kKept) {
      f.commands[f.count] = line.substr(start, i - start);
      f.columns[f.count] = start + 1;
    }
    ++f.count;
  }
  return f;
}

Classified classify(std::string_view c) {
  Classified r;
  if (c.size() >= 2 && c.front() == '(' && c.back() == ')') {
    r.kind = Instruction::Comment;
    r.argument = c.substr(1, c.size() - 2);
    r.argument_offset = 1;
    return r;
  }
  struct Exact {
    std::string_view word;
    Instruction kind;
  };
  static constexpr Exact kExact[] = {
      {"XHYH", Instruction::HomeXY},       {"X0Y0", Instruction::GotoZero}, {"SpEn", Instruction::SpindleToggle},
      {"M03", Instruction::SpindleOn},     {"M05", Instruction::SpindleOff}, {"AH", Instruction::HomeA},
      {"G90", Instruction::G90Marker},     {"G91", Instruction::G91Marker},
      {"ArtCam_file_for_2XAxisCNC", Instruction::ArtCamMarker},
  };
  for (const Exact& e : kExact) {
    if (c.size() != e.word.size()) continue;
    bool differs = false;
    if (starts_with(c, e.word, differs)) {
      r.kind = e.kind;
      r.case_differs = differs;
      return r;
    }
  }
  // Prefixed forms: the argument follows the prefix directly.
  struct Prefixed {
    std::string_view prefix;
    Instruction kind;
  };
  static constexpr Prefixed kPrefixed[] = {
      {"Out", Instruction::Relay}, {"Imp_", Instruction::Pulses}, {"RunScript_", Instruction::Script},
      {"P", Instruction::Pause},   {"A", Instruction::AMove},
  };
  for (const Prefixed& p : kPrefixed) {
    bool differs = false;
    if (c.size() <= p.prefix.size() || !starts_with(c, p.prefix, differs)) continue;
    const std::string_view arg = c.substr(p.prefix.size());
    if (p.kind == Instruction::Relay && !(arg.size() == 1 && arg[0] >= '1' && arg[0] <= '4')) continue;
    if (p.kind == Instruction::Script) {
      // RunScript_<name>.script: the name is what comes before the extension
      constexpr std::string_view ext = ".script";
      if (arg.size() <= ext.size() || arg.substr(arg.size() - ext.size()) != ext) continue;
    }
    r.kind = p.kind;
    r.case_differs = differs;
    r.argument = arg;
    r.argument_offset = p.prefix.size();
    return r;
  }
  return r;
}

}  // namespace twoaxis
