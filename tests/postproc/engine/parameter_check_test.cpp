// Values a post variable cannot take stop at their own position in the job: at read time for the
// catalogue's parameters (ParameterCheck), at run time for the others (the binding), never `:0:0:`.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <vector>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "postproc/engine/engine.hpp"
#include "postproc/engine/parameter_check.hpp"
#include "toolpath/trace_reader.hpp"
#include "tests/support/read_error.hpp"

namespace {

namespace fs = std::filesystem;
using postproc::ParameterKind;
using toolpath::Value;

TEST(ParameterCheck, KindMismatchTable) {
  struct Case {
    ParameterKind kind;
    Value value;
    std::string problem;  // "" when accepted
  } cases[] = {
      {ParameterKind::Numeric, Value::make_numeric(1.5), ""},
      {ParameterKind::Numeric, Value::make_integer(3), ""},
      {ParameterKind::Numeric, Value::make_logical(true), ""},
      {ParameterKind::Numeric, Value::make_string("12..5"), "expected a number, not '12..5'"},
      {ParameterKind::Numeric, Value::make_enum("abc"), "expected a number, not abc"},
      {ParameterKind::Integer, Value::make_integer(7), ""},
      {ParameterKind::Integer, Value::make_numeric(7.0), ""},
      {ParameterKind::Integer, Value::make_enum("Peck"), ""},  // drill_type: cycle names are codes
      {ParameterKind::Integer, Value::make_numeric(1e12), "expected an integer of at most 999999999, not 1000000000000"},
      {ParameterKind::Integer, Value::make_string("x"), "expected an integer, not 'x'"},
      {ParameterKind::Logical, Value::make_logical(false), ""},
      {ParameterKind::Logical, Value::make_integer(1), ""},
      {ParameterKind::Logical, Value::make_integer(2), "expected TRUE, FALSE, 0 or 1, not 2"},
      {ParameterKind::Logical, Value::make_enum("yes"), "expected TRUE, FALSE, 0 or 1, not yes"},
      {ParameterKind::String, Value::make_string("PART"), ""},
      {ParameterKind::String, Value::make_enum("PART"), ""},
      {ParameterKind::String, Value::make_integer(5), "expected a string ('text'), not 5"},
      {ParameterKind::Enum, Value::make_enum("CW"), ""},
      {ParameterKind::Enum, Value::make_integer(1), ""},
      {ParameterKind::Enum, Value::make_string("CW"), "expected an enumeration word (such as CW or COMP_LEFT), not 'CW'"},
      // a value of megabytes is quoted by its first 40 characters
      {ParameterKind::Numeric, Value::make_string(std::string(2 << 20, 'a')), "expected a number, not '" + std::string(40, 'a') + "...'"},
      {ParameterKind::Logical, Value::make_enum(std::string(2 << 20, 'b')), "expected TRUE, FALSE, 0 or 1, not " + std::string(40, 'b') + "..."},
  };
  for (const auto& c : cases)
    EXPECT_EQ(postproc::kind_mismatch(c.kind, c.value), c.problem) << int(c.kind) << " " << c.value.text.substr(0, 50);
}

// The message `read` and `run` give for a job, or "" when it reads through; the warnings, one per
// line, go to `warnings` when given.
std::string read_error(const std::string& trace, std::string* warnings = nullptr) {
  std::istringstream in(trace);
  toolpath::TraceReader reader(in, "job.trace");
  postproc::ParameterCheck check(reader, "job.trace", [&](const toolpath::SourcePosition& at, const std::string& m) {
    if (warnings) *warnings += at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + m + "\n";
  });
  return test_support::read_error(check);
}

// Deeper commands (the original post's own calls) pass unchecked as written, or are left out with
// Deeper::Leave, which gives exactly the stream commands.
TEST(ParameterCheck, DeeperCommandsPassOrAreLeftOut) {
  const std::string trace =
      "(1)@start_of_file   ==> program_number:1\n"
      "(2)@inner           ==> xpos:'not a number'\n"
      "(0)@line            ==> xpos:1 ypos:2 zpos:3 feed:100\n"
      "(3)@inner           ==> a:1\n"
      "(2)@inner           ==> a:2\n"
      "(1)@line            ==> xpos:4 ypos:5 zpos:6 feed:100\n"
      "(2)@inner           ==> a:3\n";
  for (const auto deeper : {postproc::ParameterCheck::Deeper::Pass, postproc::ParameterCheck::Deeper::Leave}) {
    std::istringstream in(trace);
    toolpath::TraceReader reader(in, "job.trace");
    postproc::ParameterCheck check(reader, "job.trace", {}, deeper);
    std::vector<std::string> seen;
    toolpath::Command c;
    while (check.next(c)) seen.push_back(std::to_string(c.depth) + c.name + "#" + std::to_string(c.index));
    if (deeper == postproc::ParameterCheck::Deeper::Pass)
      EXPECT_EQ(seen, (std::vector<std::string>{"1@start_of_file#0", "2@inner#1", "0@line#2", "3@inner#3", "2@inner#4",
                                                "1@line#5", "2@inner#6"}));
    else
      EXPECT_EQ(seen, (std::vector<std::string>{"1@start_of_file#0", "0@line#2", "1@line#5"}));
  }
}

TEST(ParameterCheck, ReadErrorsNameTheValue) {
  struct Case {
    const char* trace;
    const char* error;
  } cases[] = {
      {"@start_of_file\n@rapid_move\nxpos : 12..5\n", "job.trace:3:8: parameter `xpos` of @rapid_move: expected a number, not '12..5'"},
      {"(1)@rapid_move      ==> xpos:1.0 ypos:12..5 zpos:0.0\n",
       "job.trace:1:39: parameter `ypos` of @rapid_move: expected a number, not '12..5'"},
      {"@line\nfeed : fast\n", "job.trace:2:8: parameter `feed` of @line: expected a number, not fast"},
      {"@start_of_file\ng_file_name : 5000\n", "job.trace:2:15: parameter `g_file_name` of @start_of_file: expected a string ('text'), not 5000"},
      {"@arc\narc_direction : 'CW'\n", "job.trace:2:17: parameter `arc_direction` of @arc: expected an enumeration word (such as CW or COMP_LEFT), not 'CW'"},
      {"@start_of_file\nrotate_used : 7\n", "job.trace:2:15: parameter `rotate_used` of @start_of_file: expected TRUE, FALSE, 0 or 1, not 7"},
      {"@line\nxpos : 1\nfeed : -5\n", "job.trace:3:8: parameter `feed` of @line: expected a feed of 0 or more, not -5"},
      {"@arc\nradius : 0.0\n", "job.trace:2:10: parameter `radius` of @arc: expected an arc radius above 0, not 0"},
      {"@line\nxpos : 1\nypos : 2\nzpos : 0\nfeed : 0\n", ""},
      // Deeper commands record what the original post did: kept as written.
      {"(2)@rapid_move      ==> xpos:abc\n", ""},
      // Names outside the catalogue hold anything.
      {"@line\nmy_note : 12..5\nxpos : 1\nypos : 2\nzpos : 0\nfeed : 10\n", ""},
  };
  for (const auto& c : cases) EXPECT_EQ(read_error(c.trace), c.error) << c.trace;
}

// A motion command read from a trace carries what it cannot do without. One that no command
// before it gave is an error at the command's header; one given before is taken over, with one
// warning per command and parameter.
TEST(ParameterCheck, MotionsCarryWhatTheyNeed) {
  const std::string rapid = "(1)@rapid_move      ==> xpos:0 ypos:0 zpos:5\n";
  const std::string line_expects = "expected `xpos`, `ypos`, `zpos` and `feed`, which a trace gives with every @line";
  const std::string arc_expects =
      "expected `xpos`, `ypos`, `zpos`, `feed`, `arc_direction` and a centre, which a trace gives with every @arc";
  struct Case {
    std::string trace;
    std::string error;
    std::string warnings;
  } cases[] = {
      {rapid + "(1)@line            ==> xpos:1 ypos:0 zpos:0 feed:100\n", "", ""},
      {"@rapid_move\nxpos : 1\nypos : 2\n", "job.trace:1:1: @rapid_move has no `zpos`, and no command before it gave one: "
                                             "expected `xpos`, `ypos` and `zpos`, which a trace gives with every @rapid_move", ""},
      {rapid + "(1)@line            ==> xpos:1 ypos:0 zpos:0\n",
       "job.trace:2:1: @line has no `feed`, and no command before it gave one: " + line_expects, ""},
      {rapid + "(1)@line            ==> xpos:1 feed:100\n(1)@line            ==> xpos:2 feed:100\n", "",
       "job.trace:2:1: @line has no `ypos`: the last one given stays (a trace gives `xpos`, `ypos`, `zpos` and `feed` with "
       "every @line; further @line commands without it are not reported)\n"
       "job.trace:2:1: @line has no `zpos`: the last one given stays (a trace gives `xpos`, `ypos`, `zpos` and `feed` with "
       "every @line; further @line commands without it are not reported)\n"},
      {rapid + "(1)@arc             ==> xpos:1 ypos:0 zpos:0 feed:100 arc_direction:cw\n",
       "job.trace:2:1: @arc has no centre (`xcenter` and `ycenter`, or `xcenter_rel` and `ycenter_rel`), and no command "
       "before it gave one: " + arc_expects, ""},
      {rapid + "(1)@arc             ==> xpos:1 ypos:0 zpos:0 feed:100 arc_direction:cw xcenter:0.5\n",
       "job.trace:2:1: @arc has no centre (`xcenter` and `ycenter`, or `xcenter_rel` and `ycenter_rel`), and no command "
       "before it gave one: " + arc_expects, ""},
      {rapid + "(1)@arc             ==> xpos:1 ypos:0 zpos:0 feed:100 arc_direction:cw xcenter_rel:0.5 ycenter_rel:0\n", "", ""},
      {rapid + "(1)@arc             ==> xpos:1 ypos:0 zpos:0 feed:100 xcenter:0.5 ycenter:0\n",
       "job.trace:2:1: @arc has no `arc_direction`, and no command before it gave one: " + arc_expects, ""},
      {"@change_tool\ntool_offset : 3\n", "job.trace:1:1: @change_tool has no `tool_number`, and no command before it gave one: "
                                          "expected `tool_number`, which a trace gives with every @change_tool", ""},
      {"@drill_point\nxpos : 1\n", "job.trace:1:1: @drill_point has no `ypos`, and no command before it gave one: "
                                   "expected `xpos`, `ypos` and `zpos`, which a trace gives with every @drill_point", ""},
      // G-code read back by a controller model carries the axes of its machine (2XAxisCNC: no Z).
      {"(1)@start_of_file   ==> dialect:'2xaxiscnc'\n(1)@line            ==> xpos:1 ypos:2\n", "", ""},
      // What the original post called itself (depth 2) is not a command of the stream.
      {"(2)@line            ==> xpos:1\n", "", ""},
      // Other commands need nothing; a value of the wrong type is reported first.
      {"@start_of_job\n@end_of_file\n", "", ""},
      {"@line\nfeed : fast\n", "job.trace:2:8: parameter `feed` of @line: expected a number, not fast", ""},
  };
  for (const auto& c : cases) {
    std::string warnings;
    EXPECT_EQ(read_error(c.trace, &warnings), c.error) << c.trace;
    EXPECT_EQ(warnings, c.warnings) << c.trace;
  }
}

// Hands out prepared commands, each once.
class Commands final : public toolpath::CommandSource {
public:
  std::vector<toolpath::Command> commands;
  std::size_t at = 0;
  bool next(toolpath::Command& out) override {
    if (at == commands.size()) return false;
    out = commands[at++];
    return true;
  }
};

// The per-key table of the check's fast path against the rule written out here: every catalogue
// parameter (keyed or looked up by name, each twice, so that remembered names are used) with
// values of every kind at the edges, on an @arc and on another command.
TEST(ParameterCheck, FastPathAgreesWithTheRule) {
  const double inf = std::numeric_limits<double>::infinity();
  const Value values[] = {
      Value::make_integer(0), Value::make_integer(1), Value::make_integer(2), Value::make_integer(-1),
      Value::make_integer(999999999), Value::make_integer(1000000000), Value::make_numeric(0.0),
      Value::make_numeric(-0.0), Value::make_numeric(1.0), Value::make_numeric(0.5), Value::make_numeric(-3.5),
      Value::make_numeric(std::numeric_limits<double>::denorm_min()), Value::make_numeric(-std::numeric_limits<double>::denorm_min()),
      Value::make_numeric(999999999.0), Value::make_numeric(-999999999.0), Value::make_numeric(999999999.5),
      Value::make_numeric(1e300), Value::make_numeric(std::numeric_limits<double>::max()), Value::make_numeric(inf),
      Value::make_numeric(-inf), Value::make_numeric(std::nan("")), Value::make_logical(true), Value::make_logical(false),
      Value::make_string("PART"), Value::make_enum("CW"),
  };
  std::vector<std::string> names;
  for (const postproc::ParameterSpec& spec : postproc::parameter_table()) names.emplace_back(spec.name);
  names.push_back("my_note");  // outside the catalogue
  names.push_back("call_prms<<2>>");
  for (const char* command : {"@arc", "@line"}) {
    for (const std::string& name : names) {
      const postproc::ParameterSpec* spec = postproc::find_parameter(name);
      for (const Value& v : values) {
        std::string expected;
        if (spec) {
          expected = postproc::kind_mismatch(spec->kind, v);
          const bool number = v.kind == toolpath::ValueKind::Integer || v.kind == toolpath::ValueKind::Numeric;
          const double x = v.as_number();
          if (expected.empty() && number && toolpath::iequals(name, "feed") && !(x >= 0)) expected = "feed";
          if (expected.empty() && number && toolpath::iequals(name, "radius") && !(x > 0) && std::string(command) == "@arc")
            expected = "radius";
        }
        Commands source;
        toolpath::Command c;
        c.name = command;
        c.parameters.emplace_back(name, v);
        c.parameters.back().line = 7;
        source.commands = {c, c};
        postproc::ParameterCheck check(source, "job.trace");
        for (int round = 0; round < 2; ++round) {
          std::string error;
          toolpath::Command out;
          try {
            check.next(out);
          } catch (const toolpath::InputError& e) {
            error = e.what();
          }
          EXPECT_EQ(error.empty(), expected.empty()) << command << " " << name << " " << int(v.kind) << " " << v.numeric
                                                     << " " << v.integer << ": " << error;
          if (!error.empty()) {
            EXPECT_EQ(error.rfind("job.trace:7:0: parameter `" + name + "` of " + command + ": ", 0), 0u) << error;
          }
        }
      }
    }
  }
}

// A parameter outside the catalogue that the post declares itself (`global numeric`): a value of
// another type is an error of the run, at that value's position.
TEST(ParameterCheck, RunErrorsNameTheValue) {
  const fs::path dir = fs::temp_directory_path() / ("postproc-check-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "p.gpp") << "@init_post\n  global numeric my_depth\nendp\n@line\n  {nl, my_depth}\nendp\n";
  postproc::EngineOptions engine_options;
  engine_options.post = (dir / "p.gpp").string();
  postproc::Engine engine(engine_options);
  std::istringstream in("@start_of_file\n@line\nmy_depth : 5\nxpos : 0\nypos : 0\nzpos : 0\nfeed : 1\n@line\nmy_depth : deep down\n");
  toolpath::TraceReader reader(in, "job.trace");
  postproc::OutputFiles files(dir, postproc::OutputFiles::LineEnd::LF, true);
  postproc::RunOptions options;
  options.input_name = "job.trace";
  std::string error;
  try {
    engine.run(reader, files, options);
  } catch (const std::exception& e) {
    error = e.what();
  }
  fs::remove_all(dir);
  EXPECT_EQ(error.rfind("job.trace:9:12: parameter `my_depth` of @line: error 386: ", 0), 0u) << "[" << error << "]";
}

// Passes a source on without being it: the check then cannot ask a trace reader for its screen.
class Unscreened final : public toolpath::CommandSource {
public:
  explicit Unscreened(toolpath::CommandSource& inner) : inner_(inner) {}
  bool next(toolpath::Command& out) override { return inner_.next(out); }

private:
  toolpath::CommandSource& inner_;
};

// What the check gives for `trace`: every command with its values, the warnings, then the error
// if any. With `screen`, the check reads from the trace reader itself, which screens the values
// for it; `screened` counts the commands it took as screened.
std::string checked(const std::string& trace, bool screen, int* screened = nullptr) {
  std::istringstream in(trace);
  toolpath::TraceReader reader(in, "job.trace");
  Unscreened hidden(reader);
  std::ostringstream out;
  postproc::ParameterCheck check(screen ? static_cast<toolpath::CommandSource&>(reader) : hidden, "job.trace",
                                 [&](const toolpath::SourcePosition& at, const std::string& m) {
                                   out << "warning " << at.line << ':' << at.column << ": " << m << '\n';
                                 });
  toolpath::Command c;
  try {
    while (check.next(c)) {
      out << c.index << ' ' << c.name << ':';
      for (const toolpath::Parameter& p : c.parameters)
        out << ' ' << p.name << '=' << int(p.value.kind) << '/' << p.value.integer << '/' << p.value.numeric << '/' << p.value.text;
      out << '\n';
      std::uint32_t need;
      if (screened && reader.screened(need)) ++*screened;
    }
  } catch (const toolpath::InputError& e) {
    out << "error: " << e.what() << '\n';
  }
  return out.str();
}

// The reader screens the values it reads by the check's own table (toolpath::ValueScreen), so that
// a command whose every parameter passed is not looked at again: the check must say the same
// with the screen as without, on jobs with wrong values of every kind (a negative feed, an arc
// radius of 0, a word for a number, a number for a string, an integer out of range), values the
// fast path leaves to the general rule, names outside the catalogue, block-form lines, motions
// that lack what they need, and wrong values in deeper commands, which are not checked.
TEST(ParameterCheck, ScreenedByTheReaderAsCheckedOneByOne) {
  struct Key {
    const char* name;
    std::vector<const char*> values;  // the first ones pass
  };
  const Key keys[] = {
      {"xpos", {"1.5", "-0.5", "45.0F", "7", "1e3", "CW", "'a'", "TRUE", "12345678901234567890.5"}},
      {"ypos", {"0.0", "5.0T", "-12", "0", "x"}},
      {"zpos", {"-0.5", "-1.0", "2", "FALSE"}},
      {"feed", {"1500.0", "1200.0F", "0", "0.0", "-1.0", "-1", "-0.0", "1e-320", "CCW"}},
      {"radius", {"5.0", "0.001", "5", "0.0", "-5.0", "0", "4.9e-324"}},
      {"arc_direction", {"CCW", "CW", "1", "'CW'", "TRUE"}},
      {"xcenter", {"45.0", "5.0", "'q'"}},
      {"ycenter", {"5.0", "45.0", "FALSE"}},
      {"tool_number", {"4", "4.0", "999999999.0", "1000000000.0", "1e12", "T1", "'4'"}},
      {"job_name", {"'F-BENCH'", "PROFILE", "7", "1.5", "TRUE"}},
      {"my_note", {"1", "'x'", "CW"}},
  };
  const char* commands[] = {"@line", "@arc", "@rapid_move", "@change_tool", "@start_of_job", "@drill_point"};
  std::mt19937 rng(20261201);
  int screened = 0;
  for (int round = 0; round < 3000; ++round) {
    // The parameters each command name carries in this job (so that the reader's recycled slots
    // hold their names, as in a job SolidCAM writes, and its fast path reads them).
    std::uint32_t carries[std::size(commands)];
    for (std::uint32_t& set : carries) set = static_cast<std::uint32_t>(rng());
    // Mostly what the motions need (see MotionsCarryWhatTheyNeed): keys 0-3, and 5-7 for @arc.
    for (std::size_t m : {0, 1, 2, 5}) carries[m] |= rng() % 16 ? 0xfu : 0u;
    carries[1] |= rng() % 16 ? 0xe0u : 0u;
    std::string trace;
    for (std::size_t c = 1 + rng() % 40; c > 0; --c) {
      const std::size_t command = rng() % 3 == 0 ? rng() % std::size(commands) : rng() % 2;
      // The original post's own calls are not checked: their wrong values must not pass for
      // checked ones when a command of the stream repeats them.
      const bool deeper = rng() % 10 == 0;
      const std::size_t start = trace.size();
      trace += std::string(deeper ? "(2)" : "(1)") + commands[command] + "             ==>";
      std::size_t on_line = 0;
      for (std::size_t k = 0; k < std::size(keys); ++k) {
        const Key& key = keys[k];
        if ((((carries[command] >> k) & 1) != 0) == (rng() % 40 == 0)) continue;  // now and then another shape
        // Mostly a value that passes; now and then any of them.
        const std::size_t pick = rng() % (deeper ? 3 : 40) == 0 ? rng() % key.values.size() : rng() % 2;
        if (rng() % 60 == 0) {
          trace += std::string("\n  ") + key.name + " : " + key.values[pick] + "\n";  // block form
          on_line = 0;
          trace += "                    ..>";
          continue;
        }
        if (++on_line == 5) {
          trace += "\n                    ..>";
          on_line = 0;
        }
        trace += ' ';
        trace += key.name;
        trace += ':';
        trace += key.values[pick];
      }
      trace += '\n';
      if (deeper && rng() % 2) trace += "(1)" + trace.substr(start + 3);  // the same at depth 1
    }
    const std::string expected = checked(trace, false);
    ASSERT_EQ(checked(trace, true, &screened), expected) << trace;
  }
  EXPECT_GT(screened, 2000);  // the screen was used
}

}  // namespace
