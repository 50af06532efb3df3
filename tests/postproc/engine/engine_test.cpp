// The engine on small posts: parameters and change flags, command names, skipped commands,
// output directives, errors naming the command, and output left untouched by a failed run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "postproc/engine/engine.hpp"
#include "toolpath/trace_reader.hpp"

namespace {

namespace fs = std::filesystem;

class EngineTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("postproc-engine-test-" + std::to_string(::getpid()) + "-" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }

  // Posts `trace` with `post`; returns the main program (stream output) or throws.
  std::string post(const std::string& gpp, const std::string& trace, const std::string& prp = {},
                   std::optional<prp::Units> units = {}) {
    std::ofstream(dir / "p.gpp") << gpp;
    postproc::EngineOptions engine_options;
    engine_options.post = (dir / "p.gpp").string();
    if (!prp.empty()) {
      std::ofstream(dir / "p.prp") << prp;
      engine_options.prp = (dir / "p.prp").string();
    }
    engine_options.units = units;
    postproc::Engine engine(engine_options);
    std::istringstream in(trace);
    toolpath::TraceReader reader(in, "job.trace");
    postproc::OutputFiles files(dir, postproc::OutputFiles::LineEnd::LF, true);
    postproc::RunOptions options;
    options.input_name = "job.trace";
    options.warnings = &warnings;
    engine.run(reader, files, options);
    std::ostringstream out;
    files.commit_to(out);
    return out.str();
  }
  std::ostringstream warnings;  // the stream warnings of post()

  fs::path dir;
};

TEST_F(EngineTest, ParametersChangeFlagsAndCommandNames) {
  const std::string gpp =
      "@init_post\n  xpos_f = '5.3'\n  ypos_f = '5.3'\nendp\n"
      "@line\n  {nl, prev_command, ' ', current_command, ' ', next_command, [' X'xpos], [' Y'ypos]}\nendp\n";
  const std::string trace =
      "@start_of_file\n"
      "@line\nxpos : 1\nypos : 2\nzpos : 0\nfeed : 100\n"
      "@line\nxpos : 1\nypos : 3\n"
      "@line\nxpos : 1T\nypos : 4F\n"
      "@tmatrix\n"
      "@line\nxpos : 5\nypos : 4\n";
  EXPECT_EQ(post(gpp, trace),
            "\n@start_of_file @line @line X1. Y2.\n"
            "@line @line @line Y3.\n"
            "@line @line @tmatrix X1.\n"
            "@tmatrix @line  X5.");
}

// Variables the post never reads are left unassigned (ParameterBinding, Interpreter::unread_type),
// which must not show: a value that would not convert is still an error of the job, the command
// names still reach a post that reads only one of them, and the output is the same as a post that
// reads everything.
TEST_F(EngineTest, UnreadVariablesChangeNothingButSpeed) {
  const std::string declares_foo = "@init_post\n  global numeric foo\nendp\n";
  try {
    post(declares_foo, "@start_of_file\nfoo : 'abc'\n");
    ADD_FAILURE() << "no error";
  } catch (const toolpath::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("job.trace:2:7: parameter `foo` of @start_of_file: error 386"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(post(declares_foo + "@start_of_file\n  {nl, 'ok'}\nendp\n", "@start_of_file\nfoo : 2\n"), "\nok");
  const std::string lines = "@start_of_file\n@line\nxpos : 1\nypos : 0\nzpos : 0\nfeed : 100\n"
                            "@line\nxpos : 2\nypos : 0\nzpos : 0\nfeed : 100\n";
  EXPECT_EQ(post("@line\n  {nl, next_command, [' X'xpos]}\nendp\n", lines), "\n@line X1\n X2");
  EXPECT_EQ(post("@line\n  {nl, [' F'feed], ' ', prev_command}\nendp\n", lines),
            "\n F100 @start_of_file\n @line");
}

// A parameter reaches the variable of its name whatever its spelling and position: catalogue names
// are bound by their interned key, other names by their position in the command, and both bindings
// follow a command whose parameters come in another order. Enumeration words are compared without case.
TEST_F(EngineTest, ParametersBindByNameWhateverTheirSpellingAndOrder) {
  const std::string gpp =
      "@init_post\n  xpos_f = '5.3'\n  ypos_f = '5.3'\nendp\n"
      "@line\n  {nl, xpos, ' ', ypos, ' ', extra_a, ' ', extra_b}\n"
      "  if side eq COMP_LEFT\n    {' L'}\n  else\n    {' R'}\n  endif\nendp\n";
  const std::string trace =
      "@line\nxpos : 1\nypos : 2\nzpos : 0\nfeed : 100\nextra_a : 7\nextra_b : 8\nside : COMP_LEFT\n"
      "@line\nYPOS : 3\nXpos : 4\nextra_b : 9\nextra_a : 10\nside : comp_right\n"
      "@line\nextra_a : 11\nside : comp_left\nxpos : 5\nextra_b : 12\nypos : 6\n"
      "@line\nxpos : 5\nypos : 6\nEXTRA_A : 13\nextra_b : 14\nside : COMP_RIGHT\n";
  EXPECT_EQ(post(gpp, trace),
            "\n1. 2. 7 8 L\n"
            "4. 3. 10 9 R\n"
            "5. 6. 11 12 L\n"
            "5. 6. 13 14 R");
}

// The PRP half follows the job's `inch_system`, read from @start_of_file before the filters run;
// an explicit unit choice overrides it. dflt_start/dflt_end fill the positions the job leaves open.
TEST_F(EngineTest, PrpHalfFollowsTheJobsUnitSystem) {
  const std::string prp =
      "@pre_processor\n"
      "dflt_start = 0 200 100, 0 7.8740 3.9371\n"
      "dflt_end = 10 20 30, 0.3937 0.7874 1.1811\n"
      "endp\n";
  const std::string gpp =
      "@init_post\n  xpos_f = '5.4'\n  ypos_f = '5.4'\n  zpos_f = '5.4'\nendp\n"
      "@start_program\n  {nl, 'S X', xpos, ' Y', ypos, ' Z', zpos}\nendp\n"
      "@end_program\n  {nl, 'E X', xpos, ' Y', ypos, ' Z', zpos}\nendp\n";
  auto job = [](const char* inch_system) {
    return std::string("@start_of_file\n") + inch_system + "@start_program\n@end_program\n";
  };
  const std::string metric = "\nS X0. Y200. Z100.\nE X10. Y20. Z30.";
  const std::string inch = "\nS X0. Y7.874 Z3.9371\nE X0.3937 Y0.7874 Z1.1811";
  struct Case {
    const char* inch_system;
    std::optional<prp::Units> units;
    std::string expected;
  };
  for (const Case& c : {Case{"inch_system : TRUE\n", {}, inch}, Case{"inch_system : FALSE\n", {}, metric},
                        Case{"", {}, metric}, Case{"inch_system : TRUE\n", prp::Units::Metric, metric},
                        Case{"inch_system : FALSE\n", prp::Units::Inch, inch}})
    EXPECT_EQ(post(gpp, job(c.inch_system), prp, c.units), c.expected) << c.inch_system;
}

// print_file_size = 1: every `$$file_size$$` becomes the final size of its file in bytes, the size
// with the numbers written in (so the digit count is part of the size).
TEST_F(EngineTest, FileSizePlaceholderIsReplacedWhenAsked) {
  const std::string trace = "@start_of_file\n@end_of_file\n";
  struct Case {
    std::string init, start, expected;
  };
  for (const Case& c : {
           Case{"  print_file_size = 1\n", "  {nl, '(SIZE $$file_size$$)'}\n  {nl, 'M30'}\n", "\n(SIZE 14)\nM30"},
           Case{"  print_file_size = 1\n", "  {nl, '$$file_size$$ $$file_size$$'}\n", "\n4 4"},
           Case{"  print_file_size = 1\n", "  {nl, 'no placeholder'}\n", "\nno placeholder"},
           Case{"", "  {nl, '(SIZE $$file_size$$)'}\n", "\n(SIZE $$file_size$$)"},
       })
    EXPECT_EQ(post("@init_post\n  numeric_def_f = '5.3'\n" + c.init + "endp\n@start_of_file\n" + c.start + "endp\n", trace),
              c.expected)
        << c.start;
}

TEST_F(EngineTest, DirectivesSplitTheOutput) {
  const std::string gpp =
      "@start_of_file\n  {'%'}\nendp\n"
      "@proc\n  {nl, '!!open file=O', label, '.SPF!!'}\n  {nl, 'O', label}\nendp\n"
      "@end_proc\n  {nl, 'M99'}\n  {nl, '!! close file = O', label, '.SPF !!'}\nendp\n"
      "@end_of_file\n  {nl, '!!copy file=O1.SPF!!'}\n  {nl, 'M30'}\nendp\n";
  const std::string trace =
      "@start_of_file\ng_file_name : 'MAIN.NC'\n"
      "@proc\nlabel : 1\n@end_proc\n@proc\nlabel : 2\n@end_proc\n@proc\nlabel : 1\n@end_proc\n"
      "@end_of_file\n";
  EXPECT_EQ(post(gpp, trace),
            "==> MAIN.NC <==\n%\nO1\nM99\nO1\nM99\nM30\n"
            "==> O1.SPF <==\nO1\nM99\nO1\nM99\n\n"
            "==> O2.SPF <==\nO2\nM99\n");
}

// What the PRP's filters find wrong with a command points at its header in the trace: an error
// stops the run, a warning goes to the run's warnings.
// A real trace's job values reach the post as SolidCAM gives them (docs/parity.md): user parameter
// lines override the machine file's values, `on` is 1, the first drill cycle of the machine is 0,
// and `{nb}` alone keeps the blank after its number.
TEST_F(EngineTest, SolidCamTraceValuesReachThePost) {
  const std::string vmid =
      "<Machine><UserDefParams Name=\"\" Ver=\"2\"><MachineParams>"
      "<Param GppName=\"bToolPreselect\" ValueType=\"1\" Value=\"0\"/>"
      "<Param GppName=\"sWCM_MSG\" ValueType=\"2\" Value=\"from the machine\"/>"
      "<Param GppName=\"iM8_Iterations\" ValueType=\"4\" Value=\"\" DefaultValue=\"3.000000\"/>"
      "</MachineParams><MillParamsJobs><Param GppName=\"b832type\" ValueType=\"5\" Value=\"0\"/></MillParamsJobs>"
      "</UserDefParams><MillDrilCycles><DrillCycle GppName=\"CYCLE81\" DrillType=\"0\"/>"
      "<DrillCycle GppName=\"CYCLE83\" DrillType=\"2\"/></MillDrilCycles></Machine>";
  const std::string gpp =
      "@init_post\n  blknum_gen = TRUE\n  blknum = 10\n  blknum_delta = 10\n  integer_def_f = '1/2.0(p)'\nendp\n"
      "@start_of_file\n  {nb, 'PRESELECT ', bToolPreselect, ' ', sWCM_MSG, ' ', iM8_Iterations}\nendp\n"
      "@start_of_job\n  {nb, 'CYCLE832 ', b832type}\n  if flood_coolant eq 1\n    {nb, 'M', 8}\n  endif\n"
      "  if mist_coolant eq 0 or mist_coolant eq 2\n    {nb, 'M', 9}\n  endif\n  {nb}\nendp\n"
      "@drill\n  if drill_type eq CYCLE81\n    {nb, 'CYCLE81 G', 0}\n  endif\nendp\n";
  const std::string trace =
      "(1)@start_of_file   ==> program_number:1000 g_file_name:'P.MPF' \n"
      "                    ..> iWorkOffset_Method : 0  bToolPreselect : 1  sWCM_MSG : Note: Ask your supervisor!  \n"
      "(1)@start_of_job    ==> job_name:'D-drill' \n"
      "                    ..> b832type : 1  sStopMessage :   iM1 : 0  \n"
      "                    ..> flood_coolant:on mist_coolant:no_action \n"
      "(1)@drill           ==> drill_depth:3.573 \n"
      "                    ..> xpos:-112.7T ypos:-14.48T zpos:80.0T feed:132.6291T \n"
      "                    ..> drill_type:0 d_drill_type:D_Drilling drill_cycle_name:'CYCLE81' \n"
      "(1)@end_drill       ==> no parameters\n"
      "(1)@end_of_file     ==> no parameters\n";
  EXPECT_EQ(post(gpp, trace, vmid),
            "\nN10 PRESELECT 1 Note: Ask your supervisor! 3\n"
            "N20 CYCLE832 1\nN30 M8\nN40 M9\nN50 \nN60 CYCLE81 G0");
}

// A post writer's mistakes are not silent (issue 21): a motion command without a procedure stops the
// run, naming the misspelled procedure the post defines instead; another command kind without one
// is a warning at its first command, unless it only informs or SolidCAM's trace shows its own post
// had none either (depth 0).
TEST_F(EngineTest, CommandsWithoutAProcedureAreNamed) {
  const std::string job = "@def_tool\ntool_number : 1\n@def_tool\ntool_number : 2\n@rapid_move\nxpos : 0\nypos : 0\nzpos : 5\n"
                          "@delay\ndwell_time : 2\n@delay\ndwell_time : 3\n";
  try {
    post("@rapid_mvoe\n  {nl, 'G0'}\nendp\n", job);
    ADD_FAILURE() << "no error";
  } catch (const postproc::RunError& e) {
    EXPECT_EQ(std::string(e.what()),
              "job.trace:5:1: command #2 @rapid_move: the post has no @rapid_move procedure, so these moves would be "
              "missing from the NC program (the post defines @rapid_mvoe, which no command has and nothing calls: a "
              "misspelling?)");
  }
  EXPECT_EQ(post("@rapid_move\n  {nl, 'G0'}\nendp\n", job), "\nG0");
  EXPECT_EQ(warnings.str(), "job.trace:9:1: warning: @delay: the post has no procedure for it, so its 2 commands were not posted\n");
  warnings.str("");
  EXPECT_EQ(post("@rapid_move\nendp\n@dealy\nendp\n", "(1)@rapid_move      ==> xpos:0 ypos:0 zpos:5\n(1)@delay           ==> dwell_time:2\n"
                 "(0)@tool_path_info  ==> tool_path_type:'start_approach'\n"), "");
  EXPECT_EQ(warnings.str(), "job.trace:2:1: warning: @delay: the post has no procedure for it, so this command was not "
                            "posted (the post defines @dealy, which no command has and nothing calls: a misspelling?)\n");
}

// gen_procs = Y with a post that has neither @proc nor @call_proc would put every job after M30.
TEST_F(EngineTest, ProceduresWithoutCallsAreRefused) {
  const std::string gpp = "@rapid_move\nendp\n@line\n  {nl, 'G1'}\nendp\n@end_of_file\n  {nl, 'M30'}\nendp\n";
  const std::string job = "@start_of_file\n@start_of_job\n@line\nxpos : 1\nypos : 0\nzpos : 0\nfeed : 100\n@end_of_job\n@end_of_file\n";
  try {
    post(gpp, job, "@pre_processor\n  gen_procs = Y\nendp\n");
    ADD_FAILURE() << "no error";
  } catch (const postproc::RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("p.prp: the PRP says gen_procs = Y"), std::string::npos) << what;
    EXPECT_NE(what.find("neither @proc nor @call_proc"), std::string::npos) << what;
  }
  EXPECT_EQ(post(gpp, job, "@pre_processor\n  gen_procs = N\nendp\n"), "\nG1\nM30");
}

TEST_F(EngineTest, FilterErrorsAndWarningsNameTheTraceLine) {
  const std::string rapid = "(1)@rapid_move      ==> xpos:0 ypos:0 zpos:5\n";
  try {
    post("@rapid_move\nendp\n@arc\n  {nl, 'arc'}\nendp\n",
         rapid + "(1)@arc             ==> xpos:1 ypos:1 zpos:0 feed:100 arc_direction:cw arc_plane:qq xcenter:0 ycenter:1\n",
         "@pre_processor\n  arc_quadrants = Y\nendp\n");
    ADD_FAILURE() << "no error";
  } catch (const toolpath::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "job.trace:2:1: command #1 @arc: arc_plane `qq` is none of XY, YZ, ZX");
  }
  EXPECT_EQ(post("@rapid_move\nendp\n@loop\nendp\n@end_loop\nendp\n", rapid + "(1)@loop            ==> label:1 loop_count:2\n(1)@end_loop\n", "@pre_processor\n  loop_exist = N\nendp\n"), "");
  EXPECT_EQ(warnings.str(), "job.trace:2:1: warning: command #1 @loop: @loop although the PRP says loop_exist = N\n");
}

TEST_F(EngineTest, ErrorsNameTheCommandAndLeaveOldFilesAlone) {
  std::ofstream(dir / "OUT.NC") << "old\n";
  std::ofstream(dir / "p.gpp") << "@line\n  {nl, 'x'}\n  gcode = 1 / 0\nendp\n@rapid_move\nendp\n";
  postproc::EngineOptions engine_options;
  engine_options.post = (dir / "p.gpp").string();
  postproc::Engine engine(engine_options);
  std::istringstream in("@start_of_file\ng_file_name : 'OUT.NC'\n@rapid_move\nxpos : 0\nypos : 0\nzpos : 5\n"
                         "@line\nxpos : 0\nypos : 0\nzpos : 0\nfeed : 100\n");
  toolpath::TraceReader reader(in, "job.trace");
  postproc::OutputFiles files(dir);
  postproc::RunOptions options;
  options.input_name = "job.trace";
  options.main_path = [&](const std::string& name) { return dir / name; };
  try {
    engine.run(reader, files, options);
    ADD_FAILURE() << "no error";
  } catch (const postproc::RunError& e) {
    EXPECT_EQ(std::string(e.what()), "job.trace:7:1: command #2 @line: " + (dir / "p.gpp").string() +
                                         ":3:13: error 407: Zero divide");
  }
  std::ifstream old(dir / "OUT.NC");
  std::string first;
  std::getline(old, first);
  EXPECT_EQ(first, "old");
}

}  // namespace

// A lathe cycle leaves the tool at its start point or at its last point, as the PRP's retreat
// flags say; the next move then writes the axes that really move (docs/engine.md, "Turning
// cycles"). The geometry, when it follows in @turn_proc .. @turn_endproc, runs first.
TEST_F(EngineTest, LatheCyclesLeaveTheToolWhereTheRetreatFlagsSay) {
  const std::string gpp =
      "@init_post\n  xpos_f = '5.3'\n  zpos_f = '5.3'\nendp\n"
      "@rapid_move\n  {nl, 'G0', [' X'xpos], [' Z'zpos]}\nendp\n"
      "@line\n  {nl, 'G1', [' X'xpos], [' Z'zpos]}\nendp\n"
      "@turning\n  {nl, 'CYCLE'}\nendp\n"
      "@turn_proc\nendp\n@turn_endproc\nendp\n";
  const std::string start = "@start_of_file\n@rapid_move\nxpos : 21\nypos : 0\nzpos : 2\n";
  const std::string geometry =
      "@turn_proc\nlabel : 1\n@line\nxpos : 6\nypos : 0\nzpos : 2\nfeed : 0.2\n@line\nxpos : 20\nypos : 0\nzpos : -30\n"
      "@turn_endproc\nlabel : 1\n";
  const std::string away = "@rapid_move\nxpos : 20\nypos : 0\nzpos : 5\n";
  auto cycle = [](const char* work, const char* finish) {
    return std::string("@turning\nwork_type : ") + work + "\nfinish : " + finish +
           "\nsemi_finish : FALSE\nlast_pos_x : 20\nlast_pos_z : -30\nlabel : 1\n";
  };
  struct Case {
    const char* what;
    const char* flags;  // PRP lines
    std::string job;
    const char* after;  // the line the move away writes
  } cases[] = {
      {"rough, back to the start", "rough_retreat = Y\n", cycle("ROUGH", "FALSE") + geometry + away, "G0 X20. Z5."},
      {"rough, stays at the end", "rough_retreat = N\n", cycle("ROUGH", "FALSE") + geometry + away, "G0 Z5."},
      {"finish flag decides a PROFILE cycle", "rough_retreat = N\nfinish_retreat = Y\n",
       cycle("PROFILE", "TRUE") + geometry + away, "G0 X20. Z5."},
      {"a combined cycle ends with its finish", "rough_retreat = Y\nfinish_retreat = N\n",
       cycle("ROUGH", "TRUE") + geometry + away, "G0 Z5."},
      // No geometry in the stream (turn_common_proc): the start point, or the cycle's last point.
      {"shared geometry, back to the start", "finish_retreat = Y\n", cycle("PROFILE", "TRUE") + away, "G0 X20. Z5."},
      {"shared geometry, stays at the end", "finish_retreat = N\n", cycle("PROFILE", "TRUE") + away, "G0 Z5."},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    const std::string out = post(gpp, start + c.job, std::string("@pre_processor\n") + c.flags + "endp\n");
    EXPECT_EQ(out.substr(out.rfind('\n') + 1), c.after) << out;
  }
}

// A system array may leave out trailing indices of 1, in the post and in the trace, because real
// wire posts read ang_prms both ways (docs/gppl-language.md, "Arrays"); a post's own arrays may not.
TEST_F(EngineTest, SystemArraysMayLeaveOutTrailingIndicesOfOne) {
  const std::string gpp =
      "@wc_line\n  {nl, ang_prms<<1>>, ' ', ang_prms<<1,1>>, ' ', ang_prms<<2>>, ' ', ang_prms<<2,2>>}\nendp\n";
  const std::string trace =
      "@start_of_file\n@wc_line\nang_prms<<1,1>> : 2.5\nang_prms<<2>> : 1.5\nang_prms<<2,2>> : 0.5\n";
  EXPECT_EQ(post(gpp, trace), "\n2.5 2.5 1.5 0.5");
  try {
    post("@start_of_file\n  global numeric mine<<4,2>>\n  {nl, mine<<1>>}\nendp\n", "@start_of_file\n");
    ADD_FAILURE() << "a post's own array took one index for two";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("array 'mine' has 2 dimension(s)"), std::string::npos) << e.what();
  }
}
