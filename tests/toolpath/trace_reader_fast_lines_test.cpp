// The reader's fast path for the common lines of the inline layout (a header `(N)@name ==> pairs`
// or a continuation `..> pairs`, read straight from the chunk) must read exactly what the general
// rule reads, line by line: the same commands, positions and errors. Each input below is read
// both ways (TraceReader::read_by_general_rule turns the fast path off).
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "toolpath/trace_reader.hpp"
#include "tests/support/random_edits.hpp"

namespace {

// Everything a reader gives for `text`: each command with its positions, then the error if any.
// With `scribble`, each command's values are overwritten once recorded, as the filters round
// values in place before the buffers come back: what the reader remembers must be its own.
std::string read_all(const std::string& text, bool general, bool scribble = false) {
  std::istringstream in(text);
  toolpath::TraceReader reader(in, "f.trace");
  if (general) reader.read_by_general_rule();
  std::ostringstream out;
  // One command buffer reused, as a pipeline does; and a second one in turn, so that the shelf
  // swaps parameter vectors as it does behind a lookahead.
  toolpath::Command a, b;
  toolpath::Command* c = &a;
  std::vector<toolpath::Command> kept;
  try {
    while (reader.next(*c)) {
      out << c->index << ' ' << c->name << " d" << c->depth << " l" << c->line << ':';
      for (const toolpath::Parameter& p : c->parameters) out << ' ' << p.name << '@' << p.line << ':' << p.column;
      out << '\n';
      kept.push_back(*c);
      if (scribble)
        for (toolpath::Parameter& p : c->parameters) {
          p.value.kind = p.value.kind == toolpath::ValueKind::Integer ? toolpath::ValueKind::Numeric : toolpath::ValueKind::Integer;
          p.value.flag = toolpath::ChangeFlag::Changed;
          p.value.integer += 3;
          p.value.numeric = p.value.numeric * 0.5 + 0.25;
        }
      c = c == &a ? &b : &a;
    }
  } catch (const toolpath::InputError& e) {
    out << "error: " << e.what() << '\n';
  }
  // The values and trace lines, compared as Command does (by kind: a recycled value's other
  // fields are left as they were).
  std::ostringstream all;
  all << out.str();
  for (std::size_t i = 0; i < kept.size(); ++i) {
    all << '#' << i;
    for (const toolpath::Parameter& p : kept[i].parameters) {
      const toolpath::Value& v = p.value;
      all << ' ' << static_cast<int>(v.kind) << '/' << static_cast<int>(v.flag) << '/';
      switch (v.kind) {
        case toolpath::ValueKind::Integer: all << v.integer; break;
        case toolpath::ValueKind::Numeric: all << v.numeric; break;
        case toolpath::ValueKind::Logical: all << v.logical; break;
        default: all << '\'' << v.text << '\''; break;
      }
    }
    for (const toolpath::TraceLine& t : kept[i].trace) all << " [" << static_cast<int>(t.kind) << ' ' << t.text << ']';
    all << '\n';
  }
  return all.str();
}

void check(const std::string& text) {
  const std::string fast = read_all(text, false);
  const std::string general = read_all(text, true);
  ASSERT_EQ(fast, general) << "input:\n" << text.substr(0, 2000);
}

TEST(TraceReaderFastLines, ExamplesReadAsTheGeneralRuleReadsThem) {
  const char* texts[] = {
      "(1)@line ==> xpos:1.5 ypos:2\n(1)@line ==> xpos:3 ypos:4\n",
      "(1)@arc  ==> xpos:1 ypos:2\n      ..> feed:3 arc_direction:CW\n(1)@arc  ==> xpos:1 ypos:2\n      ..> feed:3 arc_direction:CCW\n",
      "(1)@line ==> xpos:1\r\n(1)@line ==> xpos:2\r\n",
      "(1)@line ==> xpos:1\r\r\n(1)@line ==> xpos:2\r \n",
      "(1)@line ==> xpos:1   \n(1)@line ==> xpos:2\t\n(1)@line ==>   \n(1)@line ==>\n",
      "(1)@line ==> xpos:1\n\n(1)@line ==> xpos:2\n;c\n   ..> ypos:1\n",
      "(1)@line ==> xpos:1\n(1)@line ==> xpos:1 extra\n(1)@line ==> xpos:1 ypos:2\n",
      "(1)@line ==> xpos:1\n(1)@line ==> xpos:'q'\n(1)@line ==> xpos:1e5\n(1)@line ==> xpos:12345678901234567890\n",
      "(1)@line ==> xpos:1\n(1)@line ==> xpos:\n(1)@line ==> xpos:1T\n(1)@line ==> xpos:1x\n",
      "(1)@line ==> xpos:1\n(2)@line ==> xpos:1\n(0)@line ==> xpos:1\n(-1)@line ==> xpos:1\n",
      "(1)@line ==> xpos:1\n(1234567890)@line ==> xpos:1\n(123456789)@line ==> xpos:1\n(99999999999999999999)@line ==> xpos:1\n",
      "(1)@line ==> xpos:1\n(1)@line  junk\n",
      "(1)@line ==> xpos:1\n(1)@line\n  xpos : 2\n(1)@line ==> xpos:3\n",
      "(1)@line ==> xpos:1\n@line\nxpos : 2\n(1)@line ==> xpos:3\n   (1)@line ==> xpos:4\n",
      "(1)@averyveryverylongname==> xpos:1\n   ut     ..> ypos:2\n(1)@averyveryverylongname==> xpos:1\n   ut\n",
      "(1)@line ==> xpos:1\n   > N10 G1\n   ..> ypos:1\n!! open !!\n",
      "(1)@line ==> xpos:1\n   ..> free text here\n(1)@end ==> no parameters\n",
      "(1)@line ==> xpos:1 ypos:2 zpos:3\n(1)@line ==> xpos:1 ypos:2\n(1)@line ==> xpos:1 ypos:2 zpos:3 feed:4\n",
      "(1)@line ==> xpos:1\n(1)@line ==> XPOS:1\n(1)@line ==> xpos:1\n",
      "(1)@line ==> xpos:1\n(1)@line ==> xpos:1",
      "(1)@line ==> xpos:1\n(1)@line ==> xpos:1\r",
      "(1)@line ==> xpos:1\n(1)@line ==> xpos:1\0\n",
      "(1)@line ==> xpos:1\n(1)@line ==> xpos:1 \0ypos:2\n",
      "(1)@line ==> xpos:1\n(1)@line ==> xpos:1\n..>",
      "(1)@line ==> xpos:1\n(1)@line ==> xpos:1\n..",
      "(1)@line ==> xpos:1\n(1)@",
      "(1)@line ==> xpos:1\n(1)",
      "(1)@line ==> xpos:1\n(",
      "(1)@line ==> xpos:1\n(1)@line ==",
      "(1)@line ==> xpos:1\n(1)@line =",
      "(1)@line ==> xpos:1\n(1)@1ine ==> xpos:1\n",
      "(1)@line ==> xpos:1\n(1)@line\t==>\txpos:1\n\t..>\typos:2\n",
  };
  for (const char* t : texts) check(t);
  // With the embedded '\0's kept.
  check(std::string("(1)@line ==> xpos:1\n(1)@line ==> xpos:1\0\n", 41));
  check(std::string("(1)@line ==> xpos:1\n(1)@line ==> xpos:1 \0ypos:2\n", 48));
  check(std::string("(1)@line ==> xpos:1\n(1)@line ==> xpos:\0\n", 40));
}

// Random jobs in the inline layout, from a few shapes with values from a small alphabet, with
// random damage: most lines the fast path reads, some it leaves to the general rule.
std::string random_job(std::mt19937& rng, std::size_t commands) {
  const char* names[] = {"@line", "@arc", "@rapid_move", "@averyveryverylongname", "@l"};
  const char* params[] = {"xpos", "ypos", "zpos", "feed", "arc_direction", "xcenter_rel", "b", "a_b"};
  const char* values[] = {"1.5", "-0.5", "1500.0", "0", "7", "CW", "CCW", "TRUE", "1T", "2F", "'q'", "1e3",
                          "12345678901234567890", ".5", "-", "x y", "", "1x", "0.30000000000000004"};
  const char* ends[] = {"\n", "\n", "\n", "\n", "\r\n", "  \n", "\t\n", "\r\r\n", "\r \n"};
  const char* blanks[] = {" ", " ", "  ", "\t"};
  std::string text;
  for (std::size_t c = 0; c < commands; ++c) {
    const std::size_t shape = rng() % std::size(names);
    text += '(';
    text += rng() % 50 == 0 ? "12345678901" : rng() % 20 == 0 ? "0" : "1";
    text += ')';
    text += names[shape];
    text += rng() % 8 == 0 ? "" : "        ";
    text += "==>";
    const std::size_t lines = 1 + (shape == 1 ? 2 : rng() % 2);
    std::size_t param = 0;
    for (std::size_t l = 0; l < lines; ++l) {
      if (l > 0) text += rng() % 30 == 0 ? "\n" : rng() % 30 == 0 ? "  ;x\n                    ..>" : "                    ..>";
      for (std::size_t k = 0; k < 3; ++k, ++param) {
        text += blanks[rng() % std::size(blanks)];
        // The same names in the same order mostly, so that the recycled slots hold them.
        text += rng() % 25 == 0 ? params[rng() % std::size(params)] : params[(shape + param) % std::size(params)];
        text += ':';
        text += rng() % 3 == 0 ? values[rng() % std::size(values)] : values[param % 3];
      }
      text += ends[rng() % std::size(ends)];
    }
    if (rng() % 40 == 0) text += "   > N10 G1 X1\n";
  }
  return text;
}

TEST(TraceReaderFastLines, RandomJobs) {
  std::mt19937 rng(20261128);
  for (int round = 0; round < 3000; ++round) check(random_job(rng, 1 + rng() % 12));
}

// Lines cut by the end of a chunk (256 KiB) go to the general rule, which puts them together.
TEST(TraceReaderFastLines, JobsLongerThanAChunk) {
  std::mt19937 rng(20261129);
  for (int round = 0; round < 4; ++round) check(random_job(rng, 9000));
  // Every cut position, for the lines around the first chunk end.
  const std::string line = "(1)@line            ==> xpos:45.0 ypos:0.0 zpos:-0.5 feed:1500.0\n";
  const std::string arc = "(1)@arc             ==> xpos:50.0 ypos:5.0\n                    ..> radius:5.0 arc_direction:CCW\n";
  for (std::size_t shift = 0; shift < arc.size() + 2; ++shift) {
    std::string text(shift, '\n');
    while (text.size() < (std::size_t{1} << 18) + 200) text += text.size() % 2 ? line : arc;
    check(text);
  }
}

// Byte mutations of the layout's example file: whatever they make of a line, both ways agree.
TEST(TraceReaderFastLines, MutatedLayoutExample) {
  std::ifstream f("toolpath/data/solidcam_layout.trace", std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  const std::string seed = s.str();
  ASSERT_FALSE(seed.empty());
  const char alphabet[] = "()@:'\" \t\r\n.>=!TF-+eE0123456789abcXYZ_;\0";
  std::mt19937 rng(20261130);
  for (int round = 0; round < 3000; ++round) {
    std::string text = seed;
    test_support::random_edits(text, rng, std::string_view(alphabet, sizeof alphabet - 1), 1 + static_cast<int>(rng() % 4));
    check(text);
  }
}

// The fast path remembers each key's last number (trace_syntax::KeyMemo) and takes the same
// bytes again without scanning them. Numbers that share the remembered bytes and go on past them
// (`1.5` then `1.55`, `1.5e3`, `1.5T`, `1.5x`), flags, numbers too long to be remembered, words,
// and each kind of line end, in jobs where every key takes few values; read with the values
// scribbled over between commands as well.
TEST(TraceReaderFastLines, RepeatedNumbersAsTheGeneralRuleReadsThem) {
  const char* values[] = {"1", "1T", "1F", "1t", "10", "1.5", "1.5", "1.5", "1.55", "1.5e3", "1.5T", "1.5F", "1.5x",
                          "1.5.5", "1.50", "-1.5", "+1.5", "1.", ".5", "-0", "0", "-0.5", "-0.5F", "1500.0",
                          "1500.0F", "12345678", "-1234567", "123456789", "1234567.5", "12345678901234567890",
                          "1e5", "2e", "2e+", "CW", "TRUE", "1:", "1'"};
  const char* params[] = {"xpos", "ypos", "zpos", "feed"};
  const char* ends[] = {"\n", "\n", "\n", "\r\n", "  \n", "\t\n", "\r \n", "\rx\n"};
  const char* blanks[] = {" ", " ", "  ", "\t"};
  std::mt19937 rng(20261131);
  for (int round = 0; round < 2000; ++round) {
    // Each key takes one of a few values of the list most of the time.
    std::size_t pool[std::size(params)][3];
    for (auto& key : pool)
      for (std::size_t& v : key) v = rng() % std::size(values);
    std::string text;
    for (std::size_t c = 1 + rng() % 30; c > 0; --c) {
      text += rng() % 2 ? "(1)@line            ==>" : "(1)@arc             ==>";
      for (std::size_t k = 0; k < std::size(params); ++k) {
        if (k == 2 && rng() % 2) {
          text += ends[rng() % std::size(ends)];
          text += "                    ..>";
        }
        text += blanks[rng() % std::size(blanks)];
        text += params[k];
        text += ':';
        text += rng() % 10 == 0 ? values[rng() % std::size(values)] : values[pool[k][rng() % 3]];
      }
      text += ends[rng() % std::size(ends)];
    }
    const std::string general = read_all(text, true);
    ASSERT_EQ(read_all(text, false), general) << "input:\n" << text;
    ASSERT_EQ(read_all(text, false, true), general) << "input:\n" << text;
  }
}

// A remembered number near the end of a chunk, where the bytes after it are not all there: the
// lines around the chunk end read at every offset, with each line's numbers as the one before.
TEST(TraceReaderFastLines, RepeatedNumbersAtTheEndOfAChunk) {
  const std::string line = "(1)@line            ==> xpos:45.0 ypos:1 zpos:-0.5F feed:1500.0\n";
  for (std::size_t shift = 0; shift < line.size() + 2; ++shift) {
    std::string text(shift, '\n');
    while (text.size() < (std::size_t{1} << 18) + 200) text += line;
    check(text);
    ASSERT_EQ(read_all(text, false, true), read_all(text, true));
  }
}

// TraceReader::screened: a command it calls screened has every parameter passing its key's
// screen, and the need bits of all of them; random screens over the random jobs above.
TEST(TraceReaderFastLines, ScreenedCommandsPassTheirScreens) {
  std::mt19937 rng(20261202);
  std::vector<toolpath::ValueScreen> screens(toolpath::param_key_count + 1);
  std::size_t screened = 0;
  for (int round = 0; round < 2000; ++round) {
    for (toolpath::ValueScreen& e : screens) {
      e.kinds = static_cast<std::uint8_t>(rng() % 4 ? 0x1f : rng() % 32);
      e.low = rng() % 4 ? -1e300 : -1.0;
      e.high = rng() % 4 ? 1e300 : 100.0;
      e.need = static_cast<std::uint16_t>(rng() % 3 ? 0 : 1u << (rng() % 16));
    }
    const std::string text = random_job(rng, 1 + rng() % 40);
    std::istringstream in(text);
    toolpath::TraceReader reader(in, "f.trace");
    reader.screen_values(screens.data());
    toolpath::Command c;
    try {
      while (reader.next(c)) {
        std::uint32_t need = 0;
        if (!reader.screened(need)) continue;
        ++screened;
        std::uint32_t expected = 0;
        for (const toolpath::Parameter& p : c.parameters) {
          ASSERT_NE(p.key, toolpath::ParamKey::none) << p.name;
          const toolpath::ValueScreen& e = screens[static_cast<std::size_t>(p.key)];
          ASSERT_TRUE(e.passes(p.value)) << p.name << " of command " << c.index << " in\n" << text;
          expected |= e.need;
        }
        ASSERT_EQ(need, expected) << "command " << c.index << " in\n" << text;
      }
    } catch (const toolpath::InputError&) {
    }
  }
  EXPECT_GT(screened, 200u);
}

}  // namespace
