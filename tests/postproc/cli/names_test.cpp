// Which names a post may use, and that `check` and `run` agree on them (docs/gppl-language.md,
// "Names"): a name is defined by the post, the system, the machine file or the job; any other name
// is the same diagnostic, with the same position and error number, from both.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gppl/compile/system_variables.hpp"
#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using test_support::run_cli;

class Names : public ::testing::Test {
protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("postproc-names-test-" + std::to_string(::getpid()) + "-" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  }
  fs::path dir;
};

const std::string kJob =
    "@start_of_file\ng_file_name : 'JOB'\n"
    "@line\nxpos : 1\nypos : 0\nzpos : 0\nfeed : 100\nuser_clamp : 3\n"
    "@end_of_file\n";

TEST_F(Names, UndefinedNameIsTheSameDiagnosticInCheckAndRun) {
  struct Case {
    const char* what;
    const char* post;
    const char* diagnostic;  // after "p.gpp:"
  } cases[] = {
      {"printed", "@start_of_file\n  {nb, 'X', not_there}\nendp\n", "2:13: error 383: Variable 'not_there' is not defined"},
      {"assigned", "@start_of_file\n  not_there = 1\nendp\n", "2:3: error 404: Symbol 'not_there' does not exist"},
      {"tested", "@line\n  if not_there eq 1\n  endif\nendp\n", "2:6: error 383: Variable 'not_there' is not defined"},
      {"change()", "@line\n  if change(not_there)\n  endif\nendp\n", "2:13: error 383: Variable 'not_there' is not defined"},
      {"in an argument", "@line\n  {nb, tostr(abs(not_there))}\nendp\n", "2:18: error 383: Variable 'not_there' is not defined"},
      {"a job name read before the job gives it", "@start_of_file\n  {nb, user_clamp}\nendp\n", ""},
  };
  const std::string job = write("job.trace", kJob);
  for (const auto& c : cases) {
    const std::string post = write("p.gpp", c.post);
    const std::string expected = std::string(c.diagnostic).empty() ? "" : post + ":" + c.diagnostic;
    auto checked = run_cli({"check", "-q", post});
    auto ran = run_cli({"run", "-q", "--post", post, job});
    if (expected.empty()) {  // check without the job refuses it; with the job, check passes and run says where
      EXPECT_EQ(checked.code, 1) << c.what;
      EXPECT_EQ(run_cli({"check", "-q", "--job", job, post}).code, 0) << c.what;
      EXPECT_NE(ran.err.find(post + ":2:8: error 383: Variable 'user_clamp' is not defined"), std::string::npos)
          << c.what << "\n" << ran.err;
      continue;
    }
    EXPECT_EQ(checked.code, 1) << c.what;
    EXPECT_NE(checked.out.find(expected), std::string::npos) << c.what << "\n" << checked.out;
    EXPECT_EQ(ran.code, 1) << c.what;
    EXPECT_NE(ran.err.find(expected), std::string::npos) << c.what << "\n" << ran.err;
  }
}

// The job's trace carries the machine's user parameters: `check --job` knows them, `run` reads them.
TEST_F(Names, JobNamesAreDefined) {
  const std::string job = write("job.trace", kJob);
  const std::string post = write("p.gpp", "@line\n  {nb, 'clamp ', user_clamp}\nendp\n");
  EXPECT_EQ(run_cli({"check", "-q", post}).code, 1);
  auto checked = run_cli({"check", "-q", "--job", job, post});
  EXPECT_EQ(checked.code, 0) << checked.out;
  auto ran = run_cli({"run", "-q", "--post", post, job});
  EXPECT_EQ(ran.code, 0) << ran.err;
  EXPECT_EQ(ran.out, "\nclamp 3");
}

// The PRP's user parameters (typed declarations) are defined for check and run alike.
TEST_F(Names, MachineUserParametersAreDefined) {
  const std::string job = write("job.trace", kJob);
  const std::string prp = write("p.prp", "@pre_processor\noptions = CLAMP_DELAY NUMERIC\nendp\n");
  const std::string post = write("p.gpp", "@start_of_file\n  clamp_delay = 2.5\n  {nb, 'delay ', clamp_delay}\nendp\n@line\nendp\n");
  auto checked = run_cli({"check", "-q", "--prp", prp, post});
  EXPECT_EQ(checked.code, 0) << checked.out;
  auto ran = run_cli({"run", "-q", "--post", post, "--prp", prp, job});
  EXPECT_EQ(ran.code, 0) << ran.err;
  EXPECT_EQ(ran.out, "\ndelay 2.5");
}

// The run fills what it knows; a value in the trace wins.
TEST_F(Names, RunFillsWhatItKnows) {
  const std::string post = write("fill.gpp",
                                 "@start_of_file\n  {nb, part_name, ' ', pre_processor, ' ', job_name}\nendp\n"
                                 "@line\n  {nb, part_name}\nendp\n");
  const std::string job = write("part7.trace", kJob + "@line\npart_name : 'FROM-TRACE'\n");
  auto ran = run_cli({"run", "-q", "--post", post, job});
  EXPECT_EQ(ran.code, 0) << ran.err;
  EXPECT_EQ(ran.out, "\npart7 fill \npart7\nFROM-TRACE");
}

// The paths the run fills look like SolidCAM's, with backslashes, so that posts which cut the name
// out at the last `\` (SolidCAM's Siemens 828D post) find it.
TEST_F(Names, RunPathsHaveBackslashes) {
  const std::string post = write("paths.gpp",
                                 "@start_of_file\n  local integer i\n  i = instr(rev(part_model_name), '\\\\')\n"
                                 "  {nb, right(part_model_name, i - 1), ' ', right(part_full_name, instr(rev(part_full_name), '\\\\') - 1)}\nendp\n"
                                 "@line\nendp\n");
  const std::string job = write("part7.trace", kJob);
  auto ran = run_cli({"run", "-q", "--post", post, job});
  EXPECT_EQ(ran.code, 0) << ran.err;
  EXPECT_EQ(ran.out, "\npart7.trace part7");
}

// An inferred type gives way to the job's value: `stock_type` is guessed numeric, the trace sends text.
TEST_F(Names, InferredTypesFollowTheJob) {
  const std::string post = write("stock.gpp", "@start_of_file\n  if stock_type eq 'box'\n    {nb, 'box'}\n  endif\nendp\n");
  const std::string job = write("stock.trace", "@start_of_file\nstock_type : 'box'\n");
  EXPECT_EQ(run_cli({"check", "-q", post}).code, 0);
  auto ran = run_cli({"run", "-q", "--post", post, job});
  EXPECT_EQ(ran.code, 0) << ran.err;
  EXPECT_EQ(ran.out, "\nbox");
}

// Tool-type words of the trace compare equal to the system constants of the same name.
TEST_F(Names, ToolTypeWordsAreConstants) {
  const std::string post = write("tools.gpp",
                                 "@change_tool\n  if tool_type eq face_mill\n    {nb, 'face'}\n  else\n    {nb, 'other'}\n"
                                 "  endif\nendp\n");
  const std::string job = write("tools.trace", "@change_tool\ntool_number : 1\ntool_type : face_mill\n"
                                                "@change_tool\ntool_number : 2\ntool_type : END_MILL\n");
  EXPECT_EQ(run_cli({"check", "-q", post}).code, 0);
  auto ran = run_cli({"run", "-q", "--post", post, job});
  EXPECT_EQ(ran.code, 0) << ran.err;
  EXPECT_EQ(ran.out, "\nface\nother");
}

// Array system variables are filled element by element from the trace, in block and inline form.
TEST_F(Names, ArraysFillFromTheTrace) {
  const std::string post = write("arrays.gpp",
                                 "@call_prms\n  {nb, 'P', call_prms<<1>>, ' ', call_prms<<2>>}\nendp\n"
                                 "@wc_chng_condition\n  {nb, chng_cond<<1,1>>, '=', chng_cond<<3,1>>}\nendp\n");
  const std::string job = write("arrays.trace",
                                "@call_prms\nlabel : 1\ncall_prms_num : 2\ncall_prms<<1>> : 5.\ncall_prms<<2>> : 7\n"
                                "(1)@wc_chng_condition==> chng_cond_num:1 chng_cond<<1,1>>:'power' chng_cond<<3,1>>:'12'\n");
  auto ran = run_cli({"run", "-q", "--post", post, job});
  EXPECT_EQ(ran.code, 0) << ran.err;
  EXPECT_EQ(ran.out, "\nP5. 7.\npower=12");
  const std::string bad = write("bad.trace", "@call_prms\ncall_prms<<101>> : 5.\n");
  ran = run_cli({"run", "-q", "--post", post, bad});
  EXPECT_EQ(ran.code, 1);
  EXPECT_NE(ran.err.find("index 1 of call_prms is 101, outside 1..100"), std::string::npos) << ran.err;
}

// Every name of SolidCAM's list passes `postproc check` in a post that prints it.
TEST_F(Names, EveryListedNamePassesCheck) {
  std::ifstream in("gppl/data/solidcam-system-variables.txt");
  std::string post = "@start_of_file\n";
  std::size_t count = 0;
  for (std::string n; std::getline(in, n);) {
    if (n.empty() || n[0] == '#') continue;
    const gppl::SystemVariable* v = gppl::find_system_variable(n);
    ASSERT_NE(v, nullptr) << n;
    post += "  {nb, " + n + (v->rows == 0 ? "" : v->columns == 0 ? "<<1>>" : "<<1,1>>") + "}\n";
    ++count;
  }
  EXPECT_EQ(count, 1629u);
  auto checked = run_cli({"check", "-q", write("every.gpp", post + "endp\n")});
  EXPECT_EQ(checked.code, 0) << checked.out.substr(0, 2000);
}

}  // namespace
