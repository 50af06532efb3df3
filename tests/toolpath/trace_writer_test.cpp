// The canonical writer: exact layout for a few commands, and read -> write -> read round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "toolpath/number_text.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/trace_writer.hpp"

using toolpath::ChangeFlag;
using toolpath::Command;
using toolpath::TraceLine;
using toolpath::Value;

namespace {

std::vector<Command> read_stream(std::istream& in) {
  toolpath::TraceReader reader(in, "in");
  std::vector<Command> all;
  Command c;
  while (reader.next(c)) all.push_back(c);
  return all;
}

std::string write_all(const std::vector<Command>& commands) {
  std::string out;
  for (const auto& c : commands) toolpath::append_command(out, c);
  return out;
}

TEST(TraceWriter, ValueForms) {
  struct Case {
    Value value;
    const char* text;
  } cases[] = {
      {Value::make_integer(-3), "-3"},
      {Value::make_integer(10, ChangeFlag::Changed), "10T"},
      {Value::make_numeric(10.0), "10.0"},
      {Value::make_numeric(-45.4760057628, ChangeFlag::Unchanged), "-45.4760057628F"},
      {Value::make_numeric(1e20), "1e+20"},
      {Value::make_logical(true), "true"},
      {Value::make_enum("COMP_LEFT"), "COMP_LEFT"},
      {Value::make_string("a b"), "'a b'"},
      {Value::make_string("it's"), "\"it's\""},
  };
  for (const auto& c : cases) {
    std::string out;
    toolpath::append_value(out, c.value);
    EXPECT_EQ(out, c.text);
  }
}

TEST(TraceWriter, SolidCamColumns) {
  Command c;
  c.name = "@rapid_move";
  c.set("xpos", Value::make_numeric(61.55, ChangeFlag::Changed));
  c.set("feed", Value::make_integer(0));
  c.trace.push_back({TraceLine::Kind::Output, "G0 X61.55 "});
  Command wrapped;
  wrapped.name = "@usr_spindle_output";
  wrapped.depth = 3;
  wrapped.trace.push_back({TraceLine::Kind::Partial, "N10"});
  wrapped.set("spin", Value::make_integer(1910));
  EXPECT_EQ(write_all({c, wrapped}),
            "(1)@rapid_move      ==> xpos:61.55T feed:0\n"
            "                      > G0 X61.55 \n"
            "(3)@usr_spindle_output ==> N10\n"
            "                    ..> spin:1910\n");
}

// read -> write -> read gives the same commands, and writing again gives the same text.
TEST(TraceWriter, RoundTrips) {
  for (const char* path : {"toolpath/data/solidcam_layout.trace", "golden/solidcam-fanuc/toolpath.trace"}) {
    SCOPED_TRACE(path);
    std::ifstream f(path, std::ios::binary);
    ASSERT_TRUE(f);
    auto first = read_stream(f);
    ASSERT_FALSE(first.empty());
    std::string text = write_all(first);
    std::istringstream again(text);
    auto second = read_stream(again);
    ASSERT_EQ(first.size(), second.size());
    for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(first[i], second[i]) << "command " << i;
    EXPECT_EQ(write_all(second), text);
  }
}

TEST(TraceWriter, LongParameterListsWrapOntoContinuationLines) {
  Command c;
  c.name = "@line";
  for (int i = 0; i < 30; ++i) c.set("parameter_" + std::to_string(i), Value::make_numeric(i + 0.5));
  std::string text = write_all({c});
  std::istringstream in(text);
  auto back = read_stream(in);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0], c);
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) EXPECT_LE(line.size(), 130u) << line;
}

}  // namespace

namespace {

// TraceWriter keeps the text of recent numbers (NumberCache); append_command writes every number
// afresh. Values drawn again and again from a pool (hash collisions included, -0, flags, values
// too long for the cache) must come out the same both ways.
TEST(TraceWriter, NumberCacheWritesWhatTheDigitsWould) {
  std::mt19937_64 rng(2025);
  std::vector<double> pool = {0.0, -0.0, 800.0, -1.0, 1e-5, 1e20, 0.1 + 0.2, -123456.123456789, 1.5e-300};
  for (int i = 0; i < 300; ++i) pool.push_back(static_cast<double>(static_cast<std::int64_t>(rng() % 2000000000) - 1000000000) / 1e4);
  for (int i = 0; i < 100; ++i) pool.push_back(std::ldexp(static_cast<double>(rng() >> 11), -static_cast<int>(rng() % 80)));
  std::string expected;
  std::ostringstream written;
  {
    toolpath::TraceWriter writer(written);
    for (int i = 0; i < 20000; ++i) {
      Command c;
      c.name = "@line";
      for (const char* name : {"xpos", "ypos", "zpos", "feed"}) {
        const ChangeFlag flag = rng() % 10 == 0 ? ChangeFlag::Changed : ChangeFlag::None;
        c.set(name, Value::make_numeric(pool[rng() % pool.size()], flag));
      }
      toolpath::append_command(expected, c);
      writer.write(c);
    }
  }
  EXPECT_EQ(written.str(), expected);
}

}  // namespace

namespace {

// The layout written the plain way, a std::string per line: what the writer's single-capacity
// pointer code must give for any command (names and texts of any length, every kind of value and
// trace line, wrapping).
std::string value_text(const Value& v) {
  const char* flag = v.flag == ChangeFlag::Changed ? "T" : v.flag == ChangeFlag::Unchanged ? "F" : "";
  switch (v.kind) {
    case toolpath::ValueKind::Integer: return std::to_string(v.integer) + flag;
    case toolpath::ValueKind::Numeric: return toolpath::number_text_exact(v.numeric) + flag;
    case toolpath::ValueKind::Logical: return v.logical ? "true" : "false";
    case toolpath::ValueKind::Enum: return v.text;
    case toolpath::ValueKind::String: {
      const char q = v.text.find('\'') == std::string::npos ? '\'' : '"';
      std::string quoted(1, q);
      quoted += v.text;
      quoted += q;
      return quoted;
    }
  }
  return {};
}

std::string reference_layout(const Command& c) {
  std::string out, line = "(";  // appended piece by piece: GCC 12 warns on "(" + std::string (-Wrestrict)
  line += std::to_string(c.depth);
  line += ")";
  line += c.name;
  line += std::string(line.size() >= 20 ? 1 : 20 - line.size(), ' ') + "==>";
  std::size_t from = 0;
  bool header_taken = false, pairs = false;
  if (!c.trace.empty() && c.trace.front().kind == TraceLine::Kind::Partial) {
    line += " " + c.trace.front().text;
    from = 1;
    header_taken = true;
  }
  for (const auto& p : c.parameters) {
    if (header_taken || (pairs && line.size() > 100)) {
      out += line + "\n";
      line = std::string(20, ' ') + "..>";
      header_taken = false;
    }
    line += " " + p.name + ":" + value_text(p.value);
    pairs = true;
  }
  out += line + "\n";
  for (std::size_t i = from; i < c.trace.size(); ++i) {
    const TraceLine& t = c.trace[i];
    if (t.kind == TraceLine::Kind::Output || t.kind == TraceLine::Kind::Partial) out += std::string(22, ' ') + "> ";
    if (t.kind == TraceLine::Kind::Note) out += std::string(20, ' ') + "..> ";
    out += t.text + "\n";
  }
  return out;
}

TEST(TraceWriter, RandomCommandsAsThePlainLayout) {
  std::mt19937_64 rng(25);
  auto text = [&](std::size_t max) {
    std::string s(rng() % (max + 1), 'a');
    for (char& ch : s) ch = static_cast<char>('a' + rng() % 26);
    return s;
  };
  std::string expected, appended;
  std::ostringstream written;
  {
    toolpath::TraceWriter writer(written);
    for (int i = 0; i < 5000; ++i) {
      Command c;
      c.name = "@" + text(30);
      c.depth = static_cast<int>(rng() % 12);
      const std::size_t params = rng() % 25;
      for (std::size_t k = 0; k < params; ++k) {
        Value v;
        switch (rng() % 5) {
          case 0: v = Value::make_integer(static_cast<std::int64_t>(rng()), ChangeFlag(rng() % 3)); break;
          case 1: v = Value::make_numeric(std::ldexp(static_cast<double>(rng() >> 11), static_cast<int>(rng() % 120) - 60), ChangeFlag(rng() % 3)); break;
          case 2: v = Value::make_logical(rng() % 2); break;
          case 3: v = Value::make_enum(text(40)); break;
          default: v = Value::make_string(rng() % 4 ? text(200) : "it's"); break;
        }
        c.parameters.emplace_back(text(40), v);
      }
      const std::size_t notes = rng() % 4;
      for (std::size_t k = 0; k < notes; ++k) c.trace.push_back({TraceLine::Kind(rng() % 4), text(150)});
      expected += reference_layout(c);
      toolpath::append_command(appended, c);
      writer.write(c);
    }
  }
  EXPECT_EQ(appended, expected);
  EXPECT_EQ(written.str(), expected);
}

}  // namespace
