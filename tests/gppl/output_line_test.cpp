// The interpreter's output line buffer against std::string: random appends of every short length
// (each has its own copy path), fills, inserts, blank removal, shrinking and direct writes through
// room()/commit(), far past the first allocation so that growing keeps the text.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "gppl/builtins/display_format.hpp"
#include "gppl/run/output_line.hpp"

namespace {

TEST(OutputLine, BehavesAsAStringUnderRandomEdits) {
  std::mt19937 random(25);
  const std::string alphabet = "XYZ. -0123456789";
  for (int round = 0; round < 200; ++round) {
    gppl::OutputLine line;
    std::string expected;
    for (int step = 0; step < 60; ++step) {
      switch (random() % 6) {
        case 0:
        case 1: {  // lengths 0 to 40: the byte, word and memcpy paths and their edges
          std::string text(random() % 41, ' ');
          for (char& c : text) c = alphabet[random() % alphabet.size()];
          line.append(text);
          expected += text;
          break;
        }
        case 2: {
          const std::size_t n = random() % 20;
          line.append_fill(n, ' ');
          expected.append(n, ' ');
          break;
        }
        case 3: {
          const std::size_t at = expected.empty() ? 0 : random() % (expected.size() + 1);
          line.insert(at, '#');
          expected.insert(at, 1, '#');
          break;
        }
        case 4: {  // what the printer does: write past the end, keep part of it
          char* p = line.room(64);
          const std::size_t kept = random() % 64;
          for (std::size_t i = 0; i < 64; ++i) p[i] = static_cast<char>('a' + i % 26);
          line.commit(p + kept);
          for (std::size_t i = 0; i < kept; ++i) expected += static_cast<char>('a' + i % 26);
          break;
        }
        default:
          if (random() % 4 == 0) {
            line.remove_all(' ');
            std::erase(expected, ' ');
          } else {
            const std::size_t n = random() % (expected.size() + 2);
            line.shrink(n);
            if (n < expected.size()) expected.resize(n);
          }
      }
      ASSERT_EQ(line.view(), expected) << "round " << round << ", step " << step;
      ASSERT_EQ(line.size(), expected.size());
    }
    line.clear();
    EXPECT_TRUE(line.empty());
  }
}

TEST(OutputLine, TakesAFormattedNumberWrittenInPlace) {
  gppl::OutputLine line;
  line.append("N10 X");
  const gppl::DisplayFormat f = gppl::parse_display_format("<> 5.3(p) <;>");
  line.commit(gppl::write_formatted(line.room(gppl::formatted_room), f, gppl::Value::of_numeric(-12.5)));
  EXPECT_EQ(line.view(), "N10 X-12.5;");
  // Option d suppresses the whole item, affixes included: nothing is kept.
  const gppl::DisplayFormat d = gppl::parse_display_format("<Q> 5.3(d)");
  line.commit(gppl::write_formatted(line.room(gppl::formatted_room), d, gppl::Value::of_numeric(0.0)));
  EXPECT_EQ(line.view(), "N10 X-12.5;");
}

}  // namespace
