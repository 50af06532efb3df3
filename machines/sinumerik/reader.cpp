#include "machines/sinumerik/reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include <Eigen/Core>

#include "machines/ncmodel/block_text.hpp"
#include "machines/ncmodel/line_reader.hpp"
#include "machines/ncmodel/motion_out.hpp"
#include "toolpath/error.hpp"
#include "toolpath/geometry.hpp"
#include "toolpath/value.hpp"

namespace sinumerik {
namespace {

namespace fs = std::filesystem;
namespace geo = toolpath::geometry;
using toolpath::Command;
using toolpath::Value;

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

using ncmodel::ident_char;
using ncmodel::ident_start;

// A block that cannot be executed: the message names what and where (1-based column).
using ncmodel::BlockError;
using ncmodel::Cursor;
using ncmodel::whole;

// Words that change nothing the motion shows (smoothing, look-ahead, work offsets whose values the
// program does not give): accepted without a word.
const std::set<std::string, std::less<>>& quiet_words() {
  static const std::set<std::string, std::less<>> words = {
      "SOFT", "BRISK", "DRIVE", "FFWON", "FFWOF", "CFC", "CFTCP", "CFIN", "COMPOF", "COMPON", "COMPCURV",
      "COMPCAD", "TRAFOOF", "SPATH", "UPATH", "DIAMOF", "DIAMON", "WALIMON", "WALIMOF", "STOPRE", "ORIWKS",
      "ORIMKS", "G60", "G64", "G641", "G642", "G643", "G644", "G645", "G9", "G601", "G602", "G603"};
  return words;
}

// The position of one program in its call chain.
struct Source {
  fs::path path;
  std::string name;  // as messages show it
  std::unique_ptr<std::istream> stream;
  std::unique_ptr<ncmodel::LineReader> lines;
  std::map<std::string, ncmodel::LineReader::Mark, std::less<>> labels;  // upper case, seen so far
  std::size_t repeats_left = 0;  // further passes of a call with P
  ncmodel::LineReader::Mark start;
  ncmodel::LineReader::Mark before;  // where the line read last starts (a label's block)
};

// The values of `X=AC(3)`, `I=IC(-1)`, `X12.5`: absolute (AC), incremental (IC) or as the mode says.
enum class Dim : unsigned char { Modal, Absolute, Incremental };
struct Coordinate {
  double value = 0;
  Dim dim = Dim::Modal;
};

struct Block {
  std::array<std::optional<Coordinate>, 3> axes;    // X Y Z
  std::array<std::optional<Coordinate>, 3> centre;  // I J K
  std::optional<double> cr, f, s, d;
  std::optional<std::string> tool_name;
  std::optional<double> tool_number;
  std::vector<double> g, m;
  bool supa = false;
  std::optional<std::string> msg;
  struct Call {
    std::string program;
    std::size_t repeats = 1;
    std::size_t column = 1;
  };
  std::optional<Call> call;
  struct Cycle {
    std::string name;
    std::vector<std::optional<double>> args;
    std::size_t column = 1;
  };
  std::optional<Cycle> cycle;
  bool mcall = false;  // MCALL: `cycle` becomes modal (or, without one, the modal call ends)
  bool ret = false;
  struct Jump {
    bool back = true;
    std::string label;
    std::size_t column = 1;
  };
  std::optional<Jump> jump;
  std::optional<std::size_t> p_column;  // a P word (repeats of the call)
  std::optional<double> p;

  // Empties the block for the next line, as Block{} (every member above), member by member: the
  // code lists keep their buffers (no allocation a line), and the texts are only tested (most
  // blocks have none), not moved over.
  void clear() {
    axes = {};
    centre = {};
    cr = f = s = d = tool_number = p = std::nullopt;
    p_column.reset();
    tool_name.reset();
    msg.reset();
    call.reset();
    cycle.reset();
    jump.reset();
    g.clear();
    m.clear();
    supa = mcall = ret = false;
  }
};

}  // namespace

struct SinumerikReader::Impl {
  Options options;
  fs::path folder;
  std::string main_name;
  std::vector<Source> stack;
  std::map<std::string, fs::path, std::less<>> folder_files;  // upper-case name -> file
  bool folder_listed = false;
  std::map<std::string, double, std::less<>> vars;  // upper-case name
  ncmodel::MotionOut out;
  toolpath::Diagnostics diagnostics{options.max_diagnostics};
  std::set<std::string, std::less<>> warned_words;
  std::size_t executed = 0;
  std::size_t current_line = 0, main_line = 0;
  bool finished = false;

  // Modal state (the tool position is out.position(), in work coordinates, mm)
  Eigen::Vector3d trans = Eigen::Vector3d::Zero();  // TRANS/ATRANS
  int motion = 0;  // 0..3
  geo::Plane plane = geo::Plane::XY;
  bool absolute = true, inch_geometry = false, inch_feed = false, per_rev = false;
  double feed = 0, speed = 0;
  std::optional<std::string> selected_name;
  std::optional<double> selected_number;
  std::optional<Block::Cycle> modal_cycle;
  bool warned_per_rev = false;

  bool in_memory = false;  // no folder: subprograms cannot be found
  Block block_;            // the block being executed, reused line after line

  Impl(const std::string& path, Options o) : options(o) {
    fs::path p(path);
    folder = p.parent_path();
    main_name = path;
    push(p, path, 1);
  }

  Impl(std::string text, std::string name, Options o) : options(o), main_name(name), in_memory(true) {
    push_stream(std::make_unique<std::istringstream>(std::move(text)), fs::path(name), name, 1);
  }

  void push(const fs::path& p, const std::string& name, std::size_t repeats) {
    auto file = std::make_unique<std::ifstream>(p, std::ios::binary);
    if (!*file) throw toolpath::InputError({name, 0, 0}, "cannot open the program");
    push_stream(std::move(file), p, name, repeats);
  }

  void push_stream(std::unique_ptr<std::istream> in, const fs::path& p, const std::string& name, std::size_t repeats) {
    Source s;
    s.path = p;
    s.name = name;
    s.stream = std::move(in);
    s.lines = std::make_unique<ncmodel::LineReader>(*s.stream, name);
    s.start = s.lines->mark();
    s.repeats_left = repeats - 1;
    stack.push_back(std::move(s));
  }

  void diagnose(bool error, std::size_t column, std::string message) {
    diagnostics.add({{stack.back().name, current_line, column},
                     error ? toolpath::Severity::Error : toolpath::Severity::Warning,
                     std::move(message)});
  }

  void warn_once(const std::string& key, std::size_t column, std::string message) {
    if (warned_words.insert(key).second) diagnose(false, column, std::move(message));
  }

  // ---------------------------------------------------------------- reading
  bool read_line(std::string_view& text) {
    while (!stack.empty()) {
      Source& s = stack.back();
      s.before = s.lines->mark();
      if (s.lines->next(text)) {
        current_line = s.lines->line_number();
        return true;
      }
      end_of_source(false);
    }
    return false;
  }

  // A program ends (its last line, M17/RET, or M2/M30 in a subprogram): the next pass of a call with
  // P, or back to the caller.
  void end_of_source(bool returned) {
    Source& s = stack.back();
    if (s.repeats_left > 0) {
      --s.repeats_left;
      s.lines->seek(s.start);
      return;
    }
    if (!returned && stack.size() > 1) diagnose(false, 1, "the subprogram ends without M17 or RET");
    stack.pop_back();
    if (stack.empty()) finished = true;
  }

  std::optional<fs::path> find_program(std::string_view name) {
    if (in_memory) return std::nullopt;
    if (!folder_listed) {
      folder_listed = true;
      std::error_code ec;
      for (const auto& e : fs::directory_iterator(folder.empty() ? fs::path(".") : folder, ec))
        if (e.is_regular_file(ec)) folder_files.emplace(upper(e.path().filename().string()), e.path());
    }
    std::string file = upper(fs::path(std::string(name)).filename().string());  // a Windows path keeps its name
    for (std::string candidate : {file, file + ".SPF", file + ".MPF"}) {
      auto it = folder_files.find(candidate);
      if (it != folder_files.end()) return it->second;
    }
    return std::nullopt;
  }

  // ---------------------------------------------------------------- lexing and expressions




  double primary(Cursor& c) {
    const char ch = c.peek();
    if (ch == '(') {
      ++c.i;
      const double v = expression(c);
      if (!c.eat(')')) throw BlockError{c.column(), "expected `)`"};
      return v;
    }
    if (ch == '-' || ch == '+') {
      ++c.i;
      const double v = primary(c);
      return ch == '-' ? -v : v;
    }
    if (std::isdigit(static_cast<unsigned char>(ch)) || ch == '.') return c.number();
    if (ident_start(ch)) {
      const std::size_t col = c.column();
      const std::string name = upper(c.ident());
      if (name == "TRUE") return 1;
      if (name == "FALSE") return 0;
      if (name == "NOT") return primary(c) == 0 ? 1 : 0;
      if (c.peek() == '(') {  // a function of one argument
        ++c.i;
        const double v = expression(c);
        if (!c.eat(')')) throw BlockError{c.column(), "expected `)`"};
        if (name == "ABS") return std::abs(v);
        if (name == "SQRT") return std::sqrt(v);
        if (name == "SIN") return std::sin(v * std::numbers::pi / 180);
        if (name == "COS") return std::cos(v * std::numbers::pi / 180);
        if (name == "TRUNC") return std::trunc(v);
        if (name == "ROUND") return std::round(v);
        throw BlockError{col, fmt::format("the function {} is not modelled", name)};
      }
      auto it = vars.find(name);
      if (it == vars.end()) {
        if (name.size() > 1 && name[0] == 'R' && std::all_of(name.begin() + 1, name.end(), ::isdigit)) return 0;  // R params start at 0
        throw BlockError{col, fmt::format("`{}` is no variable of the program (DEF it first)", name)};
      }
      return it->second;
    }
    throw BlockError{c.column(), "expected a value"};
  }

  double product(Cursor& c) {
    double v = primary(c);
    for (;;) {
      if (c.eat('*')) v *= primary(c);
      else if (c.peek() == '/') {
        ++c.i;
        const std::size_t col = c.column();
        const double d = primary(c);
        if (d == 0) throw BlockError{col, "division by zero"};
        v /= d;
      } else return v;
    }
  }

  double sum(Cursor& c) {
    double v = product(c);
    for (;;) {
      if (c.eat('+')) v += product(c);
      else if (c.eat('-')) v -= product(c);
      else return v;
    }
  }

  double comparison(Cursor& c) {
    const double a = sum(c);
    if (c.eat("==")) return a == sum(c);
    if (c.eat("<>")) return a != sum(c);
    if (c.eat("<=")) return a <= sum(c);
    if (c.eat(">=")) return a >= sum(c);
    if (c.eat('<')) return a < sum(c);
    if (c.eat('>')) return a > sum(c);
    return a;
  }

  // Comparisons joined by AND / OR (AND first).
  double expression(Cursor& c) {
    double v = comparison(c);
    for (;;) {
      const std::size_t save = c.i;
      const std::string word = upper(c.ident());
      if (word == "AND") v = (v != 0 && comparison(c) != 0) ? 1 : 0;
      else if (word == "OR") v = (v != 0 || comparison(c) != 0) ? 1 : 0;
      else {
        c.i = save;
        return v;
      }
    }
  }

  // The value after `X=`: AC(...), IC(...) or an expression.
  Coordinate coordinate_value(Cursor& c) {
    const std::size_t save = c.i;
    const std::string f = upper(c.ident());
    if ((f == "AC" || f == "IC") && c.peek() == '(') {
      ++c.i;
      Coordinate k{expression(c), f == "AC" ? Dim::Absolute : Dim::Incremental};
      if (!c.eat(')')) throw BlockError{c.column(), "expected `)`"};
      return k;
    }
    c.i = save;
    return {expression(c), Dim::Modal};
  }

  std::string string_literal(Cursor& c) {
    if (!c.eat('"')) throw BlockError{c.column(), "expected a \"text\""};
    const std::size_t b = c.i;
    while (c.i < c.text.size() && c.text[c.i] != '"') ++c.i;
    if (c.i >= c.text.size()) throw BlockError{b, "the text has no closing \""};
    return std::string(c.text.substr(b, c.i++ - b));
  }

  // ---------------------------------------------------------------- one block
  static std::string_view strip_comment(std::string_view line) {
    // A `;` before any `"` starts the comment; without either the line is all block. One scan, not a
    // loop over every byte.
    const std::size_t first = ncmodel::find_either(line.data(), line.size(), '"', ';');
    if (first == line.size()) return line;
    if (line[first] == ';') return line.substr(0, first);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '"') quoted = !quoted;
      else if (line[i] == ';' && !quoted) return line.substr(0, i);
    }
    return line;
  }

  // Parses `text` (comment stripped) into `b`; labels are registered by the caller.
  void parse(Cursor& c, Block& b) {
    for (;;) {
      c.skip();  // at_end() and peek() in one
      if (c.i >= c.text.size()) return;
      const char ch = c.text[c.i];
      const std::size_t col = c.column();
      if (ch == '/' && c.i == 0) {  // block skip: executed (the control's skip switch is off)
        ++c.i;
        continue;
      }
      if (!ident_start(ch)) throw BlockError{col, fmt::format("unexpected `{}`", ch)};
      // An address letter directly followed by its number: X12.5, G04, M3, N10 (not R11=..., an
      // assignment to the arithmetic parameter R11).
      // ASCII tests inline, as std::isalpha and std::toupper in the "C" locale (not a call each).
      // The usual number first: number()'s shortcut, which gives what number() would below.
      if (ncmodel::is_letter(ch)) {
        Cursor number{c.text, c.i + 1};
        double v;
        if (number.plain_number(v) && !assigns(c)) {
          c.i = number.i;
          address(b, static_cast<char>(ch & ~0x20), {v, Dim::Modal}, col);
          continue;
        }
      }
      if (ncmodel::is_letter(ch) && c.i + 1 < c.text.size() && !assigns(c) &&
          ((c.text[c.i + 1] >= '0' && c.text[c.i + 1] <= '9') || c.text[c.i + 1] == '-' ||
           c.text[c.i + 1] == '.' || c.text[c.i + 1] == '+')) {
        const char letter = static_cast<char>(ch & ~0x20);
        ++c.i;
        const double v = c.number();
        address(b, letter, {v, Dim::Modal}, col);
        continue;
      }
      const std::string name = upper(c.ident());
      if (c.peek() == '=' && !(c.i + 1 < c.text.size() && c.text[c.i + 1] == '=')) {
        ++c.i;
        assignment(c, b, name, col);
        continue;
      }
      if (name.rfind("CYCLE", 0) == 0 && c.peek() == '(') {
        b.cycle = Block::Cycle{name, cycle_args(c, name), col};
        continue;
      }
      keyword(c, b, name, col);
    }
  }

  // The identifier at the cursor is followed by `=` (not `==`): an assignment.
  static bool assigns(const Cursor& c) {
    std::size_t i = c.i;
    while (i < c.text.size() && ident_char(c.text[i])) ++i;
    while (i < c.text.size() && (c.text[i] == ' ' || c.text[i] == '\t')) ++i;
    return i < c.text.size() && c.text[i] == '=' && !(i + 1 < c.text.size() && c.text[i + 1] == '=');
  }

  std::vector<std::optional<double>> cycle_args(Cursor& c, const std::string& name) {
    ++c.i;  // (
    std::vector<std::optional<double>> args;
    const bool evaluate = name != "CYCLE832" && name != "CYCLE800";  // their arguments are words
    for (;;) {
      c.skip();
      if (c.peek() == ',' || c.peek() == ')') {
        args.push_back(std::nullopt);
      } else if (evaluate) {
        args.push_back(expression(c));
      } else {
        int depth = 0;
        while (c.i < c.text.size() && (depth > 0 || (c.text[c.i] != ',' && c.text[c.i] != ')'))) {
          depth += c.text[c.i] == '(' ? 1 : c.text[c.i] == ')' ? -1 : 0;
          ++c.i;
        }
        args.push_back(std::nullopt);
      }
      if (c.eat(')')) return args;
      if (!c.eat(',')) throw BlockError{c.column(), fmt::format("expected `,` or `)` in {}", name)};
    }
  }

  void address(Block& b, char letter, Coordinate k, std::size_t col) {
    switch (letter) {
      case 'X': b.axes[0] = k; return;
      case 'Y': b.axes[1] = k; return;
      case 'Z': b.axes[2] = k; return;
      case 'I': b.centre[0] = k; return;
      case 'J': b.centre[1] = k; return;
      case 'K': b.centre[2] = k; return;
      case 'F': b.f = k.value; return;
      case 'S': b.s = k.value; return;
      case 'D': b.d = k.value; return;
      case 'T': b.tool_number = static_cast<double>(whole(k.value, col, "tool number")); return;
      case 'G': b.g.push_back(static_cast<double>(whole(ncmodel::round_half_away(k.value * 10), col, "G code")) / 10); return;
      case 'M': b.m.push_back(static_cast<double>(whole(k.value, col, "M code"))); return;
      case 'H': return;  // auxiliary functions: not motion
      case 'N': return;  // a block number after the first word
      case 'P': b.p = k.value; b.p_column = col; return;
      case 'L': b.call = Block::Call{fmt::format("L{}", whole(k.value, col, "program number")), 1, col}; return;
      default:
        warn_once(fmt::format("addr {}", letter), col, fmt::format("the address {} is not modelled: ignored", letter));
    }
  }

  void assignment(Cursor& c, Block& b, const std::string& name, std::size_t col) {
    if (name == "T") {  // T="NAME"
      c.skip();
      if (c.peek() == '"') b.tool_name = string_literal(c);
      else {
        const std::size_t at = c.column();
        b.tool_number = static_cast<double>(whole(expression(c), at, "tool number"));
      }
      return;
    }
    if (name == "CR") {
      b.cr = expression(c);
      return;
    }
    if (name.size() == 1 && std::string_view("XYZIJKFSD").find(name[0]) != std::string_view::npos) {
      address(b, name[0], coordinate_value(c), col);
      return;
    }
    const double v = expression(c);
    if (vars.count(name) || (name.size() > 1 && name[0] == 'R' && std::all_of(name.begin() + 1, name.end(), ::isdigit)))
      vars[name] = v;
    else throw BlockError{col, fmt::format("`{}` is no variable of the program (DEF it first)", name)};
  }

  void keyword(Cursor& c, Block& b, const std::string& name, std::size_t col) {
    if (name == "SUPA" || name == "G53") {
      b.supa = true;
      return;
    }
    if (name == "MSG") {
      if (!c.eat('(')) throw BlockError{c.column(), "expected MSG(\"text\")"};
      c.skip();
      b.msg = c.peek() == '"' ? string_literal(c) : std::string();
      if (!c.eat(')')) throw BlockError{c.column(), "expected `)`"};
      return;
    }
    if (name == "DEF") {
      const std::string type = upper(c.ident());
      if (type != "REAL" && type != "INT" && type != "BOOL" && type != "CHAR" && type != "STRING" && type != "AXIS" &&
          type != "FRAME")
        throw BlockError{col, fmt::format("DEF of the type `{}` is not modelled", type)};
      do {
        const std::string var = upper(c.ident());
        if (var.empty()) throw BlockError{c.column(), "expected a variable name"};
        if (c.eat('[')) {
          while (c.i < c.text.size() && c.text[c.i] != ']') ++c.i;
          c.eat(']');
        }
        double v = 0;
        if (c.eat('=')) v = (type == "STRING" || type == "CHAR") ? (string_literal(c), 0.0) : expression(c);
        vars[var] = v;
      } while (c.eat(','));
      return;
    }
    if (name == "EXTCALL") {
      c.skip();
      b.call = Block::Call{c.peek() == '"' ? string_literal(c) : c.ident(), 1, col};
      return;
    }
    if (name == "MCALL") {
      b.mcall = true;
      return;
    }
    if (name == "RET" || name == "M17") {
      b.ret = true;
      return;
    }
    if (name == "IF") {
      const double condition = expression(c);
      const std::string go = upper(c.ident());
      if (go != "GOTOB" && go != "GOTOF" && go != "GOTO") throw BlockError{c.column(), "expected GOTOB or GOTOF after IF"};
      const std::size_t lc = c.column();
      const std::string label = upper(c.ident());
      if (condition != 0) b.jump = Block::Jump{go == "GOTOB", label, lc};
      return;
    }
    if (name == "GOTOB" || name == "GOTOF" || name == "GOTO") {
      const std::size_t lc = c.column();
      b.jump = Block::Jump{name == "GOTOB", upper(c.ident()), lc};
      return;
    }
    if (name == "PROC") {  // a subprogram's header: its name and parameters
      c.i = c.text.size();
      return;
    }
    if (name == "TRANS" || name == "ATRANS") {
      if (name == "TRANS") trans = Eigen::Vector3d::Zero();
      Block shift;
      parse(c, shift);
      for (int a = 0; a < 3; ++a)
        if (shift.axes[static_cast<std::size_t>(a)]) trans[a] += shift.axes[static_cast<std::size_t>(a)]->value * length_unit();
      return;
    }
    if (name == "ROT" || name == "AROT" || name == "SCALE" || name == "ASCALE" || name == "MIRROR" || name == "AMIRROR") {
      c.i = c.text.size();
      throw BlockError{col, fmt::format("the frame {} is not modelled: the motion after it would not be the program's",
                                        name)};
    }
    if (quiet_words().count(name)) return;
    if (auto file = find_program(name)) {  // a subprogram called by its name
      b.call = Block::Call{name, 1, col};
      return;
    }
    warn_once(name, col, fmt::format("`{}` is not modelled: ignored", name));
  }

  double length_unit() const { return inch_geometry ? 25.4 : 1.0; }

  // ---------------------------------------------------------------- execution
  void execute(Block& b) {
    // P: the repeats of the block's call (a P without a call is an error).
    if (b.p) {
      if (!b.call) throw BlockError{*b.p_column, "P without a subprogram call"};
      if (*b.p < 1 || *b.p > 1e6) throw BlockError{*b.p_column, fmt::format("P{} is no number of passes", *b.p)};
      b.call->repeats = static_cast<std::size_t>(*b.p);
    }
    if (b.msg && !b.msg->empty()) out.message(*b.msg);
    bool dwell_block = false;
    for (double g : b.g) {
      const int code = static_cast<int>(ncmodel::round_half_away(g * 10));  // |g| <= 1e8 (address())
      switch (code) {
        case 0: motion = 0; break;
        case 10: motion = 1; break;
        case 20: motion = 2; break;
        case 30: motion = 3; break;
        case 40: dwell_block = true; break;
        case 170: plane = geo::Plane::XY; break;
        case 180: plane = geo::Plane::ZX; break;
        case 190: plane = geo::Plane::YZ; break;
        case 400: out.compensation("COMP_OFF"); break;
        case 410: out.compensation("COMP_LEFT"); break;
        case 420: out.compensation("COMP_RIGHT"); break;
        case 700: inch_geometry = true; inch_feed = false; break;
        case 710: inch_geometry = false; inch_feed = false; break;
        case 7000: inch_geometry = true; inch_feed = true; break;
        case 7100: inch_geometry = false; inch_feed = false; break;
        case 900: absolute = true; break;
        case 910: absolute = false; break;
        case 940: per_rev = false; break;
        case 950: per_rev = true; break;
        case 530: b.supa = true; break;
        default:
          if ((code >= 5000 && code <= 5990 && code % 10 == 0) || (code >= 540 && code <= 570 && code % 10 == 0)) break;
          if (quiet_words().count(fmt::format("G{}", code / 10))) break;
          warn_once(fmt::format("G{}", g), 1, fmt::format("G{} is not modelled: ignored", g));
      }
    }
    if (dwell_block) {
      if (b.f) out.dwell(*b.f);
      else if (b.s && speed > 0) out.dwell(*b.s * 60.0 / speed);
      else throw BlockError{1, "G4 needs F (seconds) or S (revolutions of a running spindle)"};
      b.f.reset();
      b.s.reset();
    }
    if (b.f) {
      feed = *b.f * (inch_feed ? 25.4 : 1.0);
      if (per_rev && !warned_per_rev) {
        warned_per_rev = true;
        diagnose(false, 1, "G95: feeds are per revolution; they are passed on as written");
      }
    }
    tool(b);
    spindle_words(b);
    if (b.axes[0] || b.axes[1] || b.axes[2] || b.centre[0] || b.centre[1] || b.centre[2] || b.cr) move(b);
    if (b.cycle && (b.cycle->name == "CYCLE832" || b.cycle->name == "CYCLE800")) {
      if (b.cycle->name == "CYCLE800")
        warn_once("CYCLE800", b.cycle->column, "CYCLE800 (swivelling) is not modelled: the frame after it is the program's");
      b.cycle.reset();
    }
    if (b.mcall) modal_cycle = b.cycle;  // MCALL CYCLE8x(...) on, MCALL alone off
    else if (b.cycle) drill_cycle(*b.cycle);
    else if (modal_cycle && (b.axes[0] || b.axes[1] || b.axes[2])) drill_cycle(*modal_cycle);
    for (double m : b.m) {
      const int code = static_cast<int>(m);
      if (code == 2 || code == 30) {
        if (stack.size() > 1) b.ret = true;
        else {
          end_program();
          return;
        }
      }
      if (code == 17) b.ret = true;
    }
    if (b.call) call(*b.call);
    else if (b.jump) jump(*b.jump);
    if (b.ret) {
      if (stack.size() == 1) end_program();
      else end_of_source(true);
    }
  }

  void end_program() {
    out.end_program();
    finished = true;
    stack.clear();
  }

  void tool(const Block& b) {
    if (b.tool_name) {
      selected_name = b.tool_name;
      selected_number.reset();
    }
    if (b.tool_number) {
      selected_number = b.tool_number;
      selected_name.reset();
    }
    for (double m : b.m)
      if (static_cast<int>(m) == 6) out.tool_change(selected_number, selected_name);
  }

  void spindle_words(const Block& b) {
    std::optional<int> m_code;
    for (double m : b.m) {
      const int code = static_cast<int>(m);
      if (code == 3 || code == 4 || code == 5) m_code = code;
    }
    if (b.s) speed = *b.s;
    if (m_code) out.spindle(*m_code, speed);
    else if (b.s) out.speed(speed);
  }

  void move(const Block& b) {
    const Eigen::Vector3d& pos = out.position();
    Eigen::Vector3d to = pos;
    for (int a = 0; a < 3; ++a) {
      const auto& k = b.axes[static_cast<std::size_t>(a)];
      if (!k) continue;
      const double v = k->value * length_unit();
      const bool abs = k->dim == Dim::Absolute || (k->dim == Dim::Modal && absolute);
      to[a] = abs ? v + (b.supa ? 0.0 : trans[a]) : pos[a] + v;
    }
    if (b.supa) {  // machine coordinates: the model does not know where they are in the work frame
      std::array<std::optional<double>, 3> axes;
      for (std::size_t a = 0; a < 3; ++a)
        if (b.axes[a]) axes[a] = to[static_cast<int>(a)];
      return out.machine_move(axes);
    }
    if (motion == 0) return out.rapid(to);
    if (feed <= 0) diagnose(false, 1, "a feed move before any feed (F) was given");
    if (motion == 1) return out.line(to, feed);
    arc(b, to);
  }

  void arc(const Block& b, const Eigen::Vector3d& to) {
    const Eigen::Vector3d& pos = out.position();
    const bool ccw = motion == 3;
    const geo::PlaneAxes ax = geo::axes(plane);
    Eigen::Vector3d centre = pos;
    if (b.cr) {
      const auto c = geo::centre_from_radius(pos, to, *b.cr * length_unit(), plane,
                                             ccw ? geo::Direction::CCW : geo::Direction::CW, options.arc_tolerance);
      if (!c) throw BlockError{1, fmt::format("CR={} cannot join the start and the end point", *b.cr)};
      centre = *c;
    } else {
      bool any = false;
      for (int a : {ax.first, ax.second}) {
        const auto& k = b.centre[static_cast<std::size_t>(a)];
        if (!k) continue;
        any = true;
        const double v = k->value * length_unit();
        centre[a] = k->dim == Dim::Absolute ? v + trans[a] : pos[a] + v;  // I J K are incremental unless AC
      }
      if (!any) throw BlockError{1, fmt::format("G{} needs its centre (I J K) or CR=", ccw ? 3 : 2)};
    }
    out.arc(to, centre, plane, ccw, feed);
  }

  // The drilling cycles, hole by hole at the current position: RTP retract plane, RFP reference
  // plane, SDIS safety distance, DP depth (absolute) or DPR (relative to RFP).
  void drill_cycle(const Block::Cycle& cycle) {
    auto arg = [&](std::size_t i) -> std::optional<double> {
      return i < cycle.args.size() ? cycle.args[i] : std::nullopt;
    };
    auto need = [&](std::size_t i, const char* what) {
      auto v = arg(i);
      if (!v) throw BlockError{cycle.column, fmt::format("{} needs {}", cycle.name, what)};
      return *v * length_unit();
    };
    using Kind = ncmodel::MotionOut::Hole::Kind;
    ncmodel::MotionOut::Hole h;
    h.retract = need(0, "RTP");
    const double rfp = need(1, "RFP");
    h.approach = rfp + arg(2).value_or(0) * length_unit();
    if (arg(3)) h.depth = *arg(3) * length_unit();
    else if (arg(4)) h.depth = rfp - std::abs(*arg(4)) * length_unit();
    else throw BlockError{cycle.column, fmt::format("{} needs DP or DPR", cycle.name)};
    h.feed = feed;
    const std::string& n = cycle.name;
    if (n == "CYCLE81" || n == "CYCLE82") {
      h.kind = Kind::Drill;
      h.dwell = arg(5).value_or(0);
    } else if (n == "CYCLE83") {
      // FDEP (absolute) or FDPR (relative to RFP): the first depth; DAM shortens the next steps
      // (0: all as the first); VARI 1 lifts to RFP+SDIS after each step, 0 breaks the chip (1 mm).
      const double first = arg(5) ? *arg(5) * length_unit() : arg(6) ? rfp - std::abs(*arg(6)) * length_unit() : h.depth;
      h.kind = arg(11).value_or(1) != 0 ? Kind::Peck : Kind::ChipBreak;
      h.first_step = h.approach - first;
      h.step = rfp - first;
      h.step_reduction = arg(7).value_or(0) * length_unit();
      h.dwell = arg(8).value_or(0);
    } else if (n == "CYCLE84" || n == "CYCLE840") {
      h.kind = Kind::Tap;
    } else if (n == "CYCLE85" || n == "CYCLE89") {
      h.kind = Kind::Bore;
      h.dwell = arg(5).value_or(0);
      if (n == "CYCLE85") {
        h.feed = arg(6).value_or(feed);
        h.feed_out = arg(7).value_or(feed);
      }
    } else if (n == "CYCLE86") {
      h.kind = Kind::BoreSpindleStop;
      h.dwell = arg(5).value_or(0);
    } else {
      warn_once(n, cycle.column, fmt::format("the cycle {} is not modelled: no motion", n));
      return;
    }
    try {
      out.hole(h);
    } catch (const std::runtime_error& e) {
      throw BlockError{cycle.column, fmt::format("{}: {}", n, e.what())};
    }
  }

  void call(const Block::Call& c) {
    auto file = find_program(c.program);
    if (!file) throw BlockError{c.column, fmt::format("the subprogram `{}` is not in {}", c.program, folder.string())};
    if (stack.size() >= options.max_call_depth)
      throw BlockError{c.column, fmt::format("subprograms nested deeper than {} (a recursion?)", options.max_call_depth)};
    push(*file, file->filename().string(), c.repeats);
  }

  void jump(const Block::Jump& j) {
    Source& s = stack.back();
    if (j.back) {
      auto it = s.labels.find(j.label);
      if (it == s.labels.end()) throw BlockError{j.column, fmt::format("GOTOB: no label {} before this block", j.label)};
      s.lines->seek(it->second);
      return;
    }
    // Forward: read on to the label's block (blocks in between are skipped, not executed).
    std::string_view text;
    for (;;) {
      const ncmodel::LineReader::Mark at = s.lines->mark();
      if (!s.lines->next(text)) throw BlockError{j.column, fmt::format("GOTOF: no label {} after this block", j.label)};
      if (label_of(text) == j.label) {
        s.lines->seek(at);
        return;
      }
    }
  }

  // A program's first line may be its punched-tape header: `%` in the first column, then the file
  // name (`%_N_MAIN_MPF`, `%Flange3_MPF`) or nothing; the control reads it as the file's name, not
  // as a block. True when `line` is one (then it is skipped); a `%` anywhere else is an error.
  static bool is_tape_header(std::string_view line) {
    if (line.empty() || line[0] != '%') return false;
    std::size_t i = 1;
    while (i < line.size() && ident_char(line[i])) ++i;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    return i == line.size();
  }

  // Blanks, then the block number a line may start with: where what follows starts.
  static std::size_t after_block_number(std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i + 1 < line.size() && (line[i] == 'N' || line[i] == 'n') && ncmodel::is_digit(line[i + 1])) {
      ++i;
      while (i < line.size() && ncmodel::is_digit(line[i])) ++i;
    }
    return i;
  }

  // The label at `i` (blanks before it skipped), as written, and `i` after its `:`; empty when
  // there is none (then `i` is left as it is).
  static std::string_view label_at(std::string_view line, std::size_t& i) {
    std::size_t k = i;
    while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) ++k;
    const std::size_t b = k;
    if (k >= line.size() || !ident_start(line[k])) return {};
    while (k < line.size() && ident_char(line[k])) ++k;
    if (k >= line.size() || line[k] != ':') return {};
    i = k + 1;
    return line.substr(b, k - b);
  }

  // The label a line starts with (after its block number), upper case; empty when none.
  static std::string label_of(std::string_view line) {
    std::size_t i = after_block_number(line);
    return upper(label_at(line, i));
  }

  // Executes lines until commands are queued or the program ends.
  void run() {
    std::string_view raw;
    while (out.empty() && !finished && read_line(raw)) {
      if (++executed > options.max_executed_blocks) {
        diagnose(true, 1, fmt::format("more than {} blocks executed: a runaway loop?", options.max_executed_blocks));
        finished = true;
        stack.clear();
        return;
      }
      Source& s = stack.back();
      const std::size_t depth = stack.size();
      main_line = depth == 1 ? current_line : 0;
      if (current_line == 1 && is_tape_header(raw)) continue;
      std::string_view text = strip_comment(raw);
      // The block number, then a label (registered where it stands, for GOTOB).
      Cursor c{text, after_block_number(text)};
      if (const std::string_view label = label_at(text, c.i); !label.empty())
        s.labels[upper(label)] = s.before;  // GOTOB executes the label's block again
      Block& b = block_;
      b.clear();
      try {
        parse(c, b);
        execute(b);
      } catch (const BlockError& e) {
        diagnose(true, e.column, e.message);
      }
    }
  }
};

SinumerikReader::SinumerikReader(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

SinumerikReader::~SinumerikReader() = default;

std::unique_ptr<SinumerikReader> SinumerikReader::open(const std::string& path, Options options) {
  return std::unique_ptr<SinumerikReader>(new SinumerikReader(std::make_unique<Impl>(path, options)));
}

std::unique_ptr<SinumerikReader> SinumerikReader::from_string(std::string text, std::string name, Options options) {
  return std::unique_ptr<SinumerikReader>(
      new SinumerikReader(std::make_unique<Impl>(std::move(text), std::move(name), options)));
}

bool SinumerikReader::next(toolpath::Command& out) {
  if (impl_->out.empty()) impl_->run();
  return impl_->out.take(out);
}

std::size_t SinumerikReader::line() const { return impl_->main_line; }
const std::string& SinumerikReader::file_name() const { return impl_->main_name; }
const toolpath::Diagnostics& SinumerikReader::diagnostics() const { return impl_->diagnostics; }

}  // namespace sinumerik
