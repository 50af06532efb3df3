// SolidCAM's own Sinumerik output read back through the Sinumerik model passes through every
// toolpath position of SolidCAM's trace of the same job, in order (issue 23's acceptance): the
// moves' end points (X Y Z), and each hole's X Y for the drilling cycles. Data: tests/machines/
// sinumerik/achar/ (catinrage/achar, MIT).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "machines/sinumerik/reader.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/value.hpp"

namespace {

struct Point {
  double x = 0, y = 0, z = 0;
  bool has_z = true;  // a hole: its X Y, at whatever height the cycle passes it
  std::string where;
};

std::optional<double> number(const toolpath::Command& c, std::string_view name) {
  const toolpath::Value* v = c.find(name);
  if (!v) return std::nullopt;
  return v->as_number();
}

bool is(const toolpath::Command& c, std::string_view name) { return toolpath::iequals(c.name, name); }

std::vector<Point> trace_points(const std::string& path) {
  auto reader = toolpath::TraceReader::open(path);
  std::vector<Point> out;
  toolpath::Command c;
  while (reader->next(c)) {
    if (!c.is_stream_command()) continue;
    const bool move = is(c, "@rapid_move") || is(c, "@line") || is(c, "@arc");
    const bool hole = is(c, "@drill_point");
    if (!move && !hole) continue;
    auto x = number(c, "xpos"), y = number(c, "ypos"), z = number(c, "zpos");
    if (!x || !y || (move && !z)) continue;
    out.push_back({*x, *y, z.value_or(0), move, path + ":" + std::to_string(c.line) + " " + c.name});
  }
  return out;
}

std::vector<Point> nc_points(const std::vector<std::string>& programs) {
  std::vector<Point> out;
  for (const auto& path : programs) {
    auto reader = sinumerik::SinumerikReader::open(path);
    toolpath::Command c;
    while (reader->next(c)) {
      if (!is(c, "@rapid_move") && !is(c, "@line") && !is(c, "@arc")) continue;
      out.push_back({*number(c, "xpos"), *number(c, "ypos"), *number(c, "zpos"), true, path});
    }
    std::ostringstream problems;
    for (const auto& d : reader->diagnostics().kept()) problems << d.text() << "\n";
    EXPECT_EQ(reader->diagnostics().total(), 0u) << problems.str();
  }
  return out;
}

TEST(SinumerikPassThrough, SolidCamOutputPassesEveryTracePositionInOrder) {
  struct Case {
    const char* trace;
    std::vector<std::string> programs;
    std::size_t at_least;  // positions of the trace checked (so that a broken trace read fails)
  } cases[] = {
      {"D_drill.trace", {"D_drill.SPF"}, 3},
      {"F_contour.trace", {"F_contour.SPF"}, 53},
      {"i3DRough_target_2.trace", {"i3DRough_target_2.SPF"}, 61},
      {"iRest_P_contour11.trace", {"iRest_faces_1.SPF", "P_contour11.SPF"}, 67},
  };
  const std::string dir = "machines/sinumerik/achar/";
  for (const auto& c : cases) {
    SCOPED_TRACE(c.trace);
    const std::vector<Point> expected = trace_points(dir + c.trace);
    std::vector<std::string> programs;
    for (const auto& p : c.programs) programs.push_back(dir + p);
    const std::vector<Point> actual = nc_points(programs);
    EXPECT_GE(expected.size(), c.at_least);
    std::size_t next = 0;
    for (const Point& e : expected) {
      const std::size_t from = next;
      while (next < actual.size()) {
        const Point& a = actual[next++];
        if (std::abs(a.x - e.x) < 0.002 && std::abs(a.y - e.y) < 0.002 && (!e.has_z || std::abs(a.z - e.z) < 0.002))
          break;
        if (next == actual.size()) next = actual.size() + 1;  // not found
      }
      if (next > actual.size()) {
        ADD_FAILURE() << e.where << ": X" << e.x << " Y" << e.y << " Z" << e.z
                      << " is not passed by the NC program after its position " << from;
        break;
      }
    }
  }
}

}  // namespace
