// start_line / end_line in the language: allowed only as items of a generate statement (compile
// errors with the GPPTool number and position everywhere else), formatted as integers, their text
// supplied by the host, which also hears about numbered blocks and procedure boundaries.
#include <gtest/gtest.h>

#include "support.hpp"

using namespace gppl_test;

namespace {

struct Misuse {
  const char* what;
  const char* source;
  const char* expected;  // "line:column: error N"
};

class LineFunctionMisuse : public testing::TestWithParam<Misuse> {};

TEST_P(LineFunctionMisuse, IsACompileError) {
  gppl::CompileOptions strict;
  EXPECT_EQ(compile_error(GetParam().source), GetParam().expected) << GetParam().what;
  strict.implicit_host_variables = false;
  EXPECT_EQ(compile_error(GetParam().source, strict), GetParam().expected) << GetParam().what << " (strict)";
}

INSTANTIATE_TEST_SUITE_P(
    OutsideGenerate, LineFunctionMisuse,
    testing::Values(Misuse{"assignment source", "@t\ngcode = start_line\nendp\n", "2:9: error 383"},
                    Misuse{"condition", "@t\nif end_line > 0\nendif\nendp\n", "2:4: error 383"},
                    Misuse{"expression in a generate item", "@t\n{' N'(start_line + 1)}\nendp\n", "2:7: error 383"},
                    Misuse{"function argument in a generate item", "@t\n{tostr(End_Line)}\nendp\n", "2:8: error 383"},
                    Misuse{"as a display format", "@t\n{' X'gcode:start_line}\nendp\n", "2:12: error 383"},
                    Misuse{"attribute", "@t\nif change(start_line)\nendif\nendp\n", "2:11: error 383"},
                    Misuse{"assignment target", "@t\nstart_line = 3\nendp\n", "2:1: error 389"},
                    Misuse{"global declaration", "@t\nglobal integer start_line\nendp\n", "2:16: error 400"},
                    Misuse{"local declaration", "@t\nlocal integer END_LINE\nendp\n", "2:15: error 401"},
                    Misuse{"procedure parameter", "@t(integer start_line)\nendp\n", "1:12: error 401"}));

// A host that supplies `<start_line|format>` and records what the interpreter told it.
struct RecordingHost : CapturedLines {
  std::vector<std::string> events;
  gppl::Interpreter* interpreter = nullptr;
  void block_numbered(std::int64_t number) override { events.push_back("N" + std::to_string(number)); }
  void procedure_boundary(gppl::ProcedureId id, bool entering) override {
    events.push_back((entering ? "enter " : "leave ") + std::to_string(id));
  }
  void line_function(gppl::LineFunction which, std::string_view format, const gppl::Position&,
                     std::string& out) override {
    out += "<" + std::string(gppl::name_of(which)) + "|" + std::string(format) + ">";
  }
};

struct Hosted {
  explicit Hosted(const std::string& source) : program(gppl::compile_source(source, "h.gpp", {})), run(program, host) {}
  std::shared_ptr<const gppl::Program> program;
  RecordingHost host;
  gppl::Interpreter run;
  void call(const std::string& name) { run.call(*run.find_procedure(name)); }
  std::string text() {
    run.finish();
    std::string all;
    for (const auto& l : host.lines) all += l + "\n";
    return all;
  }
};

TEST(LineFunctions, FormatOfTheItemElseIntegerDefault) {
  Hosted post(
      "@init_post\n  integer_def_f = '4.0'\nendp\n"
      "@t\n  global string fmt\n  fmt = '3.0(p)'\n"
      "  {nl, 'A' start_line, ' B' end_line:'6.0', ' C' START_LINE:fmt, [' D' end_line], ' E'xpos}\nendp\n");
  post.run.start();
  post.call("@t");
  // A modal group prints only when one of its variables changed: a function is not a variable.
  EXPECT_EQ(post.text(), "A<start_line|4.0> B<end_line|6.0> C<start_line|3.0(p)> E0\n");
}

TEST(LineFunctions, NoFormatAtAllIsTheBuiltInIntegerDefault) {
  Hosted post("@t\n  {nl, start_line}\nendp\n");
  post.call("@t");
  EXPECT_EQ(post.text(), "<start_line|5.0(p)>\n");
}

TEST(LineFunctions, HostHearsNumberedBlocksAndProcedureBoundaries) {
  Hosted post(
      "@init_post\n  blknum_gen = TRUE\n  blknum = 10\n  blknum_delta = 10\nendp\n"
      "@inner\n  {nb, 'X'}\n  {nl, 'unnumbered'}\nendp\n"
      "@t\n  {nb, 'G14 N1=' start_line}\n  call @inner\nendp\n");
  post.run.start();
  const auto init = std::to_string(*post.run.find_procedure("@init_post"));
  EXPECT_EQ(post.host.events, (std::vector<std::string>{"enter " + init, "leave " + init}));
  post.host.events.clear();
  post.call("@t");
  const auto t = std::to_string(*post.run.find_procedure("@t"));
  const auto inner = std::to_string(*post.run.find_procedure("@inner"));
  EXPECT_EQ(post.host.events,
            (std::vector<std::string>{"enter " + t, "N10", "enter " + inner, "N20", "leave " + inner, "leave " + t}));
  EXPECT_EQ(post.text(), "N10 G14 N1=<start_line|5.0(p)>\nN20 X\nunnumbered\n");
}

TEST(LineFunctions, PostsWithoutThemCostTheHostNothing) {
  Hosted post("@init_post\n  blknum_gen = TRUE\nendp\n@t\n  {nb, 'X'}\nendp\n");
  post.run.start();
  post.call("@t");
  EXPECT_TRUE(post.host.events.empty());
  EXPECT_FALSE(gppl::uses_line_functions(*post.program));
  EXPECT_TRUE(gppl::uses_line_functions(*Hosted("@t\n  {nl, end_line}\nendp\n").program));
}

TEST(LineFunctions, HostWithoutThemIsARunTimeErrorAtTheItem) {
  EXPECT_EQ(run_error("@t\n  {nl, 'N1=' start_line}\nendp\n"), "2:14: error 404");
}

TEST(LineFunctions, HostErrorIsReportedAtTheItem) {
  struct Refusing : CapturedLines {
    void line_function(gppl::LineFunction, std::string_view, const gppl::Position&, std::string&) override {
      throw std::runtime_error("@line has no body");
    }
  } host;
  auto program = gppl::compile_source("@t\n  {nb, ' P' end_line}\nendp\n", "r.gpp", {});
  gppl::Interpreter run(program, host);
  try {
    run.call(*run.find_procedure("@t"));
    FAIL() << "no error";
  } catch (const gppl::Error& e) {
    EXPECT_STREQ(e.what(), "r.gpp:2:13: error 404: Symbol 'end_line' does not exist: @line has no body");
  }
}

TEST(LineFunctions, InvalidFormatIsReportedAtTheItem) {
  EXPECT_EQ(run_error("@t\n  {nl, start_line:'x'}\nendp\n"), "2:8: error 423");
}

}  // namespace
