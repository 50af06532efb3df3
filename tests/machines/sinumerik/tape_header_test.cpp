// The punched-tape header of a Sinumerik program: `%` in the first column of the first line, then
// the file's name (`%_N_MAIN_MPF`, `%Flange3_MPF`) or nothing. The control takes it as the file's
// name, so the model skips it; a `%` anywhere else stays an error.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "machines/sinumerik/reader.hpp"

namespace {

struct Read {
  std::vector<toolpath::Command> commands;
  std::vector<std::string> problems;  // line:column message
};

Read read(const std::string& program) {
  auto reader = sinumerik::SinumerikReader::from_string(program, "MAIN.MPF");
  Read r;
  toolpath::Command c;
  while (reader->next(c)) r.commands.push_back(c);
  for (const auto& d : reader->diagnostics().kept())
    r.problems.push_back(std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + " " + d.message);
  return r;
}

constexpr const char* kBody = "G0 X1 Y2\nG1 Z-1 F100\nM30\n";

TEST(SinumerikTapeHeader, FirstLineHeaderIsSkipped) {
  const Read plain = read(kBody);
  ASSERT_TRUE(plain.problems.empty());
  for (const std::string header : {"%\n", "%_N_MAIN_MPF\n;$PATH=/_N_MPF_DIR\n", "%Flange3_MPF \n", "%_N_MAIN_MPF\r\n"}) {
    const Read r = read(header + kBody);
    EXPECT_TRUE(r.problems.empty()) << header << (r.problems.empty() ? "" : r.problems[0]);
    EXPECT_EQ(r.commands, plain.commands) << header;
  }
}

TEST(SinumerikTapeHeader, PercentElsewhereIsAnError) {
  const struct {
    std::string program;
    std::string problem;
  } cases[] = {
      {std::string("G0 X1\n%\n") + kBody, "2:1 unexpected `%`"},          // not the first line
      {std::string(" %_N_MAIN_MPF\n") + kBody, "1:2 unexpected `%`"},     // not the first column
      {std::string("%_N_MAIN MPF\n") + kBody, "1:1 unexpected `%`"},      // not a file name
  };
  for (const auto& c : cases) {
    const Read r = read(c.program);
    ASSERT_EQ(r.problems.size(), 1u) << c.program;
    EXPECT_EQ(r.problems[0], c.problem) << c.program;
  }
}

}  // namespace
