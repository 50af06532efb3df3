// The fast paths of the stream filters: command kinds by hash, set-coordinate names, rounding.
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "prp/filters/command_kind.hpp"
#include "prp/filters/kinematic_sets.hpp"
#include "prp/filters/precision_filter.hpp"

namespace prp {
namespace {

struct KindCase {
  const char* name;
  CommandKind kind;
};

const KindCase kKinds[] = {
#define PRP_KIND_CASE(kind, name) {"@" name, CommandKind::kind},
    PRP_COMMAND_KINDS(PRP_KIND_CASE)
#undef PRP_KIND_CASE
};

std::string upper(std::string s) {
  for (char& c : s) c = c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
  return s;
}

TEST(CommandKind, EveryNameInAnyCase) {
  for (const auto& [name, kind] : kKinds) {
    EXPECT_EQ(command_kind(name), kind) << name;
    EXPECT_EQ(command_kind(upper(name)), kind) << name;
    std::string mixed = name;
    for (std::size_t i = 1; i < mixed.size(); i += 2) mixed[i] = upper(std::string(1, mixed[i]))[0];
    EXPECT_EQ(command_kind(mixed), kind) << mixed;
  }
}

TEST(CommandKind, NearMissesAreOther) {
  for (const auto& [name, kind] : kKinds) {
    const std::string n = name;
    for (const std::string& miss : {n.substr(1), n + "x", n + "_", n.substr(0, n.size() - 1), "@@" + n.substr(1),
                                    n.substr(0, n.size() - 1) + "#"})
      EXPECT_EQ(command_kind(miss), CommandKind::other) << miss;
  }
  for (const char* other : {"", "@", "line", "@lin", "@lines", "@arc5x", "@start_of_jobs", "@end_of_fil",
                            "@change_tool2", "@ltne", "@move4x_polaR2", "@tool_path_infO_", "@\xc3\xa9line"})
    EXPECT_EQ(command_kind(other), CommandKind::other) << other;
}

// KindMemo remembers a kind per name length: over random sequences of names (every kind in three
// cases, near misses of the same length, long names, the empty name) it answers as command_kind().
TEST(CommandKind, MemoAnswersAsCommandKind) {
  std::vector<std::string> names;
  for (const auto& [name, kind] : kKinds) {
    const std::string n = name;
    names.insert(names.end(), {n, upper(n), n.substr(0, n.size() - 1) + "#", "#" + n.substr(1)});
  }
  names.insert(names.end(), {"", "@", "@x", "@ltne", "@lin3", "@arc_5y", "@start_of_jobs_and_more", "@tool_path_info",
                             "@tool_path_infO", "@tool_path_infp", "@\xc3\xa9line"});
  std::mt19937_64 rng(5);
  KindMemo memo;
  for (int i = 0; i < 20000; ++i) {
    // Mostly a few names over and over, as in a stream; now and then any name.
    const std::string& name = names[rng() % (i % 7 == 0 ? names.size() : 8)];  // @rapid_move, @line
    ASSERT_EQ(memo(name), command_kind(name)) << name;
  }
}

TEST(CommandKind, Groups) {
  using K = CommandKind;
  for (K k : {K::rapid_move, K::line, K::arc, K::line_on, K::move_5x, K::line_5x, K::arc_5x, K::start_program,
              K::end_program})
    EXPECT_TRUE(has(kMovesTool, k));
  for (K k : {K::move_4x, K::drill, K::drill_point, K::change_tool, K::other}) EXPECT_FALSE(has(kMovesTool, k));
  for (K k : {K::line, K::arc, K::line_on, K::line_5x, K::arc_5x}) EXPECT_TRUE(has(kFeedMotion, k));
  for (K k : {K::rapid_move, K::move_5x, K::start_program, K::line_4x}) EXPECT_FALSE(has(kFeedMotion, k));
  for (K k : {K::rapid_move, K::line, K::arc, K::line_on, K::move_5x, K::line_5x, K::arc_5x, K::move_4x, K::line_4x,
              K::move4x_cartesian, K::move4x_polar, K::move4x_dir, K::line4x_cartesian, K::line4x_polar,
              K::line4x_dir, K::arc4x_cartesian, K::arc4x_polar, K::drill})
    EXPECT_TRUE(has(kMotionBlock, k));
  for (K k : {K::start_program, K::end_program, K::drill_point, K::end_drill, K::other})
    EXPECT_FALSE(has(kMotionBlock, k));
}

TEST(SetCoordinate, EveryNameAndNearMisses) {
  const char* roles[] = {"pos", "center", "start"};
  for (int s = 0; s < kSetCount; ++s)
    for (int r = 0; r < 3; ++r)
      for (int a = 0; a < 3; ++a) {
        const std::string name = std::string(1, "xyz"[a]) + std::string(kSetPrefixes[static_cast<std::size_t>(s)]) + roles[r];
        for (const std::string& spelled : {name, upper(name)}) {
          auto c = classify_set_coordinate(spelled);
          ASSERT_TRUE(c) << spelled;
          EXPECT_EQ(c->set, s);
          EXPECT_EQ(static_cast<int>(c->role), r);
          EXPECT_EQ(c->axis, a);
        }
      }
  for (const char* other : {"xpos", "xcenter", "zstart", "xcenter_rel", "xhcenter_rel", "xhpos_", "whpos", "xzpos",
                            "xttpos", "xtopo", "xtoposx", "xhstar", "start_angle_h", "arc_plane_m", "h", "",
                            "xhhpos", "x1pos", "xtocenterx"})
    EXPECT_FALSE(classify_set_coordinate(other)) << other;
}

// The key table and the spelled classification agree on every catalogue name (and none is nothing).
TEST(SetCoordinate, ByKeySameAsByName) {
  EXPECT_FALSE(classify_set_coordinate(toolpath::ParamKey::none));
  int found = 0;
  for (std::size_t k = 1; k <= toolpath::param_key_count; ++k) {
    const auto key = static_cast<toolpath::ParamKey>(k);
    const auto by_name = classify_set_coordinate(toolpath::param_name(key));
    const auto by_key = classify_set_coordinate(key);
    ASSERT_EQ(by_key.has_value(), by_name.has_value()) << toolpath::param_name(key);
    if (!by_key) continue;
    ++found;
    EXPECT_EQ(by_key->set, by_name->set) << toolpath::param_name(key);
    EXPECT_EQ(by_key->role, by_name->role) << toolpath::param_name(key);
    EXPECT_EQ(by_key->axis, by_name->axis) << toolpath::param_name(key);
  }
  EXPECT_EQ(found, kSetCount * 3 * 3);  // every set coordinate is a catalogue name
}

TEST(PrecisionRounding, SameAsStdRound) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double v : {0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994, 1.4999999999999998,
                   4503599627370495.5, -4503599627370495.5, 4503599627370496.0, 9007199254740993.0, 1e300, -1e300,
                   inf, -inf, 123456.4999, 123456.5, -123456.5, 1e-300})
    EXPECT_EQ(round_half_away(v), std::round(v)) << v;
  EXPECT_TRUE(std::isnan(round_half_away(std::nan(""))));
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> spread(-1e7, 1e7);
  for (int i = 0; i < 100000; ++i) {
    const double v = spread(random) * (i % 2 ? 1.0 : 1e-4);
    const double halves = std::floor(v) + 0.5;  // exact halves too
    EXPECT_EQ(round_half_away(v), std::round(v)) << v;
    EXPECT_EQ(round_half_away(halves), std::round(halves)) << halves;
  }
}

}  // namespace
}  // namespace prp
