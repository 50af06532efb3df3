// Interned parameter names: param_key must agree exactly with a plain case-insensitive search of
// the catalogue, and Command's key lookups with its name lookups.
#include <gtest/gtest.h>

#include <cctype>
#include <random>
#include <string>

#include "toolpath/command.hpp"
#include "toolpath/param_key.hpp"

namespace {

using toolpath::Command;
using toolpath::ParamKey;
using toolpath::Value;

ParamKey key_of(std::size_t k) { return static_cast<ParamKey>(k); }

// The definition: the key whose name equals `name` ignoring ASCII case, found by trying them all.
ParamKey plain_key(std::string_view name) {
  for (std::size_t k = 1; k <= toolpath::param_key_count; ++k) {
    const std::string_view n = toolpath::param_name(key_of(k));
    if (n.size() != name.size()) continue;
    bool same = true;
    for (std::size_t i = 0; i < n.size() && same; ++i)
      same = std::tolower(static_cast<unsigned char>(n[i])) == std::tolower(static_cast<unsigned char>(name[i]));
    if (same) return key_of(k);
  }
  return ParamKey::none;
}

std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

TEST(ParamKey, Table) {
  struct Case {
    std::string_view name;
    ParamKey key;
  };
  const Case cases[] = {
      {"xpos", ParamKey::xpos},
      {"XPOS", ParamKey::xpos},
      {"xPoS", ParamKey::xpos},
      {"feed", ParamKey::feed},
      {"arc_direction", ParamKey::arc_direction},
      {"xcenter_rel", ParamKey::xcenter_rel},
      {"tmatrix_I_16", ParamKey::tmatrix_I_16},
      {"TMATRIX_i_16", ParamKey::tmatrix_I_16},
      {"tmatrix_I_1", ParamKey::tmatrix_I_1},
      {"tool_RADIUS_BETA", ParamKey::tool_RADIUS_BETA},
      {"xhnext_start_tool_level", ParamKey::xhnext_start_tool_level},
      {"opposite_second_axis_angle", ParamKey::opposite_second_axis_angle},
      {"", ParamKey::none},
      {"x", ParamKey::none},
      {"xpo", ParamKey::none},
      {"xposs", ParamKey::none},
      {"prog_xpos", ParamKey::none},
      {"xpos ", ParamKey::none},
      {"xpo\xd3", ParamKey::none},
      {std::string_view("xpos\0", 5), ParamKey::none},
      {"tmatrix_I_17", ParamKey::none},
      {"an_unusually_long_parameter_name_of_a_user_post_that_is_in_no_table", ParamKey::none},
  };
  for (const Case& c : cases) EXPECT_EQ(toolpath::param_key(c.name), c.key) << c.name;
  EXPECT_EQ(toolpath::param_name(ParamKey::xpos), "xpos");
  EXPECT_EQ(toolpath::param_name(ParamKey::tool_RADIUS_BETA), "tool_RADIUS_BETA");
  EXPECT_EQ(toolpath::param_name(ParamKey::none), "");
}

TEST(ParamKey, EveryNameFindsItsKeyInAnyCase) {
  ASSERT_GT(toolpath::param_key_count, 400u);
  for (std::size_t k = 1; k <= toolpath::param_key_count; ++k) {
    const std::string_view name = toolpath::param_name(key_of(k));
    ASSERT_FALSE(name.empty()) << k;
    EXPECT_EQ(toolpath::param_key(name), key_of(k)) << name;
    EXPECT_EQ(toolpath::param_key(upper(name)), key_of(k)) << name;
  }
}

// Near misses of every name (one byte changed, added or removed) and random words: the hash
// lookup and the plain search agree.
TEST(ParamKey, AgreesWithPlainSearch) {
  std::mt19937 rng(20240611);
  const std::string alphabet = "abcdefghijklmnopqrstuvwxyzXYZ_0123456789\x80\xff ";
  auto random_char = [&] { return alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)]; };
  std::size_t checked = 0;
  for (std::size_t k = 1; k <= toolpath::param_key_count; ++k) {
    const std::string name(toolpath::param_name(key_of(k)));
    for (std::size_t i = 0; i <= name.size(); ++i) {
      std::string changed = name, added = name, removed = name;
      if (i < name.size()) {
        changed[i] = random_char();
        removed.erase(i, 1);
      }
      added.insert(i, 1, random_char());
      for (const std::string& s : {changed, added, removed}) {
        ASSERT_EQ(toolpath::param_key(s), plain_key(s)) << s;
        ++checked;
      }
    }
  }
  for (int n = 0; n < 20000; ++n) {
    std::string s(std::uniform_int_distribution<std::size_t>(0, 12)(rng), ' ');
    for (char& c : s) c = random_char();
    ASSERT_EQ(toolpath::param_key(s), plain_key(s)) << s;
  }
  EXPECT_GT(checked, 10000u);
}

Command sample() {
  Command c;
  c.name = "@line";
  c.parameters = {{"XPOS", Value::make_numeric(1)},
                  {"ypos", Value::make_numeric(2)},
                  {"my_param", Value::make_integer(3)},
                  {"xpos", Value::make_numeric(4)},
                  {"MY_PARAM", Value::make_integer(5)}};
  return c;
}

TEST(CommandKeys, ParametersCarryTheirKeys) {
  const Command c = sample();
  EXPECT_EQ(c.parameters[0].key, ParamKey::xpos);
  EXPECT_EQ(c.parameters[1].key, ParamKey::ypos);
  EXPECT_EQ(c.parameters[2].key, ParamKey::none);
  toolpath::Parameter p;
  EXPECT_EQ(p.key, ParamKey::none);
  p.rename("Feed");
  EXPECT_EQ(p.name, "Feed");
  EXPECT_EQ(p.key, ParamKey::feed);
  p.rename("feedrate");
  EXPECT_EQ(p.key, ParamKey::none);
}

TEST(CommandKeys, FindByKeyIsFindByName) {
  const Command c = sample();
  // The first of a name wins, whatever its case; names outside the catalogue compare as text.
  EXPECT_EQ(c.find(ParamKey::xpos), &c.parameters[0].value);
  EXPECT_EQ(c.find("xpos"), &c.parameters[0].value);
  EXPECT_EQ(c.find("Ypos"), &c.parameters[1].value);
  EXPECT_EQ(c.find("my_PARAM"), &c.parameters[2].value);
  EXPECT_EQ(c.find(ParamKey::zpos), nullptr);
  EXPECT_EQ(c.find("zpos"), nullptr);
  EXPECT_EQ(c.find("my_para"), nullptr);
  EXPECT_EQ(c.find(""), nullptr);
  EXPECT_EQ(c.find(ParamKey::none), nullptr);
  for (std::size_t k = 1; k <= toolpath::param_key_count; ++k)
    EXPECT_EQ(c.find(key_of(k)), c.find(toolpath::param_name(key_of(k))));
}

TEST(CommandKeys, Set) {
  Command c = sample();
  c.set("YPOS", Value::make_numeric(7));  // replaces the first ypos, keeps its spelling
  EXPECT_EQ(c.parameters[1].name, "ypos");
  EXPECT_EQ(c.parameters[1].value, Value::make_numeric(7));
  c.set(ParamKey::xpos, Value::make_numeric(8));
  EXPECT_EQ(c.parameters[0], toolpath::Parameter("XPOS", Value::make_numeric(8)));
  c.set("my_param", Value::make_integer(9));
  EXPECT_EQ(c.parameters[2].value, Value::make_integer(9));
  ASSERT_EQ(c.parameters.size(), 5u);
  c.set("ZPOS", Value::make_numeric(10));  // a new one is named as given
  c.set(ParamKey::feed, Value::make_numeric(11));  // or in the catalogue's spelling
  c.set("other", Value::make_integer(12));
  c.set(ParamKey::none, Value::make_integer(13));  // nothing to name it with: ignored
  ASSERT_EQ(c.parameters.size(), 8u);
  EXPECT_EQ(c.parameters[5], toolpath::Parameter("ZPOS", Value::make_numeric(10)));
  EXPECT_EQ(c.parameters[5].key, ParamKey::zpos);
  EXPECT_EQ(c.parameters[6], toolpath::Parameter("feed", Value::make_numeric(11)));
  EXPECT_EQ(c.parameters[7], toolpath::Parameter("other", Value::make_integer(12)));
  EXPECT_EQ(c.parameters[7].key, ParamKey::none);
}

}  // namespace
