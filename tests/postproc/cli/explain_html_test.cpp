// `postproc explain --html`: the page, loaded in a real browser (Debian's chromium, headless). The
// page's self-test hook clicks an NC line (or a plot segment) through its own event handlers and
// records what got highlighted; the test reads that back from the DOM chromium dumps. A screenshot
// of the page with a line selected is kept as an artefact. Without chromium the browser tests are
// skipped with a message (CI installs it: .ci/run).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/synthetic_job.hpp"
#include "tests/support/cli_run.hpp"
#include "toolpath/trace_writer.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using test_support::run_cli;

// A folder per test: ctest runs the tests of this file side by side, and two of them writing the
// same page would take each other's staged file away ("cannot write file").
fs::path test_dir() {
  return fs::temp_directory_path() /
         ("postproc-explain-html-" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
}

std::string chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    const std::string probe = std::string("command -v ") + name + " >/dev/null 2>&1";
    if (std::system(probe.c_str()) == 0) return name;
  }
  return {};
}

std::string shell(const std::string& command) {
  std::string out;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return out;
  char buffer[65536];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe.get())) > 0;) out.append(buffer, n);
  return out;
}

// The page's self-test result after `hash`, from the DOM chromium dumps.
json selftest(const std::string& browser, const fs::path& page, const std::string& hash, int budget_ms = 4000) {
  const std::string dom = shell(browser + " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage "
                                          "--window-size=1400,900 --virtual-time-budget=" + std::to_string(budget_ms) +
                                " --dump-dom 'file://" + page.string() + hash + "' 2>/dev/null");
  std::smatch m;
  if (!std::regex_search(dom, m, std::regex("data-selftest=\"([^\"]*)\""))) return json();
  std::string text = m[1];
  for (const auto& [entity, c] : {std::pair<std::string, std::string>{"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}})
    for (std::size_t at = text.find(entity); at != std::string::npos; at = text.find(entity, at + 1)) text.replace(at, entity.size(), c);
  return json::parse(text, nullptr, false);
}

fs::path sample_page() {
  fs::create_directories(test_dir());
  const fs::path page = test_dir() / "sample.html";
  const auto r = run_cli({"explain", "--post", "../machines/fanuc/fanuc.gpp", "--prp", "../machines/fanuc/fanuc.prp", "-q",
                          "--html", page.string(), "../docs/examples/sample-job.trace"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "../docs/examples/sample-job.trace: wrote " + page.string() + "\n");
  return page;
}

TEST(ExplainHtml, ASelfContainedPage) {
  const std::string html = test_support::slurp(sample_page());
  EXPECT_EQ(html.rfind("<!doctype html>", 0), 0u);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);  // no script or image from the network
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_NE(html.find("\"N70 T3 M6\""), std::string::npos);
  EXPECT_NE(html.find("\"@change_tool\""), std::string::npos);
}

TEST(ExplainHtml, ClickingALineHighlightsItsSourceAndSegment) {
  const std::string browser = chromium();
  if (browser.empty()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium): the browser test needs it";
  const fs::path page = sample_page();
  // The first cut of the sample (its first @line), and the GPP line that wrote it, as the text
  // form of explain tells them.
  const auto text = run_cli({"explain", "--post", "../machines/fanuc/fanuc.gpp", "--prp", "../machines/fanuc/fanuc.prp",
                             "-q", "../docs/examples/sample-job.trace"});
  std::smatch m;
  const std::string out = text.out;
  ASSERT_TRUE(std::regex_search(out, m, std::regex("\\n *(\\d+) [^\\n]*\\| #(\\d+) @line -> \\S+ \\(fanuc\\.gpp:(\\d+)\\)")));
  const int nc = std::stoi(m[1]), command = std::stoi(m[2]), gpp = std::stoi(m[3]);
  const json line = selftest(browser, page, "#select=" + std::to_string(nc));
  ASSERT_TRUE(line.is_object()) << "no self-test result in the page's DOM";
  EXPECT_EQ(line["selected"]["line"], nc);
  EXPECT_EQ(line["selected"]["command"], command);
  EXPECT_EQ(line["ncHighlighted"], nc);
  EXPECT_EQ(line["srcHighlighted"], gpp);
  EXPECT_GE(line["selected"]["segments"].get<int>(), 1);
  // Clicking that command's segment in the plot selects its first NC line.
  const json plot = selftest(browser, page, "#plotclick=" + std::to_string(command));
  ASSERT_TRUE(plot.is_object() && plot["selected"].is_object()) << plot.dump();
  EXPECT_EQ(plot["selected"]["command"], command);
  EXPECT_EQ(plot["ncHighlighted"], nc);
  // The artefact: the page with the line selected.
  const fs::path png = test_dir() / "explain-page.png";
  fs::remove(png);
  shell(browser + " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --window-size=1400,900 "
                  "--virtual-time-budget=4000 --screenshot=" + png.string() + " 'file://" + page.string() + "#select=" +
                  std::to_string(nc) + "' 2>/dev/null");
  ASSERT_TRUE(fs::exists(png));
  EXPECT_GT(fs::file_size(png), 10000u);
  std::printf("screenshot kept: %s\n", png.string().c_str());
}

// A line written by an include file's statement shows that file in the source pane, at its line.
TEST(ExplainHtml, ALineOfAnIncludeFileShowsThatFile) {
  const std::string browser = chromium();
  if (browser.empty()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium): the browser test needs it";
  const fs::path dir = test_dir() / "include";
  fs::create_directories(dir / "lib");
  std::ofstream(dir / "p.gpp") << "@start_of_file\n  {nl, '%'}\nendp\n@rapid_move\nendp\ninc 'lib/moves.inc'\n";
  std::ofstream(dir / "lib" / "moves.inc") << "; moves\n@line\n  {nl, 'G1'}\nendp\n";
  std::ofstream(dir / "j.trace") << "@start_of_file\n@rapid_move\nxpos : 0\nypos : 0\nzpos : 5\n"
                                    "@line\nxpos : 1\nypos : 0\nzpos : 0\nfeed : 100\n";
  const fs::path page = dir / "page.html";
  const auto r = run_cli({"explain", "-q", "--post", (dir / "p.gpp").string(), "--html", page.string(), (dir / "j.trace").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  // NC line 1 is the empty line before the first block: '%' is line 2, G1 line 3.
  const json included = selftest(browser, page, "#select=3");
  ASSERT_TRUE(included.is_object()) << "no self-test result in the page's DOM";
  EXPECT_EQ(included["srcFile"], "lib/moves.inc");
  EXPECT_EQ(included["srcHighlighted"], 3);
  const json own = selftest(browser, page, "#select=2");
  ASSERT_TRUE(own.is_object());
  EXPECT_EQ(own["srcFile"], "p.gpp");
  EXPECT_EQ(own["srcHighlighted"], 2);
}

// 200 000 NC lines: the lists draw only what is in view, so the page keeps a few hundred elements.
TEST(ExplainHtml, ALongProgramStaysSmallInTheBrowser) {
  const std::string browser = chromium();
  if (browser.empty()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium): the browser test needs it";
  fs::create_directories(test_dir());
  const fs::path job = test_dir() / "long.trace", page = test_dir() / "long.html";
  {
    std::ofstream out(job, std::ios::binary);
    toolpath::TraceWriter writer(out);
    bench::SyntheticJob source(200'000);
    toolpath::Command c;
    while (source.next(c)) writer.write(c);
    writer.flush();
  }
  const auto r = run_cli({"explain", "--post", "../machines/fanuc/fanuc.gpp", "--prp", "../machines/fanuc/fanuc.prp", "-q",
                          "--html", page.string(), job.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const json result = selftest(browser, page, "#select=150000", 20000);
  ASSERT_TRUE(result.is_object()) << "no self-test result: the page did not finish loading";
  EXPECT_EQ(result["ncHighlighted"], 150000);
  EXPECT_LT(result["elements"].get<int>(), 2000);
  fs::remove(job);
}

}  // namespace
