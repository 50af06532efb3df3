// The block models' line reader: every line end the controls write, and a jump back to a mark (a
// loop, a label) both inside the buffered chunk and behind it.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "machines/ncmodel/line_reader.hpp"

namespace {

std::vector<std::string> lines(ncmodel::LineReader& r) {
  std::vector<std::string> out;
  std::string_view line;
  while (r.next(line)) out.emplace_back(line);
  return out;
}

TEST(LineReader, EveryLineEnd) {
  std::istringstream in("G0 X1\nG1 X2\r\nG1 X3\rG1 X4\n\nlast");
  ncmodel::LineReader r(in, "p.nc");
  EXPECT_EQ(lines(r), (std::vector<std::string>{"G0 X1", "G1 X2", "G1 X3", "G1 X4", "", "last"}));
  EXPECT_EQ(r.line_number(), 6u);
}

TEST(LineReader, SeeksBackToAMark) {
  // the second pass starts behind the first 256 KiB chunk, which is no longer buffered
  std::string text = "L1\nL2\n";
  for (int i = 0; i < 40000; ++i) text += "G1 X" + std::to_string(i) + "\n";
  std::istringstream in(text);
  ncmodel::LineReader r(in, "p.nc");
  std::string_view line;
  ASSERT_TRUE(r.next(line));
  const ncmodel::LineReader::Mark second = r.mark();
  ASSERT_TRUE(r.next(line));
  EXPECT_EQ(line, "L2");
  r.seek(second);  // inside the buffer
  ASSERT_TRUE(r.next(line));
  EXPECT_EQ(line, "L2");
  EXPECT_EQ(r.line_number(), 2u);
  EXPECT_EQ(lines(r).size(), 40000u);
  r.seek(second);  // behind it: read again from the stream
  ASSERT_TRUE(r.next(line));
  EXPECT_EQ(line, "L2");
  EXPECT_EQ(r.line_number(), 2u);
  ASSERT_TRUE(r.next(line));
  EXPECT_EQ(line, "G1 X0");
}

}  // namespace
