// `postproc new-post`: each template is a shipped post written out as it is in machines/, its
// machine file renamed with the post, and what it writes passes `check` and posts its sample job
// (the milling sample job, or the turning, mill-turn or wire job; GRBL's is the one it can cut).
// Runs from tests/ (the suite's working directory).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "machines/templates/post_templates.hpp"
#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;

class NewPost : public ::testing::Test {
protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("postproc-new-post-" + std::to_string(::getpid()) + "-" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(NewPost, EveryTemplateIsTheShippedPostAndRunsOnTheSampleJob) {
  ASSERT_EQ(machines::post_templates().size(), 7u);
  for (const auto& t : machines::post_templates()) {
    const std::string name(t.name);
    SCOPED_TRACE(name);
    const auto wrote = run_cli({"new-post", "--template", name, "-o", dir.string()});
    ASSERT_EQ(wrote.code, 0) << wrote.err;
    const fs::path gpp = dir / (name + ".gpp"), prp = dir / (name + ".prp");
    EXPECT_EQ(slurp(gpp), slurp("../machines/" + name + "/" + name + ".gpp"));
    EXPECT_EQ(slurp(prp), slurp("../machines/" + name + "/" + name + ".prp"));
    const auto checked = run_cli({"check", gpp.string(), prp.string()});
    EXPECT_EQ(checked.code, 0) << checked.err;
    EXPECT_EQ(checked.err.find("warning"), std::string::npos) << checked.err;
    const std::string job = "../docs/examples/" + std::string(t.sample_job) + ".trace";
    EXPECT_NE(wrote.out.find(std::string(t.sample_job) + ".trace"), std::string::npos) << wrote.out;
    const auto posted = run_cli({"run", "-q", "--post", gpp.string(), "--prp", prp.string(), job, "-o",
                                 (dir / ("nc-" + name)).string() + "/"});
    EXPECT_EQ(posted.code, 0) << posted.err;
    EXPECT_EQ(posted.err, "");
  }
}

TEST_F(NewPost, GrblRefusesWhatTheControlCannotDoAndSaysWhy) {
  ASSERT_EQ(run_cli({"new-post", "-t", "grbl", "-o", dir.string()}).code, 0);
  const std::string post = (dir / "grbl.gpp").string(), prp = (dir / "grbl.prp").string();
  struct Case {
    const char* job;
    const char* says;
  } cases[] = {
      {"sample-job", "compensation COMP_LEFT on a machine without it (comp_exist = N)"},
      {"subroutine-loops", "GRBL has no subprograms"},
      {"drill-cycles", "cannot be written as plain moves"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli({"run", "-q", "--post", post, "--prp", prp,
                            std::string("../docs/examples/") + c.job + ".trace", "-o", (dir / "nc").string() + "/"});
    EXPECT_EQ(r.code, 1) << c.job;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
  }
}

TEST_F(NewPost, TheNameNamesTheFilesAndThePostInTheMachineFile) {
  const auto r = run_cli({"new-post", "-t", "sinumerik", "--name", "dmu50", "-o", dir.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("postproc check " + (dir / "dmu50.gpp").string()), std::string::npos) << r.out;
  const std::string prp = slurp(dir / "dmu50.prp");
  EXPECT_NE(prp.find("\npost_processor = dmu50\n"), std::string::npos);
  EXPECT_NE(prp.find("\ndoc_processor = dmu50\n"), std::string::npos);
  EXPECT_EQ(prp.find("= sinumerik"), std::string::npos);
  EXPECT_EQ(slurp(dir / "dmu50.gpp"), slurp("../machines/sinumerik/sinumerik.gpp"));
}

TEST_F(NewPost, NeverOverwritesWithoutForce) {
  ASSERT_EQ(run_cli({"new-post", "-t", "fanuc", "-o", dir.string()}).code, 0);
  std::ofstream(dir / "fanuc.gpp") << "; my edits\n";
  const auto again = run_cli({"new-post", "-t", "fanuc", "-o", dir.string()});
  EXPECT_EQ(again.code, 1);
  EXPECT_NE(again.err.find((dir / "fanuc.gpp").string() + ": already exists; --force replaces it"), std::string::npos)
      << again.err;
  EXPECT_EQ(slurp(dir / "fanuc.gpp"), "; my edits\n");
  ASSERT_EQ(run_cli({"new-post", "-t", "fanuc", "-o", dir.string(), "--force"}).code, 0);
  EXPECT_EQ(slurp(dir / "fanuc.gpp"), slurp("../machines/fanuc/fanuc.gpp"));
  for (const auto& e : fs::directory_iterator(dir)) EXPECT_NE(e.path().extension(), ".tmp");
}

TEST_F(NewPost, WrongCommandLinesListTheTemplates) {
  struct Case {
    std::vector<std::string> args;
    const char* says;
  } cases[] = {
      {{"new-post"}, "--template NAME is required"},
      {{"new-post", "-t", "haas"}, "no template 'haas'"},
      {{"new-post", "-t", "fanuc", "--name", "my post"}, "--name takes letters, digits"},
      {{"new-post", "-t", "fanuc", "extra"}, "unexpected argument extra"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.code, 2) << c.says;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    if (c.args.size() < 4) {  // a missing or unknown template: the list says what there is
      EXPECT_NE(r.err.find("sinumerik"), std::string::npos) << r.err;
    }
  }
  const auto listed = run_cli({"new-post", "--list"});
  EXPECT_EQ(listed.code, 0);
  for (const auto& t : machines::post_templates()) EXPECT_NE(listed.out.find(std::string(t.name)), std::string::npos);
}

}  // namespace
