// CommandFields finds, in one pass, what Command::find finds name by name; the arc filter hands
// them on with each command and the precision filter reads them instead of the parameters. Both
// are held to the general path: find() per name, and the precision filter scanning on its own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "prp/filters/command_fields.hpp"
#include "prp/filters/precision_filter.hpp"
#include "stream_helpers.hpp"

using namespace prp_test;
using prp::CommandFields;
using toolpath::Command;
using toolpath::Value;

namespace {

// Hands its input on as it is, without fields: the filter after it finds them itself.
class WithoutFields final : public prp::KindSource {
public:
  explicit WithoutFields(toolpath::CommandSource& input) : input_(input) {}
  bool next_with_kind(Command& out, prp::CommandKind& kind) override { return input_.next(out, kind); }

private:
  prp::KindedInput input_;
};

std::uint64_t bits_of(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// Every field is the first parameter of its name (any case), or none; set end points are told;
// one CommandFields serves command after command (it clears nothing between them).
TEST(CommandFields, FindsWhatFindFinds) {
  std::mt19937_64 rng(5);
  const char* names[] = {"xpos", "XPOS", "ypos", "zpos", "xcenter", "ycenter_rel", "radius", "zstart", "feed",
                         "Spin", "drill_depth", "down_step", "apos", "bpos", "arc_size", "arc_plane",
                         "arc_direction", "arc_plane_m", "xhpos", "ztopos", "start_angle", "not_a_name", "tool_number"};
  CommandFields fields;
  for (int i = 0; i < 5000; ++i) {
    Command c = command("@line", {});
    const int n = static_cast<int>(rng() % 12);
    for (int j = 0; j < n; ++j) c.parameters.push_back({names[rng() % std::size(names)], num(j)});
    fields.find(c);
    for (std::uint8_t f = 0; f < CommandFields::count; ++f)
      ASSERT_EQ(fields[f], c.find(CommandFields::key_of[f])) << i << " " << toolpath::param_name(CommandFields::key_of[f]);
    bool names_set_end_point = false;
    for (toolpath::ParamKey key : prp::kSetEndPoints) names_set_end_point |= c.find(key) != nullptr;
    ASSERT_EQ(fields.names_set_end_point(), names_set_end_point) << i;
  }
}

// A random stream of moves and arcs (arcs split at the quadrants and halved, so the arc filter
// also hands on pieces it made), with values off and on the grids, names given twice, texts and
// integers: the precision filter after the arc filter gives, bit for bit, what it gives finding
// the parameters itself.
TEST(CommandFields, PrecisionFilterReadsThemAsItWouldFindThem) {
  std::mt19937_64 rng(17);
  auto pick = [&](auto... options) {
    const double table[] = {static_cast<double>(options)...};
    return table[rng() % sizeof...(options)];
  };
  const char* extras[] = {"xpos", "feed", "spin", "radius", "zstart", "drill_depth", "down_step", "apos",
                          "start_angle", "tool_number"};
  for (int round = 0; round < 60; ++round) {
    prp::PrecisionSettings s;
    s.zero_value = pick(0.0, 0.001, 0.5, 1.5);
    if (rng() % 4) s.movement_digits = static_cast<int>(pick(3, 3, 0, 4));
    if (rng() % 2) s.feed_digits = static_cast<int>(pick(0, 1, -2));
    if (rng() % 2) s.spin_digits = static_cast<int>(pick(0, -2));
    prp::ArcSettings arcs;
    arcs.quadrants = rng() % 2 == 0;
    arcs.gt_180 = rng() % 2 == 0;
    arcs.eps_angle = 0.002;
    arcs.min_length = 0.001;
    std::vector<Command> in;
    double x = 10, y = 5, z = 1;
    for (int i = 0; i < 150; ++i) {
      Command c;
      if (rng() % 3 == 0) {  // an arc from where the tool is, its end on the circle
        const double dx = pick(5.0, -2.5, 0.0, 1.0004, 0.3), dy = pick(0.0, 4.0, -1.2345, 2.0);
        const double cx = x + dx, cy = y + dy, r = std::hypot(dx, dy);
        if (r < 0.1) continue;
        const double turn = pick(30.0, 90.0, 200.0, 300.0, 135.0) * std::numbers::pi / 180;
        const bool ccw = rng() % 2 == 0;
        const double from = std::atan2(-dy, -dx), to = from + (ccw ? turn : -turn);
        const double ex = cx + r * std::cos(to), ey = cy + r * std::sin(to);
        c = command("@arc", {{"xpos", num(ex)}, {"ypos", num(ey)}, {"zpos", num(z)}, {"feed", num(pick(1500, 99.6))},
                             {"xcenter", num(cx)}, {"ycenter", num(cy)}, {"xcenter_rel", num(dx)},
                             {"ycenter_rel", num(dy)}, {"radius", num(r)}, {"arc_direction", word(ccw ? "CCW" : "CW")},
                             {"arc_plane", word("XY")}});
        x = ex, y = ey;
      } else {
        x += pick(0.0, 0.0004, 1.0, -2.5, 3.14159);
        y += pick(0.0, -0.0004, 2.0, 0.5);
        z += pick(0.0, 0.0002, -0.5);
        c = command(rng() % 2 ? "@line" : "@rapid_move",
                    {{"xpos", Value::make_numeric(x, rng() % 5 ? toolpath::ChangeFlag::None : toolpath::ChangeFlag::Changed)},
                     {"ypos", num(y)},
                     {"zpos", num(z)}});
      }
      c.index = in.size();
      const int n = static_cast<int>(rng() % 4);
      for (int j = 0; j < n; ++j) {
        Value v;
        switch (rng() % 4) {
          case 0: v = Value::make_integer(static_cast<std::int64_t>(rng() % 5) - 2); break;
          case 1: v = Value::make_string("1.2345"); break;
          default: v = num(pick(0.0004, 12.3456, -7.0, 1e16, std::numeric_limits<double>::infinity()));
        }
        c.parameters.push_back({extras[rng() % std::size(extras)], v});
      }
      in.push_back(std::move(c));
    }
    ListSource handed_in(in), found_in(in);
    prp::ArcFilter handed_arcs(handed_in, arcs), found_arcs(found_in, arcs);
    WithoutFields hidden(found_arcs);
    prp::PrecisionFilter handed(handed_arcs, s), found(hidden, s);
    Command a, b;
    std::size_t count = 0;
    for (;;) {
      const bool more = handed.next(a);
      ASSERT_EQ(more, found.next(b));
      if (!more) break;
      ASSERT_NE(handed_arcs.fields(), nullptr);  // the path under test
      ++count;
      ASSERT_EQ(a.name, b.name);
      ASSERT_EQ(a.parameters.size(), b.parameters.size());
      for (std::size_t j = 0; j < a.parameters.size(); ++j) {
        const Value &p = a.parameters[j].value, &q = b.parameters[j].value;
        ASSERT_EQ(p.kind, q.kind) << round << " " << count << " " << j;
        ASSERT_EQ(p.flag, q.flag);
        ASSERT_EQ(p.integer, q.integer);
        ASSERT_EQ(bits_of(p.numeric), bits_of(q.numeric)) << round << " " << count << " " << a.parameters[j].name;
        ASSERT_EQ(p.text, q.text);
      }
    }
    EXPECT_GE(count, in.size());
  }
}

}  // namespace
