// The parameter shelf only moves buffers: a trace read through commands handed back in rotation
// (as the engine and the pipeline do, shapes alternating) gives exactly what fresh commands give.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "toolpath/trace_reader.hpp"

namespace {

using toolpath::Command;

std::string slurp(const char* path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::vector<Command> read_fresh(const std::string& text) {
  std::istringstream in(text);
  toolpath::TraceReader reader(in, "s.trace");
  std::vector<Command> all;
  for (Command c; reader.next(c); c = Command{}) all.push_back(c);
  return all;
}

// Reads into `rotation` buffers used in turn; a consumer may also change a buffer it hands back.
std::vector<Command> read_rotating(const std::string& text, std::size_t rotation, bool consumer_edits) {
  std::istringstream in(text);
  toolpath::TraceReader reader(in, "s.trace");
  std::vector<Command> buffers(rotation), all;
  for (std::size_t k = 0;; ++k) {
    Command& c = buffers[k % rotation];
    if (!reader.next(c)) break;
    all.push_back(c);
    if (consumer_edits && k % 3 == 0) c.set("added_by_filter", toolpath::Value::make_integer(1));
    if (consumer_edits && k % 5 == 0) c.name = "@renamed";
  }
  return all;
}

TEST(ParameterShelf, RotatingBuffersReadAsFreshOnes) {
  std::string alternating;
  for (int k = 0; k < 40; ++k) {
    alternating += "(1)@line ==> xpos:" + std::to_string(k) + ".5 ypos:1 zpos:-0.5 feed:1500.0\n";
    alternating += "(1)@arc ==> xpos:1 ypos:2 zpos:3 feed:4 xcenter:5\n           ..> ycenter:6 arc_direction:CW\n";
    if (k % 7 == 0) alternating += "(1)@line ==> ypos:2 xpos:1 user_value:'x y'\n";
    if (k % 11 == 0) alternating += "@rapid\nxpos : 1\nYPOS : 2T\n";
    if (k % 5 == 0)  // near misses of the names the slots hold: longer, other case, a prefix
      alternating += "(1)@arc ==> xpos:1 ypos2:2 ZPOS:3 fee:4 xcenter_reL:5\n           ..> ycenter:6 arc_direction:CW\n";
    if (k % 13 == 0) alternating += "(1)@c" + std::to_string(k) + " ==> a:1 b:2\n";
    if (k % 3 == 0) alternating += "(1)@a_name_of_more_than_16 ==> xpos:1 ypos:2\n";  // never shelved
  }
  const std::string texts[] = {alternating, slurp("golden/solidcam-fanuc/toolpath.trace"),
                               slurp("toolpath/data/solidcam_layout.trace")};
  for (const std::string& text : texts) {
    ASSERT_FALSE(text.empty());
    const std::vector<Command> expected = read_fresh(text);
    for (std::size_t rotation : {1, 2, 3, 5, 8})
      for (bool edits : {false, true}) EXPECT_EQ(read_rotating(text, rotation, edits), expected) << rotation << edits;
  }
}

}  // namespace
