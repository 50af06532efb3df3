// start_line / end_line through the engine: golden NC for each kind of body (block-range
// subroutine calls, G14 loops, a turning cycle's geometry, a user subroutine the post writes
// itself, placeholders in opened, copied and deleted files), the errors a post writer can meet,
// and `postproc test` comparing lines whose numbers came late.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "postproc/engine/engine.hpp"
#include "postproc/checks/regression.hpp"
#include "postproc/engine/slot_marker.hpp"
#include "toolpath/trace_reader.hpp"

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class LineNumbersTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("postproc-line-numbers-" + std::to_string(::getpid()) + "-" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }

  // Posts `trace` with the post file `gpp`; every output file on one stream (OutputFiles::commit_to).
  std::string post(const fs::path& gpp, const std::string& trace, postproc::LineObserver* observer = nullptr,
                   postproc::OutputFiles::LineEnd end = postproc::OutputFiles::LineEnd::LF) {
    postproc::EngineOptions engine_options;
    engine_options.post = gpp.string();
    postproc::Engine engine(engine_options);
    std::istringstream in(trace);
    toolpath::TraceReader reader(in, "job.trace");
    postproc::OutputFiles files(dir, end, true);
    postproc::RunOptions options;
    options.input_name = "job.trace";
    options.observer = observer;
    engine.run(reader, files, options);
    std::ostringstream out;
    files.commit_to(out);
    return out.str();
  }
  std::string post_text(const std::string& gpp, const std::string& trace) {
    std::ofstream(dir / "p.gpp") << gpp;
    return post(dir / "p.gpp", trace);
  }
  // The run's error message (the run must fail).
  std::string error(const std::string& gpp, const std::string& trace) {
    try {
      post_text(gpp, trace);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "no error";
  }

  fs::path dir;
};

const fs::path kData = "postproc/engine/data/line_numbers";

class Golden : public LineNumbersTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(Golden, MatchesExpectedNc) {
  const fs::path c = kData / GetParam();
  EXPECT_EQ(post(c / "post.gpp", read(c / "job.trace")), read(c / "expected.nc"));
}

INSTANTIATE_TEST_SUITE_P(Bodies, Golden,
                         ::testing::Values("subroutine_calls", "loop_g14", "turning_cycle", "user_subroutine",
                                           "output_files", "bare_bodies"));

TEST_F(LineNumbersTest, CrLfFilesKeepTheirPlaceholdersInPlace) {
  const fs::path c = kData / "subroutine_calls";
  std::string expected = read(c / "expected.nc");
  std::string crlf;
  for (char ch : expected) crlf += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
  EXPECT_EQ(post(c / "post.gpp", read(c / "job.trace"), nullptr, postproc::OutputFiles::LineEnd::CRLF), crlf);
}

const std::string kNumbered = "@init_post\n  blknum_gen = TRUE\nendp\n@line\n  {nb, 'X'}\nendp\n";
// A @line as a trace gives it (five lines).
const std::string kLine = "@line\nxpos : 1\nypos : 0\nzpos : 0\nfeed : 90\n";

TEST_F(LineNumbersTest, ErrorsNameTheItemTheCommandAndTheBody) {
  struct Case {
    const char* what;
    std::string gpp, trace, expected;
  };
  for (const Case& c : {
           Case{"a body without numbered blocks",
                "@call_proc\n  {nb, 'CALL ' start_line}\nendp\n@line\n  {nl, 'X'}\nendp\n",
                "@call_proc\nlabel : 4\n@proc\nlabel : 4\n" + kLine + "@end_proc\n",
                "job.trace:10:1: command #3 @end_proc: start_line at " + (dir / "p.gpp").string() +
                    ":2:16 (command #0 @call_proc): the body of subroutine 4 has no numbered blocks (is block "
                    "numbering on there?)"},
           Case{"a closed body without numbered blocks, asked for later",
                "@call_proc\n  {nb, 'CALL ' end_line}\nendp\n@line\n  {nl, 'X'}\nendp\n",
                "@proc\nlabel : 4\n" + kLine + "@end_proc\n@call_proc\nlabel : 4\n",
                "job.trace:9:1: command #3 @call_proc: " + (dir / "p.gpp").string() +
                    ":2:16: error 404: Symbol 'end_line' does not exist: the body of subroutine 4 has no numbered "
                    "blocks (is block numbering on there?)"},
           Case{"a call whose body never comes", kNumbered + "@call_proc\n  {nb, 'CALL ' end_line}\nendp\n",
                "@call_proc\nlabel : 9\n" + kLine,
                "job.trace: at the end of the run: end_line at " + (dir / "p.gpp").string() +
                    ":8:16 (command #0 @call_proc): no body of subroutine 9 followed (no @proc with label 9)"},
           Case{"a loop that never ends", kNumbered + "@loop\n  {nl, '(' start_line ')'}\nendp\n",
                "@loop\nlabel : 2\n" + kLine,
                "job.trace: at the end of the run: start_line at " + (dir / "p.gpp").string() +
                    ":8:12 (command #0 @loop): the body of loop 2 never ended (no @end_loop)"},
           Case{"a command without a body", kNumbered + "@rapid_move\n  {nb, 'N' start_line}\nendp\n",
                "@rapid_move\nxpos : 0\nypos : 0\nzpos : 5\n",
                "job.trace:1:1: command #0 @rapid_move: " + (dir / "p.gpp").string() +
                    ":8:12: error 404: Symbol 'start_line' does not exist: start_line and end_line belong to "
                    "@call_proc, @call_prms, @start_of_job, @turning, @thread, @proc, @end_proc, @turn_proc, "
                    "@turn_endproc, @loop and @end_loop (and the procedures they call)"},
           Case{"an end without a beginning", kNumbered + "@end_loop\n  {nb, 'G14 N1=' start_line}\nendp\n",
                "@end_loop\n",
                "job.trace:1:1: command #0 @end_loop: " + (dir / "p.gpp").string() +
                    ":8:18: error 404: Symbol 'start_line' does not exist: no loop is open here to end"},
       })
    EXPECT_EQ(error(c.gpp, c.trace), c.expected) << c.what;
}

TEST_F(LineNumbersTest, FailedRunLeavesNoFile) {
  std::ofstream(dir / "OUT.NC") << "old\n";
  EXPECT_NE(error("@call_proc\n  {nb, start_line}\nendp\n", "@start_of_file\ng_file_name : 'OUT.NC'\n@call_proc\nlabel : 1\n"),
            "no error");
  EXPECT_EQ(read(dir / "OUT.NC"), "old\n");
}

// `postproc test` sees each line as it is written, placeholders included, and compares it once
// its numbers are known: the first difference is still reported in the order of the lines.
TEST_F(LineNumbersTest, RegressionComparesLinesOnceTheirNumbersAreKnown) {
  const fs::path c = kData / "subroutine_calls";
  struct Feeder : postproc::LineObserver {
    postproc::RegressionComparer& comparer;
    explicit Feeder(postproc::RegressionComparer& r) : comparer(r) {}
    void on_line(const postproc::LineEvent& e) override { comparer.produced("main", e.text, e.origin); }
    void on_slot_filled(std::uint32_t slot, std::string_view text) override { comparer.filled(slot, text); }
  };
  for (const auto& [golden, report] : {
           std::pair<std::string, std::string>{read(c / "expected.nc"), ""},
           {[&] {
              std::string g = read(c / "expected.nc");
              g.replace(g.find("N1=60 N2=80"), 11, "N1=60 N2=81");  // line 3, compared late
              g.replace(g.find("N30 G1 X5."), 10, "N30 G1 X6.");    // line 5, compared at once
              return g;
            }(),
            "main:3: the output differs from the expected line\n"
            "  expected: `N10 CALL N1=60 N2=81 (SUB 1)`\n"
            "  actual:   `N10 CALL N1=60 N2=80 (SUB 1)`\n"
            "  produced by command #1 @call_proc, procedure @call_proc (p.gpp:13)\n"
            "2 differing lines in all\n"},
       }) {
    std::ofstream(dir / "golden.nc") << golden;
    postproc::RegressionComparer comparer(
        [&](const std::string&) { return postproc::expected_from_file((dir / "golden.nc").string()); }, {}, "p.gpp");
    Feeder feeder(comparer);
    post(c / "post.gpp", read(c / "job.trace"), &feeder);
    comparer.finish();
    EXPECT_EQ(comparer.report(), report);
    EXPECT_EQ(comparer.lines_compared(), 16u);  // the empty first line the break before the first block makes
  }
}

TEST(SlotMarker, RoundTrips) {
  const std::string m = postproc::slot::marker(4294967295u);
  ASSERT_EQ(m.size(), postproc::slot::kWidth);
  const std::string line = "A" + m + "B" + postproc::slot::marker(7);
  auto first = postproc::slot::find_marker(line);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->position, 1u);
  EXPECT_EQ(first->id, 4294967295u);
  EXPECT_EQ(postproc::slot::find_marker(line, 2)->id, 7u);
  EXPECT_EQ(postproc::slot::readable(line), "A{?4294967295}B{?7}");
  const std::string f = postproc::slot::filled("1234");
  EXPECT_EQ(postproc::slot::filled_text(f, 0), std::optional<std::string_view>("1234"));
  EXPECT_FALSE(postproc::slot::filled_text(m, 0));
  EXPECT_FALSE(postproc::slot::find_marker(f));
  EXPECT_TRUE(postproc::slot::fits(std::string(postproc::slot::kWidth - 2, '9')));
  EXPECT_FALSE(postproc::slot::fits(std::string(postproc::slot::kWidth - 1, '9')));
  EXPECT_FALSE(postproc::slot::fits("\x03"));
}

}  // namespace
