// The command line: dispatch, help, exit codes, and `read` printing a stream that reads back the same.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "postproc/cli/cli.hpp"
#include "tests/support/cli_run.hpp"

namespace {

using Run = test_support::CliRun;
const auto run = test_support::run_cli;

TEST(Cli, ExitCodes) {
  struct Case {
    std::vector<std::string> args;
    int code;
    const char* err_contains;
  } cases[] = {
      {{}, 2, "usage: postproc <command>"},
      {{"frobnicate"}, 2, "unknown command `frobnicate`"},
      {{"read"}, 2, "expected one input file"},
      {{"read", "--bogus", "x"}, 2, "unknown option --bogus"},
      {{"read", "--dialect"}, 2, "option --dialect needs a value"},
      {{"read", "--dialect=gcode", "x"}, 2, "unknown dialect `gcode`"},
      {{"read", "no/such.trace"}, 1, "no/such.trace: cannot open file"},
      {{"read", "toolpath/data/bad.trace"}, 1, "toolpath/data/bad.trace:3:6: expected `:` after the parameter name `ypos`"},
      {{"read", "postproc/cli/data/bad-number.trace"}, 1,
       "postproc/cli/data/bad-number.trace:4:8: parameter `xpos` of @rapid_move: expected a number, not '12..5'"},
      {{"--help"}, 0, ""},
      {{"read", "--help"}, 0, ""},
      {{"--version"}, 0, ""},
  };
  for (const auto& c : cases) {
    auto r = run(c.args);
    EXPECT_EQ(r.code, c.code) << r.err;
    EXPECT_NE(r.err.find(c.err_contains), std::string::npos) << r.err;
  }
}

// `test` with nothing to compare is a failure, not "ok: 0 lines match" (a green CI with no test).
TEST(Cli, TestWithNothingComparedFails) {
  const auto empty = std::filesystem::temp_directory_path() / ("postproc-empty-golden-" + std::to_string(::getpid()));
  std::filesystem::create_directories(empty);
  auto r = run({"test", "golden/solidcam-fanuc/toolpath.trace", "--post", "golden/solidcam-fanuc/fanuc.gpp", "--prp",
                "golden/solidcam-fanuc/fanuc.prp", "--expect", empty.string() + "/", "-q"});
  std::filesystem::remove_all(empty);
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("nothing was compared: " + empty.string() + "/ holds no golden file for the output (OUT.TAP)"),
            std::string::npos)
      << r.out;
}

// --trace switches on SolidCAM-style tracing from the command line: every procedure at a level, or
// only the post's own `trace` statements, to stderr or a file.
TEST(Cli, TraceFromTheCommandLine) {
  const auto dir = std::filesystem::temp_directory_path() / ("postproc-trace-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "p.gpp") << "@start_of_file\n  trace '@line':2\n  {nl, '%'}\nendp\n@rapid_move\nendp\n"
                                  "@line\n  {nl, 'G1'}\nendp\n";
  std::ofstream(dir / "j.trace") << "@start_of_file\n@rapid_move\nxpos : 0\nypos : 0\nzpos : 5\n"
                                    "@line\nxpos : 1\nypos : 0\nzpos : 0\nfeed : 100\n";
  auto traced = [&](const std::string& option) {
    auto r = run({"run", "-q", "--post", (dir / "p.gpp").string(), (dir / "j.trace").string(), "--trace", option,
                  "-o", (dir / "out.nc").string()});
    EXPECT_EQ(r.code, 0) << r.err;
    return r.err;
  };
  // A line is traced when it ends: `%` ends where @line starts the next one.
  EXPECT_EQ(traced("post"), "(1)@line            ==>\n                      > %\n                      > G1\n");
  const std::string all = traced("1");
  EXPECT_NE(all.find("(1)@start_of_file   ==>"), std::string::npos) << all;
  EXPECT_NE(all.find("(1)@rapid_move      ==>"), std::string::npos) << all;
  EXPECT_EQ(traced("1:" + (dir / "t.txt").string()), "");
  std::ifstream file(dir / "t.txt");
  std::string first;
  std::getline(file, first);
  EXPECT_EQ(first, "(1)@start_of_file   ==>");
  std::filesystem::remove_all(dir);
}

// A line written by a statement of an include file names that file (relative to the post's folder)
// and its line, in explain's text and page and in test --diff; the post's own lines name the post.
TEST(Cli, LinesOfIncludeFilesNameTheirFile) {
  const auto dir = std::filesystem::temp_directory_path() / ("postproc-include-origin-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "lib");
  std::ofstream(dir / "p.gpp") << "@start_of_file\n  {nl, '%'}\nendp\n@rapid_move\nendp\ninc 'lib/moves.inc'\n";
  std::ofstream(dir / "lib" / "moves.inc") << "; moves\n@line\n  {nl, 'G1'}\nendp\n";
  std::ofstream(dir / "j.trace") << "@start_of_file\n@rapid_move\nxpos : 0\nypos : 0\nzpos : 5\n"
                                    "@line\nxpos : 1\nypos : 0\nzpos : 0\nfeed : 100\n";
  std::ofstream(dir / "expected.nc") << "\n%\nG2";
  const std::string post = (dir / "p.gpp").string(), job = (dir / "j.trace").string();
  const auto text = run({"explain", "-q", "--post", post, job});
  EXPECT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("% "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("| #0 @start_of_file -> @start_of_file (p.gpp:2)"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("| #2 @line -> @line (lib/moves.inc:3)"), std::string::npos) << text.out;
  const auto diff = run({"test", "-q", job, "--post", post, "--expect", (dir / "expected.nc").string(), "--diff"});
  EXPECT_EQ(diff.code, 1);
  EXPECT_NE(diff.out.find("procedure @line (lib/moves.inc:3)"), std::string::npos) << diff.out << diff.err;
  const auto page = run({"explain", "-q", "--post", post, "--html", (dir / "page.html").string(), job});
  EXPECT_EQ(page.code, 0) << page.err;
  std::ifstream in(dir / "page.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find(R"({"lines":["; moves","@line","  {nl, 'G1'}","endp"],"name":"lib/moves.inc"})"), std::string::npos)
      << html.substr(html.find("\"sources\""), 400);
  EXPECT_NE(html.find(R"(["G1",2,)"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// --progress draws the bar into a log too (stderr is no terminal here).
TEST(Cli, ProgressCanBeForced) {
  const auto dir = std::filesystem::temp_directory_path() / ("postproc-progress-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream job(dir / "j.trace");
    job << "@start_of_file\n";
    for (int i = 0; i < 5000; ++i) job << "@line\nxpos : " << i << "\nypos : 0\nzpos : 0\nfeed : 100\n";
  }
  std::ofstream(dir / "p.gpp") << "@line\nendp\n@rapid_move\nendp\n";
  for (bool forced : {false, true}) {
    std::vector<std::string> args{"run", "-q", "--post", (dir / "p.gpp").string(), (dir / "j.trace").string(), "-o",
                                  (dir / "out.nc").string()};
    if (forced) args.push_back("--progress");
    auto r = run(args);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("4096 commands") != std::string::npos, forced) << r.err;
  }
  std::filesystem::remove_all(dir);
}

// Every subcommand: a wrong command line is exit code 2 with a message naming the command; a
// missing input file is exit code 1 naming the file; --help is 0.
TEST(Cli, UsageErrorsOfEverySubcommand) {
  const std::string post = "../machines/fanuc/fanuc.gpp";
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string err_contains;
  } cases[] = {
      {{"run"}, 2, "postproc run: expected one job file"},
      {{"run", "job.trace"}, 2, "postproc run: --post is required"},
      {{"run", "--post"}, 2, "postproc run: option --post needs a value"},
      {{"run", "--post", post, "a.trace", "b.trace"}, 2, "postproc run: expected one job file"},
      {{"run", "--post", post, "--units", "mm", "j.trace"}, 2, "postproc run: --units must be metric or inch, not `mm`"},
      {{"run", "--bogus"}, 2, "postproc run: unknown option --bogus"},
      {{"run", "--post", "no.gpp", "j.trace"}, 1, "no.gpp:1:1: error 399: Can't open file 'no.gpp'"},
      {{"run", "--post", post, "--prp", "no.prp", "j.trace"}, 1, "no.prp: cannot open the PRP file"},
      {{"run", "--post", post, "no/such.trace"}, 1, "no/such.trace: cannot open file"},
      {{"run", "--post", post, "postproc/cli/data/bad-number.trace"}, 1,
       "postproc/cli/data/bad-number.trace:4:8: parameter `xpos` of @rapid_move: expected a number, not '12..5'"},
      {{"run", "--post", post, "--threads", "4", "j.trace"}, 2, "postproc run: --threads is 2 or 3, not '4'"},
      {{"run", "--help"}, 0, ""},
      {{"check"}, 2, "postproc check: expected one or more .gpp files or machine files (.prp, .mac, .vmid)"},
      {{"check", "--bogus", "x.gpp"}, 2, "postproc check: unknown option --bogus"},
      {{"check", "--help"}, 0, ""},
      {{"test"}, 2, "postproc test: expected one job file"},
      {{"test", "j.trace"}, 2, "postproc test: --post is required"},
      {{"test", "j.trace", "--post", post, "--tolerance", "abc"}, 2,
       "postproc test: --tolerance needs a number >= 0, not `abc`"},
      {{"test", "no/such.trace", "--post", post}, 1, "no/such.trace: cannot open file"},
      {{"test", "--help"}, 0, ""},
      {{"explain"}, 2, "postproc explain: expected one job file"},
      {{"explain", "j.trace"}, 2, "postproc explain: --post is required"},
      {{"explain", "--post", post, "no/such.trace"}, 1, "no/such.trace: cannot open file"},
      {{"explain", "--help"}, 0, ""},
      {{"plot"}, 2, "postproc plot: expected one input file"},
      {{"plot", "x.trace"}, 2, "postproc plot: -o FILE.svg is required"},
      {{"plot", "--dialect", "foo", "x.trace", "-o", "o.svg"}, 2, "postproc plot: unknown dialect `foo`"},
      {{"plot", "--help"}, 0, ""},
      {{"verify"}, 2, "postproc verify: expected one job file"},
      {{"verify", "j.trace"}, 2, "postproc verify: --post is required"},
      {{"verify", "--help"}, 0, ""},
  };
  for (const auto& c : cases) {
    std::string line;
    for (const auto& a : c.args) line += a + " ";
    SCOPED_TRACE(line);
    auto r = run(c.args);
    EXPECT_EQ(r.code, c.code) << r.err;
    EXPECT_NE(r.err.find(c.err_contains), std::string::npos) << r.err;
  }
}

// Two threads or three: the same program on stdout, the same error where a run stops.
TEST(Cli, ThreadsGiveTheSameOutput) {
  const std::vector<std::string> post{"--post", "../machines/fanuc/fanuc.gpp", "--prp", "../machines/fanuc/fanuc.prp", "-q"};
  for (const std::string job : {"../docs/examples/sample-job.trace", "postproc/cli/data/bad-number.trace"}) {
    std::vector<test_support::CliRun> runs;
    for (const std::string threads : {"2", "3"}) {
      std::vector<std::string> args{"run", job, "--threads", threads};
      args.insert(args.end(), post.begin(), post.end());
      runs.push_back(run(args));
    }
    EXPECT_EQ(runs[1].code, runs[0].code) << job;
    EXPECT_EQ(runs[1].out, runs[0].out) << job;
    EXPECT_EQ(runs[1].err, runs[0].err) << job;
    EXPECT_FALSE(runs[0].out.empty() && runs[0].err.empty()) << job;
  }
}

// `check` prints its findings on stdout and exits 1 when a file cannot be read.
TEST(Cli, CheckOfMissingFiles) {
  auto r = run({"check", "no.gpp"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.out, "no.gpp:1:1: error 399: Can't open file 'no.gpp'\nno.gpp: 1 error(s)\n");
}

// A copy of `from`, each edit's text inserted before the last occurrence of its mark, written into
// `dir` as `name`.
struct Edit {
  std::string mark, text;
};
std::string edited_copy(const std::filesystem::path& dir, const std::string& from, const std::vector<Edit>& edits,
                        const std::string& name) {
  std::string content = test_support::slurp(from);
  for (const auto& e : edits) {
    const auto at = content.rfind(e.mark);
    EXPECT_NE(at, std::string::npos) << from << ": " << e.mark;
    if (at != std::string::npos) content.insert(at, e.text);
  }
  const auto path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// Every subcommand that loads a machine file prints its warnings, PRP and VMID alike, once, although
// the engine loads the file for both unit systems and the filters run many times: the posting ones
// on stderr before they post, `check` on stdout among its findings.
TEST(Cli, MachineFileWarningsArePrintedOnceByEverySubcommand) {
  const auto dir = std::filesystem::temp_directory_path() / "postproc-cli-machine-warnings";
  std::filesystem::create_directories(dir);
  const std::string fanuc = "../machines/fanuc/fanuc.gpp", piko = "../machines/pikocnc/pikocnc.gpp";
  const std::string job = "golden/fanuc-sample/job.trace", helix = "../docs/examples/planes-helix.trace";
  const Edit spare_key{"endp", "spare_key = 1\n"};
  const Edit cycle85{"</MillDrilCycles>", "<DrillCycle GppName=\"CYCLE85\" UseCycle=\"1\" DrillType=\"8\"/>\n"};
  const Edit coolant{"</UserDefParams>",  // the job option the PikoCNC post reads
                     "<MillParamsJobs><ParamJobs GppName=\"coolant\" ValueType=\"5\" Value=\"0\"/></MillParamsJobs>"};
  const std::string prp = edited_copy(dir, "../machines/fanuc/fanuc.prp", {spare_key}, "extra.prp");
  const std::string piko_prp = edited_copy(dir, "../machines/pikocnc/pikocnc.prp", {spare_key}, "piko-extra.prp");
  const std::string vmid = edited_copy(dir, "golden/vmid-fanuc/fanuc.vmid", {cycle85}, "extra.vmid");
  const std::string piko_vmid = edited_copy(dir, "golden/vmid-fanuc/fanuc.vmid", {cycle85, coolant}, "piko.vmid");
  const std::string unknown_key = "warning: unknown key `spare_key`: kept as text for the post";
  const std::string drill_type =
      ":40:55: warning: DrillType=\"8\" of `CYCLE85`: expected 0 to 6; the cycle has no base type (None)";
  struct Case {
    std::vector<std::string> args;
    std::string file;     // the machine file the warning names
    std::string warning;  // on a line that starts with `file:`
    bool on_stdout;
  } cases[] = {
      {{"run", "--post", fanuc, "--prp", prp, job}, prp, unknown_key, false},
      {{"test", "--post", fanuc, "--prp", prp, "--expect", "golden/fanuc-sample/", job}, prp, unknown_key, false},
      {{"explain", "--post", fanuc, "--prp", prp, job}, prp, unknown_key, false},
      {{"verify", "--post", piko, "--prp", piko_prp, helix}, piko_prp, unknown_key, false},
      {{"check", piko, piko_prp}, piko_prp, unknown_key, true},
      {{"run", "--post", fanuc, "--prp", vmid, job}, vmid, drill_type, false},
      {{"test", "--post", fanuc, "--prp", vmid, "--expect", "golden/fanuc-sample/", job}, vmid, drill_type, false},
      {{"explain", "--post", fanuc, "--prp", vmid, job}, vmid, drill_type, false},
      {{"verify", "--post", piko, "--prp", piko_vmid, helix}, piko_vmid, drill_type, false},
      {{"check", "--prp", vmid, fanuc}, vmid, drill_type, true},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args[0] + " " + c.file);
    auto r = run(c.args);
    EXPECT_EQ(r.code, 0) << r.err << r.out;
    const std::string& printed = c.on_stdout ? r.out : r.err;
    const auto first = printed.find(c.warning);
    ASSERT_NE(first, std::string::npos) << printed;
    EXPECT_EQ(printed.find(c.warning, first + 1), std::string::npos) << printed;
    const auto line = printed.rfind('\n', first) + 1;  // npos + 1: the first line
    EXPECT_EQ(printed.compare(line, c.file.size() + 1, c.file + ":"), 0) << printed;
    EXPECT_EQ((c.on_stdout ? r.err : r.out).find("warning:"), std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

TEST(Cli, HelpListsCommandsAndOptions) {
  EXPECT_NE(run({"--help"}).out.find("read"), std::string::npos);
  EXPECT_NE(run({"read", "--help"}).out.find("--summary"), std::string::npos);
}

TEST(Cli, ReadPrintsCanonicalFormThatReadsBackTheSame) {
  auto first = run({"read", "golden/solidcam-fanuc/toolpath.trace"});
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_EQ(first.out.rfind("(1)@start_of_file   ==> program_number:5000", 0), 0u);
  std::size_t headers = 0;
  for (std::size_t p = 0; (p = first.out.find("\n(1)@", p)) != std::string::npos; ++p) ++headers;
  EXPECT_EQ(headers + 1, 210u);
}

TEST(Cli, ReadSummaryCountsCommands) {
  auto r = run({"read", "--summary", "golden/solidcam-fanuc/toolpath.trace"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("210 commands (210 stream commands)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("@drill_point                   4"), std::string::npos) << r.out;
}

}  // namespace
