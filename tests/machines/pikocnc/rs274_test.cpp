// Cross-check with LinuxCNC's stand-alone interpreter `rs274` (package linuxcnc-uspace,
// scripts/install-rs274.sh) on programs of the subset both dialects share: G0-G3, G17-G19, G20/G21,
// G81/G83, G90/G91. Skipped when rs274 is not installed.
//
// One documented difference is left out of the comparison: PikoCNC's G83 returns at rapid exactly
// to the previous peck depth, LinuxCNC stops a small clearance above it; for G83 only the feed moves
// (the peck depths) and the final position are compared.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "machines/pikocnc/model/reader.hpp"

namespace {

struct Motion {
  char kind;  // 'R' rapid, 'F' feed, 'A' arc
  double x, y, z;
  double cx = 0, cy = 0, cz = 0;  // arcs: centre (the normal coordinate is not compared)
  int turn = 0;                   // arcs: +1 counter-clockwise, -1 clockwise about the plane normal
};

bool have_rs274() { return std::system("command -v rs274 >/dev/null 2>&1") == 0; }

std::string run(const std::string& command) {
  std::string out;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return out;
  std::array<char, 4096> buf;
  while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe.get())) out.append(buf.data(), n);
  return out;
}

// STRAIGHT_TRAVERSE(x, y, z, ...), STRAIGHT_FEED(x, y, z, ...), ARC_FEED(first, second, c1, c2,
// rotation, axis_end, ...) in the canonical call trace, converted to millimetres.
std::vector<Motion> linuxcnc_motion(const std::string& program) {
  // One tool table per process: ctest runs these tests in parallel processes.
  const std::string tools = testing::TempDir() + "rs274-" + std::to_string(::getpid()) + ".tbl";
  std::ofstream(tools) << "T1 P1 D1 Z0 ;\n";
  const std::string trace = run("rs274 -t " + tools + " " + program + " 2>&1 </dev/null");
  std::vector<Motion> out;
  double scale = 1.0;
  int plane = 17;
  std::istringstream lines(trace);
  std::string line;
  const std::regex call(R"((STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|USE_LENGTH_UNITS|SELECT_PLANE)\((.*)\))");
  while (std::getline(lines, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, call)) continue;
    const std::string name = m[1];
    std::vector<double> v;
    std::string args = m[2];
    if (name == "USE_LENGTH_UNITS") {
      scale = args.find("INCHES") != std::string::npos ? 25.4 : 1.0;
      continue;
    }
    if (name == "SELECT_PLANE") {
      plane = args.find("XZ") != std::string::npos ? 18 : args.find("YZ") != std::string::npos ? 19 : 17;
      continue;
    }
    std::istringstream a(args);
    std::string item;
    while (std::getline(a, item, ',')) v.push_back(std::atof(item.c_str()));
    if (name == "ARC_FEED") {
      // first/second end are the plane's axes; axis_end is the normal axis.
      double x = 0, y = 0, z = 0, cx = 0, cy = 0, cz = 0;
      if (plane == 17) x = v[0], y = v[1], z = v[5], cx = v[2], cy = v[3];
      if (plane == 18) z = v[0], x = v[1], y = v[5], cz = v[2], cx = v[3];
      if (plane == 19) y = v[0], z = v[1], x = v[5], cy = v[2], cz = v[3];
      out.push_back({'A', x * scale, y * scale, z * scale, cx * scale, cy * scale, cz * scale, v[4] > 0 ? 1 : -1});
    } else {
      out.push_back({name == "STRAIGHT_FEED" ? 'F' : 'R', v[0] * scale, v[1] * scale, v[2] * scale});
    }
  }
  return out;
}

std::vector<Motion> our_motion(const std::string& program) {
  auto reader = pikocnc::PikoReader::open(program);
  std::vector<Motion> out;
  toolpath::Command c;
  while (reader->next(c)) {
    const char kind = c.name == "@rapid_move" ? 'R' : c.name == "@line" ? 'F' : c.name == "@arc" ? 'A' : 0;
    if (!kind) continue;
    Motion m{kind, c.find("xpos")->numeric, c.find("ypos")->numeric, c.find("zpos")->numeric};
    if (kind == 'A') {
      const std::string plane = c.find("arc_plane")->text;
      m.cx = plane == "YZ" ? 0 : c.find("xcenter")->numeric;
      m.cy = plane == "ZX" ? 0 : c.find("ycenter")->numeric;
      m.cz = plane == "XY" ? 0 : c.find("zcenter")->numeric;
      m.turn = c.find("arc_direction")->text == "CCW" ? 1 : -1;
    }
    out.push_back(m);
  }
  return out;
}

std::string show(const std::vector<Motion>& m) {
  std::string s;
  for (const auto& x : m) s += std::string(1, x.kind) + " " + std::to_string(x.x) + " " + std::to_string(x.y) + " " + std::to_string(x.z) + "\n";
  return s;
}

void compare(const std::string& name, bool feeds_only) {
  if (!have_rs274()) GTEST_SKIP() << "LinuxCNC rs274 is not installed (scripts/install-rs274.sh installs it)";
  const std::string program = "machines/pikocnc/rs274/" + name;
  std::vector<Motion> theirs = linuxcnc_motion(program), ours = our_motion(program);
  auto drop_rapids = [](std::vector<Motion>& m) {
    std::erase_if(m, [](const Motion& x) { return x.kind == 'R'; });
  };
  // rs274 reports zero-length moves; we do not emit them
  std::vector<Motion> filtered;
  Motion at{'R', 0, 0, 0};
  for (const auto& m : theirs) {
    if (std::abs(m.x - at.x) + std::abs(m.y - at.y) + std::abs(m.z - at.z) > 1e-6 || m.kind == 'A') filtered.push_back(m);
    at = m;
  }
  theirs = filtered;
  if (feeds_only) {
    drop_rapids(theirs);
    drop_rapids(ours);
  }
  ASSERT_FALSE(theirs.empty()) << "no canonical motion from rs274 for " << program;
  ASSERT_EQ(theirs.size(), ours.size()) << "rs274:\n" << show(theirs) << "ours:\n" << show(ours);
  for (std::size_t i = 0; i < ours.size(); ++i) {
    EXPECT_EQ(theirs[i].kind, ours[i].kind) << i;
    EXPECT_NEAR(theirs[i].x, ours[i].x, 1e-3) << i;
    EXPECT_NEAR(theirs[i].y, ours[i].y, 1e-3) << i;
    EXPECT_NEAR(theirs[i].z, ours[i].z, 1e-3) << i;
    EXPECT_NEAR(theirs[i].cx, ours[i].cx, 1e-3) << i;
    EXPECT_NEAR(theirs[i].cy, ours[i].cy, 1e-3) << i;
    EXPECT_NEAR(theirs[i].cz, ours[i].cz, 1e-3) << i;
    EXPECT_EQ(theirs[i].turn, ours[i].turn) << i;
  }
}

TEST(PikoRs274, MotionPlanesAndDistanceModes) { compare("basic.nc", false); }
TEST(PikoRs274, InchProgram) { compare("inch.nc", false); }
TEST(PikoRs274, DrillingCyclesFeedMoves) { compare("drilling.nc", true); }

}  // namespace
