// Golden folders under machines/2xaxiscnc/golden/<case>/: `program.nc` is read back and printed in
// the canonical trace form, which must equal `expected.trace`; every diagnostic
// (`line:col: severity: text`) must equal `expected.diagnostics` (absent: none). Optional `options`:
// one reader setting a line (machine_speed N, rapid_coefficient K, exact, scripts_folder DIR).
// POSTPROC_UPDATE_GOLDEN=1 rewrites the expected files (review them before committing).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "machines/2xaxiscnc/reader.hpp"
#include "tests/support/golden_file.hpp"
#include "toolpath/trace_writer.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = "machines/2xaxiscnc/golden";

twoaxis::Options parse_options(const fs::path& file) {
  twoaxis::Options o;
  std::ifstream in(file);
  std::string key;
  while (in >> key) {
    if (key == "machine_speed") in >> o.machine_speed;
    else if (key == "rapid_coefficient") in >> o.rapid_coefficient;
    else if (key == "exact") o.single_precision = false;
    else if (key == "scripts_folder") in >> o.scripts_folder;
    else ADD_FAILURE() << file << ": unknown setting " << key;
  }
  return o;
}

class Golden : public ::testing::TestWithParam<std::string> {};

TEST_P(Golden, ReadsBackAsExpected) {
  const fs::path dir = kRoot / GetParam();
  const auto options = fs::exists(dir / "options") ? parse_options(dir / "options") : twoaxis::Options{};
  auto reader = twoaxis::TwoAxisReader::open((dir / "program.nc").string(), options);
  std::ostringstream trace;
  toolpath::TraceWriter writer(trace);
  toolpath::Command c;
  while (reader->next(c)) writer.write(c);
  writer.flush();
  std::string diagnostics;
  for (const auto& d : reader->diagnostics().kept())
    diagnostics += fmt::format("{}{}:{}: {}: {}\n", d.where.file.empty() ? "" : d.where.file + ":", d.where.line,
                               d.where.column, d.error() ? "error" : "warning", d.message);
  test_support::expect_golden(dir / "expected.trace", trace.str());
  test_support::expect_golden(dir / "expected.diagnostics", diagnostics);
}


INSTANTIATE_TEST_SUITE_P(TwoAxis, Golden, ::testing::ValuesIn(test_support::subfolders(kRoot)),
                         [](const auto& info) { return info.param; });

}  // namespace
