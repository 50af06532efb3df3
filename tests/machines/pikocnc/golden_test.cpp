// Golden folders under machines/pikocnc/golden/<case>/: `program.nc` is read back and printed in
// the canonical trace form, which must equal `expected.trace`. Optional files: `options` (machine
// configuration, one setting a line), `expected.warnings` (every diagnostic, `line:col: text`),
// `expected.error` (the program must fail with exactly this message).
// POSTPROC_UPDATE_GOLDEN=1 rewrites the expected files (review them before committing).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "machines/pikocnc/model/reader.hpp"
#include "tests/support/golden_file.hpp"
#include "toolpath/trace_writer.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = "machines/pikocnc/golden";

using test_support::slurp;

pikocnc::Axes5 axes(std::istringstream& in) {
  pikocnc::Axes5 a{};
  for (double& v : a) in >> v;
  return a;
}

pikocnc::Options parse_options(const fs::path& file) {
  pikocnc::Options o;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    if (!(words >> key) || key[0] == '#') continue;
    if (key == "dialect") {
      std::string d;
      words >> d;
      o.dialect = *pikocnc::parse_dialect(d);
    } else if (key == "mdi") {
      o.mdi = true;
    } else if (key == "tool") {  // tool N radius R offset X Y Z A B
      int n;
      std::string word;
      words >> n >> word >> o.tools[n].radius >> word;
      o.tools[n].offset = axes(words);
    } else if (key == "work_offset") {  // work_offset 55 X Y Z A B
      int g;
      words >> g;
      o.work_offsets[static_cast<std::size_t>(g - 54)] = axes(words);
    } else if (key == "park") {
      int q;
      words >> q;
      o.parks[q] = axes(words);
    } else if (key == "home1") {
      o.home1 = axes(words);
    } else if (key == "home2") {
      o.home2 = axes(words);
    } else if (key == "start") {
      o.start_position = axes(words);
    } else if (key == "m99_restarts") {
      words >> o.m99_restarts;
    } else if (key == "max_lines") {
      words >> o.max_executed_lines;
    } else if (key == "max_commands") {
      words >> o.max_commands;
    } else if (key == "lenient_arcs") {
      o.strict_arcs = false;
    } else if (key == "macro_m") {
      int m;
      words >> m;
      o.macro_m_codes.insert(m);
    } else if (key == "no_comment_messages") {
      o.comments_as_messages = false;
    } else if (key == "nc_lines") {
      o.nc_lines_in_trace = true;
    } else if (key == "chord_tolerance") {
      words >> o.chord_tolerance;
    } else if (key == "feed") {
      words >> o.initial_feed;
    } else {
      ADD_FAILURE() << file << ": unknown option " << key;
    }
  }
  return o;
}

struct Result {
  std::string trace, warnings, error;
};

Result run_case(const fs::path& dir) {
  const fs::path options_file = dir / "options";
  pikocnc::Options options = fs::exists(options_file) ? parse_options(options_file) : pikocnc::Options{};
  std::ifstream in(dir / "program.nc", std::ios::binary);
  pikocnc::PikoReader reader(in, "program.nc", options);
  Result r;
  std::ostringstream out;
  {
    toolpath::TraceWriter writer(out);
    toolpath::Command c;
    try {
      while (reader.next(c)) writer.write(c);
    } catch (const toolpath::InputError& e) {
      r.error = std::string(e.what()) + "\n";
    }
  }
  r.trace = out.str();
  for (const auto& d : reader.diagnostics().kept()) r.warnings += std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + ": " + d.message + "\n";
  return r;
}

void check(const fs::path& file, const std::string& actual, bool update, bool optional) {
  if (update) {
    if (!actual.empty() || fs::exists(file)) {
      if (actual.empty() && optional) fs::remove(file);
      else std::ofstream(file, std::ios::binary) << actual;
    }
    return;
  }
  const std::string expected = fs::exists(file) ? slurp(file) : std::string();
  EXPECT_EQ(actual, expected) << "golden file " << file;
}

class Golden : public testing::TestWithParam<std::string> {};

TEST_P(Golden, MatchesExpectedStream) {
  const fs::path dir = kRoot / GetParam();
  const bool update = std::getenv("POSTPROC_UPDATE_GOLDEN") != nullptr;
  const Result r = run_case(dir);
  if (update && !fs::exists(dir / "expected.warnings") && !r.warnings.empty())
    std::ofstream(dir / "expected.warnings", std::ios::binary) << r.warnings;
  if (update && !fs::exists(dir / "expected.error") && !r.error.empty())
    std::ofstream(dir / "expected.error", std::ios::binary) << r.error;
  check(dir / "expected.trace", r.trace, update, false);
  check(dir / "expected.warnings", r.warnings, update, true);
  check(dir / "expected.error", r.error, update, true);
}


INSTANTIATE_TEST_SUITE_P(PikoCnc, Golden, testing::ValuesIn(test_support::subfolders(kRoot)),
                         [](const testing::TestParamInfo<std::string>& i) {
                           std::string n = i.param;
                           for (char& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace
