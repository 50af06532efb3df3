// Golden folders under machines/iso/golden/<case>/: `program.nc`, read with the dialect named in
// `dialect`, is printed in the canonical trace form, which must equal `expected.trace`; every
// diagnostic (`line:col: severity: text`) must equal `expected.diagnostics` (absent: none). A
// `tool.tbl` beside the program is the control's tool table.
// POSTPROC_UPDATE_GOLDEN=1 rewrites the expected files (review them before committing).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "machines/iso/reader.hpp"
#include "tests/support/golden_file.hpp"
#include "toolpath/trace_writer.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = "machines/iso/golden";

class Golden : public ::testing::TestWithParam<std::string> {};

TEST_P(Golden, ReadsBackAsExpected) {
  const fs::path dir = kRoot / GetParam();
  std::istringstream dialect_file(test_support::slurp(dir / "dialect"));
  std::string dialect;
  dialect_file >> dialect;
  const iso::Rules* rules = iso::rules_of(dialect);
  ASSERT_NE(rules, nullptr) << dir / "dialect" << ": " << dialect;
  iso::Options options;
  if (fs::exists(dir / "tool.tbl"))
    options.tools = std::make_shared<const ncmodel::ToolTable>(ncmodel::load_tool_table((dir / "tool.tbl").string()));
  auto reader = iso::IsoReader::open((dir / "program.nc").string(), *rules, options);
  std::ostringstream trace;
  toolpath::TraceWriter writer(trace);
  toolpath::Command c;
  while (reader->next(c)) writer.write(c);
  writer.flush();
  std::string diagnostics;
  for (const auto& d : reader->diagnostics().kept())
    diagnostics += fmt::format("{}:{}: {}: {}\n", d.where.line, d.where.column, d.error() ? "error" : "warning", d.message);
  test_support::expect_golden(dir / "expected.trace", trace.str());
  test_support::expect_golden(dir / "expected.diagnostics", diagnostics);
}


INSTANTIATE_TEST_SUITE_P(Iso, Golden, ::testing::ValuesIn(test_support::subfolders(kRoot)), [](const auto& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

}  // namespace
