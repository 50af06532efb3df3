// The example FANUC post (tests/gppl/data/fanuc.gpp, from the GPPTool manual) parses and its
// procedures write the exact lines GPPL semantics give for hand-set command parameters.
#include <gtest/gtest.h>

#include <filesystem>

#include "support.hpp"

using namespace gppl_test;

namespace {

std::string read(const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) throw std::runtime_error("cannot open " + path);
  std::string text;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
  std::fclose(f);
  return text;
}

// The enumeration constants the engine declares (read-only integers).
gppl::CompileOptions fanuc_options() {
  gppl::CompileOptions options;
  for (const char* name : {"CW", "CCW", "XY", "YZ", "ZX", "COMP_LEFT", "COMP_RIGHT", "COMP_OFF", "MIRROR_OFF",
                           "MIRROR_X", "MIRROR_Y", "MIRROR_XY", "drilling", "f_drill", "peck", "tapping", "boring",
                           "r_boring", "f_boring"})
    options.host_variables.push_back({name, gppl::Type::Integer, true, {}});
  return options;
}

class Fanuc : public testing::Test {
protected:
  Fanuc() : post(read("gppl/data/fanuc.gpp"), fanuc_options(), "fanuc.gpp") {
    int value = 1;
    for (const auto& v : fanuc_options().host_variables) post.set(v.name, integer(value++));
    EXPECT_EQ(post.run->start(), gppl::RunResult::Normal);
  }
  // Runs the command procedure and returns the lines written since the last check.
  std::string lines_of(const std::string& procedure) {
    post.call(procedure);
    return take();
  }
  // A motion command carries its whole position and feed (the engine assigns them all).
  void at(double x, double y, double z, double feed = 0.) {
    post.set("xpos", numeric(x));
    post.set("ypos", numeric(y));
    post.set("zpos", numeric(z));
    post.set("feed", numeric(feed));
  }
  std::string take() {
    std::string all;
    for (std::size_t i = seen; i < post.out.lines.size(); ++i) all += post.out.lines[i] + "\n";
    seen = post.out.lines.size();
    return all;
  }
  Post post;
  std::size_t seen = 0;
};

TEST_F(Fanuc, EveryProcedureIsThere) {
  for (const char* name :
       {"@init_post", "@start_of_file", "@start_program", "@end_program", "@end_of_file", "@relative_mode",
        "@absolute_mode", "@machine_plane", "@call_proc", "@proc", "@end_proc", "@loop", "@end_loop", "@def_tool",
        "@rapid_move", "@line", "@arc", "@compensation", "@delay", "@change_ref_point", "@home_number", "@rotate",
        "@fourth_axis", "@change_tool", "@message", "@drill", "@drill_point", "@mirror", "@end_drill",
        "@halt_program", "@start_of_job", "@end_of_job", "@call_simple_proc", "@start_tool", "@stop_tool"})
    EXPECT_TRUE(post.run->find_procedure(name).has_value()) << name;
  EXPECT_FALSE(post.run->find_procedure("@turning").has_value());
}

TEST_F(Fanuc, ProgramHeaderAndToolTable) {
  post.set("program_number", integer(5000));
  post.set("g_file_name", string("OUT"));
  post.set("rotate_used", logical(false));
  post.set("mirror_used", logical(false));
  post.set("first_proc_number", integer(1));
  post.set("last_proc_number", integer(5));
  post.call("@start_of_file");
  for (auto [number, offset] : {std::pair{1, 6.35}, {14, 5.}, {12, 6.}}) {
    post.set("tool_number", integer(number));
    post.set("tool_offset", numeric(offset));
    post.call("@def_tool");
  }
  post.set("machine_plane", post.get("XY"));
  post.call("@machine_plane");
  post.set("home_number", integer(1));
  post.call("@start_program");
  post.run->finish();
  EXPECT_EQ(take(),
            "%\nO5000 (OUT)\n(SUBROUTINES: O1 .. O5)\n(G10 L12 P51 R6.35)\n(G10 L12 P64 R5.)\n(G10 L12 P62 R6.)\n"
            "G17\nG80 G49 G40\nG54\n");
}

TEST_F(Fanuc, ToolChangeAndJobCall) {
  post.set("first_user_proc", integer(5));
  post.set("tool_number", integer(1));
  post.set("tool_diameter", numeric(12.7));
  post.set("xnext", numeric(-16.35));
  post.set("ynext", numeric(-53.75));
  post.set("znext", numeric(50.));
  post.set("spin", numeric(3000.));
  post.call("@change_tool");
  post.set("label", integer(1));
  post.set("proc_count", integer(1));
  post.set("message", string("F-PR1-T1"));
  post.run->set_active(post.id("parm1"), false);
  post.call("@call_proc");
  post.run->finish();
  EXPECT_EQ(take(),
            "(*TOOL 1 - DIA 12.7*)\nT1\nM98 P5\nN5 G43 H1 D51 G0 X-16.35 Y-53.75 Z50. S3000 M3\nM8\n"
            "M98 P1 (F-PR1-T1)\n");
  EXPECT_EQ(post.get("blknum"), integer(10));
  EXPECT_EQ(post.get("blknum_gen"), logical(false));
}

TEST_F(Fanuc, MotionIsModal) {
  post.set("label", integer(1));
  post.call("@proc");
  at(-16.35, -53.75, 10.);
  post.call("@rapid_move");
  at(-16.35, -53.75, 2.);
  post.call("@rapid_move");
  at(-16.35, -53.75, -30., 75.);
  post.call("@line");
  at(-16.35, -37.832, -30., 250.);
  post.call("@line");
  // @arc has no {nb} in this post: the arc continues the previous block (README discrepancy 1).
  post.set("arc_direction", post.get("CW"));
  at(-8.35, -24.565, -30., 250.);
  post.set("arc_size", numeric(90.));
  post.set("radius", numeric(15.));
  post.call("@arc");
  post.set("side", post.get("COMP_LEFT"));
  post.call("@compensation");
  at(5., -24.565, -30., 250.);
  post.call("@line");
  post.run->finish();
  EXPECT_EQ(take(),
            "O1\nG0 X-16.35 Y-53.75 Z10.\n  Z2.\nG1 Z-30. F75\n  Y-37.832 F250G2 X-8.35 Y-24.565 R15.\n"
            "G41 G1 X5.\n");
}

TEST_F(Fanuc, DrillCycle) {
  at(75., -19., 10., 75.);
  post.set("drill_type", post.get("peck"));
  post.set("drill_lower_z", numeric(-30.));
  post.set("drill_upper_z", numeric(2.));
  post.set("down_step", numeric(30.));
  post.call("@drill");
  post.set("first_drill", logical(true));
  at(75., -19., 10., 75.);
  post.call("@drill_point");
  post.set("first_drill", logical(false));
  at(95., -19., 10., 75.);
  post.call("@drill_point");
  post.call("@end_drill");
  post.run->finish();
  EXPECT_EQ(take(), "G0 X75. Y-19. Z10.\nG98 G83 Z-30. R2. Q30. F75\n  X95.\nG80\n");
}

TEST_F(Fanuc, DwellLoopAndEndOfFile) {
  post.set("delay_period", numeric(2.5));
  post.call("@delay");
  post.set("loop_level", integer(1));
  post.set("loop_count", integer(3));
  post.call("@loop");
  post.call("@end_loop");
  post.set("first_user_proc", integer(5));
  post.call("@end_of_file");
  post.run->finish();
  EXPECT_EQ(take(),
            "G4 P3\n#21 = 0\nWHILE [#21 LT 3] DO 1\n#21 = #21 + 1\nEND 1\nO5\n(--------------------)\n"
            "(- CHANGE TOOL -)\n(--------------------)\nG80 G49 G40 M9\nG91 G28 Z0. M5\nG90 M1\nM6\nM99\n%\n");
}

TEST_F(Fanuc, RelativeModeContinuesNextBlock) {
  post.call("@relative_mode");
  post.set("xpos", numeric(1.));
  post.set("ypos", numeric(2.));
  post.set("zpos", numeric(3.));
  post.call("@rapid_move");
  post.call("@absolute_mode");
  post.call("@halt_program");
  post.run->finish();
  EXPECT_EQ(take(), "G91 G0 X1. Y2. Z3.\nG90  M0\n");
}

}  // namespace

namespace {

// Every post the project ships (machines/) and every golden post compiles without error.
TEST(ShippedPosts, Compile) {
  std::vector<std::filesystem::path> posts;
  for (const char* root : {"../machines", "golden"})
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
      if (entry.path().extension() == ".gpp") posts.push_back(entry.path());
  EXPECT_FALSE(posts.empty());
  for (const auto& post : posts) {
    try {
      gppl::compile_file(post.string(), {});
    } catch (const gppl::Errors& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

}  // namespace
