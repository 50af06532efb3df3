#include "machines/iso/reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <Eigen/Core>

#include "machines/ncmodel/block_text.hpp"
#include "machines/ncmodel/line_reader.hpp"
#include "machines/ncmodel/motion_out.hpp"
#include "toolpath/error.hpp"
#include "toolpath/geometry.hpp"

namespace iso {

namespace {

namespace geo = toolpath::geometry;

constexpr Rules kRules[] = {
    // Fanuc 0i/31i (M): M98/M99 subprograms, custom macro B loops, G4 P in milliseconds.
    {"fanuc", "Fanuc", true, true, true, false, true, true, 0.1},
    // LinuxCNC 2.8+: o-word subroutines and repeats, Fanuc-style M98/M99 too, P in seconds.
    {"linuxcnc", "LinuxCNC", true, true, true, true, false, false, 0.254},
    // Mach3/Mach4: M98/M99, P in seconds (the default setting).
    {"mach3", "Mach3", true, true, true, false, false, false, 0.254, Scaling::PerAxis},
    // GRBL 1.1: no cycles, no tool changer, no subprograms.
    {"grbl", "GRBL", false, false, false, false, false, false, 0.254},
};

using ncmodel::BlockError;
using ncmodel::Cursor;
using ncmodel::whole;

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A word's value: a number, #n, or [expression] (macro B).
struct Word {
  char letter = 0;  // upper case
  double value = 0;
  std::size_t column = 1;
};

// The words of a block, in order, and where the first of each letter is: execute() asks for a
// letter a dozen times a block.
struct Words {
  std::vector<Word> list;
  std::array<std::uint32_t, 26> first{};  // 1 + its index in list; 0: none

  void clear() {  // keeps the buffer (no allocation a block); only the letters used are reset
    for (const Word& w : list) first[static_cast<std::size_t>(w.letter - 'A')] = 0;
    list.clear();
  }
  void add(const Word& w) {
    std::uint32_t& at = first[static_cast<std::size_t>(w.letter - 'A')];
    if (at == 0) at = static_cast<std::uint32_t>(list.size() + 1);
    list.push_back(w);
  }
  // The block's first word of `letter` (upper case), or nullptr.
  const Word* find(char letter) const {
    const std::uint32_t at = first[static_cast<std::size_t>(letter - 'A')];
    return at == 0 ? nullptr : &list[at - 1];
  }
};

}  // namespace

const Rules* rules_of(std::string_view dialect) {
  const std::string d = lower(dialect);
  for (const Rules& r : kRules)
    if (r.name == d) return &r;
  return nullptr;
}

struct IsoReader::Impl {
  const Rules& rules;
  Options options;
  std::string name;
  std::unique_ptr<std::istream> stream;
  std::unique_ptr<ncmodel::LineReader> lines;
  // O<n> lines (Fanuc) and o<name> sub lines (LinuxCNC), their starts: found on the first M98 or
  // call that needs one (index_labels), as most programs have none.
  std::map<long long, ncmodel::LineReader::Mark> programs;
  std::map<std::string, ncmodel::LineReader::Mark> subs;
  bool labels_indexed = false;
  ncmodel::LineReader::Mark start;  // of the program
  ncmodel::LineReader::Mark before;                         // where the line read last starts
  std::size_t current_line = 0, command_line = 0;
  toolpath::Diagnostics diagnostics;
  std::set<std::string> warned;
  std::size_t executed = 0;
  bool finished = false, started = false, percent_seen = false;
  ncmodel::MotionOut out;
  Words words_;                                // of the block being executed
  std::vector<const Word*> g_codes_, m_codes_;

  struct Frame {  // a subprogram being run
    ncmodel::LineReader::Mark body, back;
    long long repeats_left = 0;
    std::string o_name;  // LinuxCNC o-word sub: its endsub returns
    std::map<long long, double> caller_locals;  // LinuxCNC: #1-#30 of the caller, back at endsub
  };
  std::vector<Frame> calls;
  struct Repeat {  // o<n> repeat, WHILE .. DOm
    std::string key;
    ncmodel::LineReader::Mark body;
    long long remaining = 0;
  };
  std::vector<Repeat> repeats;
  std::map<long long, double> macro;  // #n
  std::map<std::string, double> named;  // LinuxCNC #<name>

  // modal state
  int motion = 0;  // 0..3, or a cycle 73, 81..89
  geo::Plane plane = geo::Plane::XY;
  bool absolute = true, absolute_centres = false, inch = false;
  bool return_to_r = false;  // G99
  double feed = 0, speed = 0;
  std::optional<double> selected_tool;
  // Tool length compensation, with a tool table: the length G43 applies (0: G49) less the length of
  // the tool in the spindle is where the tip is below the programmed Z (docs/iso.md, "Tool table").
  std::optional<std::int64_t> spindle_tool;  // none before the first M6: no length known
  double applied_length = 0, spindle_length = 0;
  double length_shift() const { return applied_length - spindle_length; }
  struct Cycle {
    double z = 0, r = 0, q = 0, p = 0;
    double initial = 0;
  } cycle;
  bool cycle_defined = false;

  Impl(std::unique_ptr<std::istream> in, std::string n, const Rules& r, Options o)
      : rules(r), options(o), name(std::move(n)), stream(std::move(in)), diagnostics(o.max_diagnostics) {
    lines = std::make_unique<ncmodel::LineReader>(*stream, name);
    start = lines->mark();
  }

  // One pass over the whole program for its O numbers and o-word subs, the first time one is
  // looked up, then back to where the reading is.
  void index_labels() {
    if (labels_indexed) return;
    labels_indexed = true;
    const ncmodel::LineReader::Mark back = lines->mark();
    lines->seek(start);
    std::string_view text;
    for (;;) {
      const ncmodel::LineReader::Mark at = lines->mark();
      if (!lines->next(text)) break;
      Cursor c{text, 0};
      skip_block_number(c);
      // O<n>, or :<n> (the ISO tape code's program number, Mach3's subprogram label)
      const char head = c.peek();
      if (head != 'O' && head != 'o' && head != ':') continue;
      ++c.i;
      const std::string_view digits = c.digits();
      if (digits.empty() || digits.size() > 9) continue;
      const long long number = std::strtoll(std::string(digits).c_str(), nullptr, 10);
      if (head != ':' && c.keyword().rfind("sub", 0) == 0) subs.emplace(fmt::format("o{}", number), at);
      else if (!programs.count(number)) programs.emplace(number, at);
    }
    lines->seek(back);
  }

  void diagnose(bool error, std::size_t column, std::string message) {
    diagnostics.add({{name, current_line, column}, error ? toolpath::Severity::Error : toolpath::Severity::Warning,
                     std::move(message)});
  }
  void warn_once(const std::string& key, std::size_t column, std::string message) {
    if (warned.insert(key).second) diagnose(false, column, std::move(message));
  }
  double unit() const { return inch ? 25.4 : 1.0; }

  // Program coordinates to the work frame the toolpath is in: a scale per axis (Mach3's G51), then
  // the G92 and G52 shifts.
  Eigen::Vector3d g92 = Eigen::Vector3d::Zero(), g52 = Eigen::Vector3d::Zero();
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  double to_work(int axis, double programmed) const {
    return programmed * unit() * scale[axis] + g92[axis] + g52[axis] + (axis == 2 ? length_shift() : 0.0);
  }
  double step(int axis, double programmed) const { return programmed * unit() * scale[axis]; }  // G91, I J K
  bool uniform_in(geo::Plane p) const { return scale[geo::axes(p).first] == scale[geo::axes(p).second]; }

  // ---------------------------------------------------------------- expressions (macro B)





  double value(Cursor& c) {
    const char ch = c.peek();
    if (ch == '[') {
      ++c.i;
      const double v = expression(c);
      if (!std::isfinite(v)) throw BlockError{c.column(), "the expression has no finite value"};
      if (c.peek() != ']') throw BlockError{c.column(), "expected `]`"};
      ++c.i;
      return v;
    }
    if (ch == '#') {
      if (!rules.macro_b && !rules.o_words) throw BlockError{c.column(), fmt::format("{} has no # variables", rules.title)};
      ++c.i;
      const std::size_t col = c.column();
      if (c.peek() == '<') {  // LinuxCNC's named parameter #<name>
        const std::string key = named_parameter(c);
        auto it = named.find(key);
        if (it == named.end()) throw BlockError{col, fmt::format("#<{}> has no value yet", key)};
        return it->second;
      }
      const double n = value(c);
      if (n < 0 || n > 99999) throw BlockError{col, fmt::format("#{} is no variable", n)};
      auto it = macro.find(whole(n, col, "variable number"));
      return it == macro.end() ? 0.0 : it->second;
    }
    if (ncmodel::is_letter(ch)) return function(c);
    if (ch == '-') {
      ++c.i;
      return -value(c);
    }
    return c.number();
  }



  // SIN COS TAN (degrees), ATAN[a]/[b], SQRT ABS ROUND FIX FUP of a [ ] argument. FIX and FUP: Fanuc
  // drops or adds the fraction (toward or away from zero); LinuxCNC rounds down or up.
  double function(Cursor& c) {
    const std::size_t column = c.column();
    const std::string name = c.keyword();
    if (c.peek() != '[') throw BlockError{column, fmt::format("expected a number, found `{}`", name)};
    const double a = value(c);
    constexpr double kDegree = 3.14159265358979323846 / 180;
    const bool fanuc = rules.macro_b;
    if (name == "sin") return std::sin(a * kDegree);
    if (name == "cos") return std::cos(a * kDegree);
    if (name == "tan") return std::tan(a * kDegree);
    if (name == "atan") {
      if (c.peek() != '/') return std::atan(a) / kDegree;
      ++c.i;
      return std::atan2(a, value(c)) / kDegree;
    }
    if (name == "sqrt") {
      if (a < 0) throw BlockError{column, "SQRT of a negative number"};
      return std::sqrt(a);
    }
    if (name == "abs") return std::abs(a);
    if (name == "round") return std::round(a);
    if (name == "fix") return fanuc ? std::trunc(a) : std::floor(a);
    if (name == "fup") return fanuc ? (a < 0 ? std::floor(a) : std::ceil(a)) : std::ceil(a);
    throw BlockError{column, fmt::format("`{}` is no function the model knows", name)};
  }

  double product(Cursor& c) {
    double v = value(c);
    for (;;) {
      if (c.peek() == '*') {
        ++c.i;
        v *= value(c);
      } else if (c.peek() == '/') {
        ++c.i;
        const double d = value(c);
        if (d == 0) throw BlockError{c.column(), "division by zero"};
        v /= d;
      } else {
        return v;
      }
    }
  }

  double sum(Cursor& c) {
    double v = product(c);
    for (;;) {
      if (c.peek() == '+') {
        ++c.i;
        v += product(c);
      } else if (c.peek() == '-') {
        ++c.i;
        v -= product(c);
      } else {
        return v;
      }
    }
  }

  // Comparisons (EQ NE LT LE GT GE) joined by AND / OR, inside [ ].
  double expression(Cursor& c) {
    double v = sum(c);
    for (;;) {
      const std::size_t save = c.i;
      const std::string op = c.keyword();
      if (op == "eq") v = v == sum(c);
      else if (op == "ne") v = v != sum(c);
      else if (op == "lt") v = v < sum(c);
      else if (op == "le") v = v <= sum(c);
      else if (op == "gt") v = v > sum(c);
      else if (op == "ge") v = v >= sum(c);
      else if (op == "and") v = (v != 0 && sum(c) != 0);
      else if (op == "or") v = (v != 0 || sum(c) != 0);
      else {
        c.i = save;
        return v;
      }
    }
  }

  // ---------------------------------------------------------------- reading
  bool read_line(std::string_view& text) {
    before = lines->mark();
    if (!lines->next(text)) return false;
    current_line = lines->line_number();
    return true;
  }

  // The line without its ( ) comments and what follows `;`, in `out` (reused: no allocation per
  // block). A line without comments is returned as it is.
  static std::string_view strip(std::string_view line, bool& unclosed, std::string& out) {
    unclosed = false;
    // One scan for both (find_first_of("(;") calls memchr on the set for every byte of the line).
    if (ncmodel::find_either(line.data(), line.size(), '(', ';') == line.size()) return line;
    out.clear();
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (line[i] == ';') break;
      if (line[i] == '(') {
        const std::size_t close = line.find(')', i);
        if (close == std::string_view::npos) {
          unclosed = true;
          break;
        }
        out += ' ';
        i = close;
        continue;
      }
      out += line[i];
    }
    return out;
  }
  std::string block_text_, skipped_text_;  // strip()'s buffers: the block's, and skip_to()'s

  void run() {
    std::string_view raw;
    while (out.empty() && !finished && read_line(raw)) {
      if (++executed > options.max_executed_blocks) {
        diagnose(true, 1, fmt::format("more than {} blocks executed: a runaway loop?", options.max_executed_blocks));
        finished = true;
        return;
      }
      command_line = current_line;
      try {
        block(raw);
      } catch (const BlockError& e) {
        diagnose(true, e.column, e.message);
      }
    }
    if (finished || !out.empty()) return;
    // The end of the file without M2/M30 (or the closing %): the program ends there.
    if (!calls.empty()) diagnose(true, 1, "the file ends inside a subprogram (no M99 or endsub)");
    else if (!repeats.empty()) {
      const std::string& key = repeats.back().key;  // do<m> (WHILE) or o<n> (repeat)
      diagnose(true, 1, fmt::format("the file ends inside a loop (no {})",
                                    key.rfind("do", 0) == 0 ? "END" + key.substr(2) : key + " endrepeat"));
    }
    else diagnose(false, 1, "the program ends without M2, M30 or %");
    finish();
  }

  void block(std::string_view raw) {
    bool unclosed = false;
    const std::string_view text = strip(raw, unclosed, block_text_);
    if (unclosed) throw BlockError{raw.find('(') + 1, "a comment without its `)`"};
    // A loop, not find_first_not_of(" \t\r"), which calls memchr on the set for every byte.
    std::size_t first = 0;
    while (first < text.size() && (text[first] == ' ' || text[first] == '\t' || text[first] == '\r')) ++first;
    if (first == text.size()) return;
    if (text[first] == '%') {
      if (!rules.subprograms) {  // GRBL: its senders drop the line; GRBL itself answers error 1
        warn_once("%", first + 1, fmt::format("{} itself takes no `%` (a sender drops the line): ignored", rules.title));
        return;
      }
      if (percent_seen) {  // the end of the program
        finish();
        return;
      }
      percent_seen = true;
      return;
    }
    Cursor c{text, first};
    skip_block_number(c);
    const char head = c.peek();  // what the block opens with, after its number
    // :<n>, the ISO tape code's O: a program number (Mach3 labels its subprograms so)
    if (head == ':') {
      const std::size_t col = c.column();
      ++c.i;
      whole(c.number(), col, "program number");
      if (!rules.subprograms) throw BlockError{col, fmt::format("{} takes no program numbers", rules.title)};
      return;
    }
    // O words: a program number (Fanuc), or LinuxCNC's o-word control
    if (head == 'O' || head == 'o') {
      const std::size_t col = c.column();
      ++c.i;
      if (!std::isdigit(static_cast<unsigned char>(c.peek())))
        throw BlockError{col, "o<name> words are not modelled: use numbered o-words"};
      const long long number = whole(c.number(), col, "o-word number");
      const std::string word = c.keyword();
      if (word.empty()) {
        if (!rules.subprograms) throw BlockError{col, fmt::format("{} takes no O program numbers", rules.title)};
        return;  // a program's number: reached in sequence, it is only a label
      }
      if (!rules.o_words) throw BlockError{col, fmt::format("{} has no o-word control (`o{} {}`)", rules.title, number, word)};
      return o_word(fmt::format("o{}", number), word, c, col);
    }
    // WHILE and END are words of three letters or more; a block that opens with a letter and a
    // number (nearly every block) is not read as a keyword.
    if (rules.macro_b && head != '\0' && c.i + 1 < c.text.size() && ncmodel::is_letter(c.text[c.i]) &&
        ncmodel::is_letter(c.text[c.i + 1])) {
      const std::size_t save = c.i;
      const std::string word = c.keyword();
      if (word == "while") return macro_while(c);
      if (word.size() == 3 && word == "end") return macro_end(c);
      c.i = save;
    }
    if ((rules.macro_b || rules.o_words) && head == '#') return macro_assign(c);
    read_words(c);
    execute(words_);
  }

  // The words of a block into words_ (reused: no allocation per block).
  void read_words(Cursor& c) {
    Words& words = words_;
    words.clear();
    for (;;) {
      c.skip();
      if (c.i >= c.text.size() || c.text[c.i] == '\0') return;  // as peek() == '\0': a NUL ends the words
      const std::size_t col = c.column();
      const char ch = c.text[c.i];
      const char upper = static_cast<char>(ch & ~0x20);  // ASCII letters only
      if (upper < 'A' || upper > 'Z') unexpected(col, ch);
      ++c.i;
      // The usual word, a letter and its number (X12.5, G1, Y-3.25): number()'s shortcut, which
      // gives what value() would. Anything else (blanks, #n, [..], a function) through value().
      double v;
      if (!c.plain_number(v)) v = value(c);
      words.add({upper, v, col});
    }
  }
  [[noreturn, gnu::cold]] static void unexpected(std::size_t column, char ch) {
    throw BlockError{column, fmt::format("unexpected `{}`", ch)};
  }

  // ---------------------------------------------------------------- macro B and o-words
  // #<name>: the name between < and >, lower case without blanks (LinuxCNC compares them so).
  std::string named_parameter(Cursor& c) {
    const std::size_t col = c.column();
    if (!rules.o_words) throw BlockError{col, fmt::format("{} has no named parameters", rules.title)};
    const std::size_t close = c.text.find('>', c.i);
    if (close == std::string_view::npos) throw BlockError{col, "a named parameter without its `>`"};
    std::string key;
    for (char ch : c.text.substr(c.i + 1, close - c.i - 1))
      if (ch != ' ' && ch != '\t') key += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (key.empty()) throw BlockError{col, "a named parameter without a name"};
    c.i = close + 1;
    return key;
  }

  void macro_assign(Cursor& c) {
    ++c.i;  // #
    if (c.peek() == '<') {
      const std::string key = named_parameter(c);
      if (c.peek() != '=') throw BlockError{c.column(), "expected `=`"};
      ++c.i;
      const double v = expression(c);
      if (!std::isfinite(v)) throw BlockError{c.column(), "the expression has no finite value"};
      named[key] = v;
      return;
    }
    const std::size_t col = c.column();
    const double n = value(c);
    if (c.peek() != '=') throw BlockError{c.column(), "expected `=`"};
    ++c.i;
    if (n < 1 || n > 99999) throw BlockError{col, fmt::format("#{} cannot be assigned", n)};
    const double v = expression(c);
    if (!std::isfinite(v)) throw BlockError{col, "the expression has no finite value"};
    macro[whole(n, col, "variable number")] = v;
  }

  // WHILE [cond] DOm: the body runs while the condition holds; ENDm goes back to the WHILE.
  void macro_while(Cursor& c) {
    const double condition = value(c);
    if (c.keyword() != "do") throw BlockError{c.column(), "expected DO after WHILE [...]"};
    const std::string key = fmt::format("do{}", whole(c.number(), c.column(), "DO number"));
    if (!repeats.empty() && repeats.back().key == key) repeats.pop_back();  // the loop's own WHILE again
    if (condition != 0) {
      repeats.push_back({key, before, 0});
      return;
    }
    const std::string end = "end" + key.substr(2);
    skip_to([&](std::string_view line) { return opening(line) == end; }, "END" + key.substr(2));
  }

  void macro_end(Cursor& c) {
    const std::string key = fmt::format("do{}", whole(c.number(), c.column(), "DO number"));
    if (repeats.empty() || repeats.back().key != key) throw BlockError{1, fmt::format("END{} without its WHILE", key.substr(2))};
    lines->seek(repeats.back().body);  // the WHILE tests again
  }

  // A block-delete `/` (the block is executed: the switch is off) and the N number a block may open with.
  static void skip_block_number(Cursor& c) {
    char ch = c.peek();
    if (ch == '/') {
      ++c.i;
      ch = c.peek();
    }
    if (ch != 'N' && ch != 'n') return;
    std::size_t end = c.i + 1;
    while (end < c.text.size() && ncmodel::is_digit(c.text[end])) ++end;
    if (end > c.i + 1) c.i = end;  // else not a number: a word of the block
  }

  // How a block opens, lower case, the block number left out: "end1" (END1), "o101 endrepeat"
  // (o101 endrepeat [..]), "" for anything else. What skip_to looks for.
  std::string opening(std::string_view line) {
    Cursor c{line, 0};
    skip_block_number(c);
    const std::string word = c.keyword();
    const std::string digits(c.digits());
    if (word == "end" && !digits.empty()) return word + digits;
    if (word == "o" && !digits.empty()) {
      const std::string what = c.keyword();
      return what.empty() ? "" : "o" + digits + " " + what;
    }
    return "";
  }

  template <class Match>
  void skip_to(Match match, const std::string& what) {
    std::string_view text;
    for (;;) {
      if (!read_line(text)) throw BlockError{1, fmt::format("{} not found", what)};
      bool unclosed = false;
      if (match(strip(text, unclosed, skipped_text_))) return;
    }
  }

  void o_word(const std::string& label, const std::string& word, Cursor& c, std::size_t col) {
    auto line_is = [&](const std::string& want) {
      return [this, key = label + " " + want](std::string_view line) { return opening(line) == key; };
    };
    if (word == "sub") {  // a definition, met in sequence: skipped
      skip_to(line_is("endsub"), label + " endsub");
      return;
    }
    if (word == "endsub" || word == "return") {
      if (calls.empty() || calls.back().o_name != label) throw BlockError{col, fmt::format("{} {} outside its sub", label, word)};
      return return_from_call();
    }
    if (word == "call") {
      index_labels();
      auto it = subs.find(label);
      if (it == subs.end()) {  // LinuxCNC then looks in its subroutine folders: a machine's own routine
        warn_once(label + " call", col,
                  fmt::format("{} call: no {} sub in this file (a routine of the machine's subroutine folders?): "
                              "not run, its motion is not in the model",
                              label, label));
        return;
      }
      // LinuxCNC: the [arguments] become #1, #2, ... of the sub; #1-#30 are its own (docs/iso.md)
      std::vector<double> arguments;
      while (c.peek() == '[') {
        if (arguments.size() == 30) throw BlockError{c.column(), "more than 30 arguments"};
        arguments.push_back(value(c));
      }
      if (c.peek() != '\0') throw BlockError{c.column(), fmt::format("unexpected `{}` after the arguments", c.peek())};
      call(it->second, 1, label, col);
      for (long long n = 1; n <= 30; ++n)
        if (auto v = macro.find(n); v != macro.end()) calls.back().caller_locals.emplace(n, v->second);
      for (long long n = 1; n <= 30; ++n) macro.erase(n);
      for (std::size_t n = 0; n < arguments.size(); ++n) macro[static_cast<long long>(n) + 1] = arguments[n];
      return;
    }
    if (word == "repeat") {
      const double count = c.peek() == '[' ? value(c) : 1;
      if (count >= 1) {
        repeats.push_back({label, lines->mark(), whole(count, col, "repeat count") - 1});
        return;
      }
      skip_to(line_is("endrepeat"), label + " endrepeat");
      return;
    }
    if (word == "endrepeat") {
      if (repeats.empty() || repeats.back().key != label) throw BlockError{col, fmt::format("{} endrepeat without its repeat", label)};
      if (repeats.back().remaining-- > 0) lines->seek(repeats.back().body);
      else repeats.pop_back();
      return;
    }
    throw BlockError{col, fmt::format("`{} {}` is not modelled", label, word)};
  }

  // Runs a body (the line after `at`), `times` times, then comes back after the calling line.
  void call(const ncmodel::LineReader::Mark& at, long long times, const std::string& o_name, std::size_t col) {
    if (calls.size() >= options.max_call_depth)
      throw BlockError{col, fmt::format("subprograms nested deeper than {} (a recursion?)", options.max_call_depth)};
    const ncmodel::LineReader::Mark back = lines->mark();
    lines->seek(at);
    std::string_view header;
    lines->next(header);  // the O / sub line itself
    calls.push_back({lines->mark(), back, times - 1, o_name, {}});
  }

  void return_from_call() {
    Frame& f = calls.back();
    if (f.repeats_left-- > 0) {
      lines->seek(f.body);
      return;
    }
    lines->seek(f.back);
    if (!f.o_name.empty()) {  // the caller's #1-#30 again
      for (long long n = 1; n <= 30; ++n) macro.erase(n);
      macro.insert(f.caller_locals.begin(), f.caller_locals.end());
    }
    calls.pop_back();
  }

  void finish() {
    out.end_program();
    finished = true;
  }

  // ---------------------------------------------------------------- one block of words
  void execute(const Words& w) {
    std::vector<const Word*>& g_codes = g_codes_;
    std::vector<const Word*>& m_codes = m_codes_;
    g_codes.clear();
    m_codes.clear();
    for (const Word& x : w.list) {
      if (x.letter == 'G') g_codes.push_back(&x);
      if (x.letter == 'M') m_codes.push_back(&x);
    }
    if (const Word* f = w.find('F')) feed = f->value * unit();
    if (const Word* t = w.find('T')) selected_tool = static_cast<double>(whole(t->value, t->column, "tool number"));
    bool dwell = false, machine = false, motion_given = false;
    enum class Shift { None, G92, G52, Scale } shift = Shift::None;
    std::optional<int> new_cycle;
    for (const Word* g : g_codes) {
      const long long code = whole(ncmodel::round_half_away(g->value * 10), g->column, "G code");
      switch (code) {
        case 0: case 10: case 20: case 30:
          motion = static_cast<int>(code / 10);
          motion_given = true;
          break;
        case 40: dwell = true; break;
        case 170: plane = geo::Plane::XY; break;
        case 180: plane = geo::Plane::ZX; break;
        case 190: plane = geo::Plane::YZ; break;
        case 200: inch = true; break;
        case 210: inch = false; break;
        case 280: case 300: case 530: machine = true; break;
        case 920: shift = Shift::G92; break;
        case 921: case 922: g92.setZero(); break;  // G92.1 resets the G92 shift, G92.2 suspends it
        case 520: shift = Shift::G52; break;
        case 500: scale.setOnes(); break;        // cancel scaling
        case 510: shift = Shift::Scale; break;
        case 400: out.compensation("COMP_OFF"); break;
        case 410: out.compensation("COMP_LEFT"); break;
        case 420: out.compensation("COMP_RIGHT"); break;
        case 800: motion = 0; cycle_defined = false; break;
        case 900: absolute = true; break;
        case 910: absolute = false; break;
        case 901: absolute_centres = true; break;
        case 911: absolute_centres = false; break;
        case 980: return_to_r = false; break;
        case 990: return_to_r = true; break;
        case 730: case 740: case 760: case 810: case 820: case 830: case 840: case 850: case 860: case 890:
          if (!rules.canned_cycles)
            throw BlockError{g->column, fmt::format("{} has no canned cycles (G{:g})", rules.title, g->value)};
          new_cycle = static_cast<int>(code / 10);
          break;
        case 430: tool_length(w, g->column); break;
        case 490: applied_length = 0; break;
        // modes whose values the program does not give, and path modes: nothing to move
        case 540: case 550: case 560: case 570: case 580: case 590: case 610:
        case 640: case 930: case 940: case 960: case 970: case 150: case 160:
          break;
        case 950:  // feed per revolution: passed on as written, the model has no spindle speed for it
          warn_once("G95", g->column, "G95 (feed per revolution) is not modelled: F is taken as mm/min");
          break;
        default:
          // Its words may not be positions (G10 L2 P1 X..): a block that has any is not guessed at.
          if (w.find('X') || w.find('Y') || w.find('Z'))
            throw BlockError{g->column, fmt::format("G{:g} is not modelled, and its block has axis words", g->value)};
          warn_once(fmt::format("G{}", g->value), g->column, fmt::format("G{:g} is not modelled: ignored", g->value));
      }
    }
    // Tool and spindle (in this order: M6 then M3 in one block loads the tool first)
    for (const Word* m : m_codes) {
      const long long code = whole(m->value, m->column, "M code");
      if (code == 6) {
        if (!rules.tool_change) throw BlockError{m->column, fmt::format("{} has no tool changer (M6: error 20, unsupported command)", rules.title)};
        out.tool_change(selected_tool, std::nullopt);
        load_tool(m->column);
      }
    }
    if (const Word* s = w.find('S')) speed = s->value;
    bool spindle_given = false;
    for (const Word* m : m_codes) {
      const long long code = whole(m->value, m->column, "M code");
      if (code == 3 || code == 4 || code == 5) {
        out.spindle(code, speed);
        spindle_given = true;
      }
    }
    if (w.find('S') && !spindle_given) out.speed(speed);
    if (dwell) {
      double seconds = 0;
      if (const Word* p = w.find('P')) seconds = rules.dwell_p_in_ms ? p->value / 1000 : p->value;
      else if (const Word* x = w.find('X')) seconds = x->value;
      else throw BlockError{1, "G4 needs its time (P or X)"};
      out.dwell(seconds);
    } else if (shift == Shift::G92) {  // the position, as the program will name it from now on
      for (int a = 0; a < 3; ++a)
        if (const Word* x = w.find("XYZ"[a]))
          g92[a] = out.position()[a] - x->value * unit() * scale[a] - g52[a] - (a == 2 ? length_shift() : 0.0);
    } else if (shift == Shift::G52) {  // a local shift of the work frame; G52 X0 Y0 Z0 cancels it
      for (int a = 0; a < 3; ++a)
        if (const Word* x = w.find("XYZ"[a])) g52[a] = x->value * unit();
    } else if (shift == Shift::Scale) {
      if (rules.scaling != Scaling::PerAxis)
        throw BlockError{1, fmt::format("{}'s G51 scaling is not modelled", rules.title)};
      for (int a = 0; a < 3; ++a)  // Mach3: the factors per axis, about the program zero
        if (const Word* x = w.find("XYZ"[a])) {
          if (!(x->value > 0) && !(x->value < 0)) throw BlockError{x->column, "a scale factor of 0"};
          scale[a] = x->value;
        }
    } else if (machine) {
      std::array<std::optional<double>, 3> axes, rotary;
      for (std::size_t a = 0; a < 3; ++a) {
        if (const Word* x = w.find("XYZ"[a])) axes[a] = x->value * unit();
        if (const Word* r = w.find("ABC"[a])) rotary[a] = r->value;  // degrees, not scaled by G20
      }
      out.machine_move(axes, rotary);
    } else if (new_cycle) {
      define_cycle(*new_cycle, w);
    } else {
      // Rotary axes (a 4th axis on Mach3, LinuxCNC): the angle the next move carries.
      bool rotary = false;
      for (int a = 0; a < 3; ++a)
        if (const Word* r = w.find("ABC"[a])) {
          const double now = out.rotary(a).value_or(0.0);
          out.set_rotary(a, absolute ? r->value : now + r->value);
          rotary = true;
        }
      const bool axes = rotary || w.find('X') || w.find('Y') || w.find('Z');
      if (motion >= 73 && cycle_defined && (w.find('X') || w.find('Y'))) {
        position_hole(w);
      } else if (axes || (motion_given && (w.find('I') || w.find('J') || w.find('K') || w.find('R')))) {
        move(w);
      }
    }
    flow(w, m_codes);
  }

  // G43 [H<n>]: the length of tool n (H0: none; no H: the tool in the spindle, as LinuxCNC takes
  // it) applies from this block on.
  void tool_length(const Words& w, std::size_t column) {
    if (!options.tools) return;
    const Word* h = w.find('H');
    if (!h && !spindle_tool) throw BlockError{column, "G43 without H before any M6: which tool's length applies?"};
    const std::int64_t number = h ? whole(h->value, h->column, "H number") : *spindle_tool;
    applied_length = number == 0 ? 0.0 : table_length(number, h ? h->column : column, 'H');
  }

  // M6: the selected tool is in the spindle; its length decides where its tip is.
  void load_tool(std::size_t column) {
    if (!options.tools || !selected_tool) return;
    const auto tool = static_cast<std::int64_t>(*selected_tool);
    spindle_length = tool == 0 ? 0.0 : table_length(tool, column, 'T');
    spindle_tool = tool;
  }

  double table_length(std::int64_t number, std::size_t column, char word) const {
    const ncmodel::ToolOffsets* t = options.tools->find(number);
    if (!t) throw BlockError{column, fmt::format("{}{}: tool {} is not in the tool table {}", word, number, number,
                                                 options.tools->file)};
    return t->length * unit();
  }

  Eigen::Vector3d target(const Words& w) const {
    Eigen::Vector3d to = out.position();
    for (int a = 0; a < 3; ++a)
      if (const Word* x = w.find("XYZ"[a])) to[a] = absolute ? to_work(a, x->value) : to[a] + step(a, x->value);
    return to;
  }

  void move(const Words& w) {
    if (motion >= 73) motion = 1;  // not reached: a cycle's blocks are holes
    const Eigen::Vector3d to = target(w);
    if (motion == 0) return out.rapid(to);
    if (feed <= 0) diagnose(false, 1, "a feed move before any feed (F) was given");
    if (motion == 1) return out.line(to, feed);
    const bool ccw = motion == 3;
    if (!uniform_in(plane)) throw BlockError{1, "an arc under a scale that differs in its plane is an ellipse: not modelled"};
    Eigen::Vector3d centre = out.position();
    if (const Word* r = w.find('R')) {
      const Eigen::Vector3d& from = out.position();
      if ((geo::in_plane(from, plane) - geo::in_plane(to, plane)).norm() < 1e-9)
        throw BlockError{r->column, "an R arc cannot be a full circle: give I J K"};
      const auto c = geo::centre_from_radius(from, to, step(geo::axes(plane).first, r->value), plane,
                                             ccw ? geo::Direction::CCW : geo::Direction::CW, options.arc_tolerance);
      if (!c) throw BlockError{r->column, fmt::format("R{:g} cannot join the start and the end point", r->value)};
      centre = *c;
    } else {
      bool any = false;
      for (int a = 0; a < 3; ++a)
        if (const Word* k = w.find("IJK"[a])) {
          any = true;
          centre[a] = absolute_centres ? to_work(static_cast<int>(a), k->value) : centre[a] + step(static_cast<int>(a), k->value);
        }
      if (!any) throw BlockError{1, fmt::format("G{} needs its centre (I J K) or R", ccw ? 3 : 2)};
      // The control's alarm when the end is not on the circle (LinuxCNC: "radius to end of arc
      // differs from radius to start"): beyond the tolerance and 0.1 % of the radius.
      const double r0 = (geo::in_plane(out.position(), plane) - geo::in_plane(centre, plane)).norm();
      const double r1 = (geo::in_plane(to, plane) - geo::in_plane(centre, plane)).norm();
      if (std::abs(r1 - r0) > std::max(options.arc_tolerance, 0.001 * r0))
        throw BlockError{1, fmt::format("the end point is {:.4f} mm from the centre, the start {:.4f} mm: not one circle",
                                        r1, r0)};
    }
    out.arc(to, centre, plane, ccw, feed);
  }

  // A cycle block: its words, then the first hole where the tool is (or at the block's X Y).
  void define_cycle(int code, const Words& w) {
    if (!absolute) throw BlockError{1, "canned cycles in G91 are not modelled"};
    if (motion < 73 || !cycle_defined) cycle.initial = out.position().z();
    motion = code;
    cycle_defined = true;
    if (const Word* z = w.find('Z')) cycle.z = to_work(2, z->value);
    if (const Word* r = w.find('R')) cycle.r = to_work(2, r->value);
    if (const Word* q = w.find('Q')) cycle.q = std::abs(step(2, q->value));
    if (const Word* p = w.find('P')) cycle.p = rules.dwell_p_in_ms ? p->value / 1000 : p->value;
    position_hole(w);
  }

  void position_hole(const Words& w) {
    Eigen::Vector3d at = out.position();
    for (int a = 0; a < 2; ++a)
      if (const Word* x = w.find("XY"[a])) at[a] = absolute ? to_work(a, x->value) : at[a] + step(a, x->value);
    if ((at - out.position()).norm() > 1e-12) out.rapid(at);
    using Kind = ncmodel::MotionOut::Hole::Kind;
    ncmodel::MotionOut::Hole h;
    h.approach = cycle.r;
    h.depth = cycle.z;
    h.retract = return_to_r ? cycle.r : cycle.initial;
    h.feed = feed;
    switch (motion) {
      case 81: h.kind = Kind::Drill; break;
      case 82: h.kind = Kind::Drill; h.dwell = cycle.p; break;
      case 83:
      case 73:
        h.kind = motion == 83 ? Kind::Peck : Kind::ChipBreak;
        h.first_step = cycle.q > 0 ? cycle.q : h.approach - h.depth;
        h.chip_lift = rules.chip_break_lift;
        break;
      case 84: case 74: h.kind = Kind::Tap; break;  // G74: left-handed (the reversal is the control's)
      case 76: h.kind = Kind::BoreSpindleStop; break;  // fine boring: the shift off the wall is not modelled
      case 85: h.kind = Kind::Bore; break;
      case 86: h.kind = Kind::BoreSpindleStop; break;
      case 89: h.kind = Kind::Bore; h.dwell = cycle.p; break;
      default: throw BlockError{1, fmt::format("G{} is not modelled", motion)};
    }
    try {
      out.hole(h);
    } catch (const std::runtime_error& e) {
      throw BlockError{1, e.what()};
    }
  }

  // M98, M99, M2, M30.
  void flow(const Words& w, const std::vector<const Word*>& m_codes) {
    for (const Word* m : m_codes) {
      const long long code = whole(m->value, m->column, "M code");
      if (code == 98) {
        if (!rules.subprograms) throw BlockError{m->column, fmt::format("{} has no subprograms (M98)", rules.title)};
        const Word* p = w.find('P');
        if (!p) throw BlockError{m->column, "M98 needs P, the program number"};
        long long program = whole(p->value, p->column, "program number"), times = 1;
        if (const Word* l = w.find('L')) times = whole(l->value, l->column, "repeat count");
        else if (program > 9999) {  // P<times><4-digit program>
          times = program / 10000;
          program %= 10000;
        }
        index_labels();
        auto it = programs.find(program);
        if (it == programs.end()) throw BlockError{p->column, fmt::format("no O{} in the program", program)};
        if (times < 1) return;  // L0: not run
        call(it->second, times, {}, m->column);
        return;
      }
      if (code == 99) {
        if (calls.empty() || !calls.back().o_name.empty()) {
          warn_once("M99", m->column, "M99 in the main program restarts it on the control: the model stops here");
          finish();
          return;
        }
        return_from_call();
        return;
      }
      if (code == 2 || code == 30) {
        finish();
        return;
      }
    }
  }
};

IsoReader::IsoReader(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
IsoReader::~IsoReader() = default;

std::unique_ptr<IsoReader> IsoReader::open(const std::string& path, const Rules& rules, Options options) {
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file) throw toolpath::InputError({path, 0, 0}, "cannot open the program");
  return std::unique_ptr<IsoReader>(new IsoReader(std::make_unique<Impl>(std::move(file), path, rules, options)));
}

std::unique_ptr<IsoReader> IsoReader::from_string(std::string text, std::string name, const Rules& rules,
                                                  Options options) {
  return std::unique_ptr<IsoReader>(new IsoReader(
      std::make_unique<Impl>(std::make_unique<std::istringstream>(std::move(text)), std::move(name), rules, options)));
}

bool IsoReader::next(toolpath::Command& out) {
  if (impl_->out.empty()) impl_->run();
  return impl_->out.take(out);
}

std::size_t IsoReader::line() const { return impl_->command_line; }
const std::string& IsoReader::file_name() const { return impl_->name; }
const toolpath::Diagnostics& IsoReader::diagnostics() const { return impl_->diagnostics; }

}  // namespace iso
