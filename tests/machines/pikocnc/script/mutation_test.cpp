// Bad scripts end in an InputError with a position, never in a crash or a hang: the golden
// scripts and the example, mutated deterministically, parsed and run with a small step budget.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "machines/pikocnc/script/script.hpp"

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ScriptMutations, NeverCrashOrHang) {
  std::vector<std::string> seeds = {slurp("../machines/pikocnc/scripts/front.pas")};
  for (const auto& dir : fs::directory_iterator("machines/pikocnc/script/golden"))
    seeds.push_back(slurp(dir.path() / "script.pas"));
  const std::vector<std::string> pieces = {"begin", "end", ";", "(", ")", "[", "]", ":=", "'", "\"", "{", "(*", "0",
                                           "1.5e308", "2147483647", "$", "#", "div", "mod", "not", "-", "/", "if",
                                           "then", "else", "while", "do", "for", "to", "repeat", "until", "var",
                                           "x", "TPoint", "record", "array", "of", "..", ".", ",", "procedure",
                                           "function", "Result", "exit", "break", "case", "Write", "SetG(300)"};
  std::mt19937 rng(20260620);
  int errors = 0, runs = 0;
  for (int round = 0; round < 800; ++round) {
    std::string text = seeds[rng() % seeds.size()];
    const int edits = 1 + int(rng() % 4);
    for (int k = 0; k < edits && !text.empty(); ++k) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 4) {
        case 0: text.erase(at, 1 + rng() % 8); break;
        case 1: text.insert(at, pieces[rng() % pieces.size()]); break;
        case 2: text[at] = char(rng() % 128); break;
        default: text.insert(at, text.substr(rng() % text.size(), rng() % 40)); break;
      }
    }
    pikocnc::script::RunInputs inputs;
    inputs.max_steps = 20000;
    inputs.ordered_answers = {true, false};
    std::ostringstream out, diag;
    try {
      pikocnc::script::run_script_text(text, "m.pas", inputs, out, diag);
      ++runs;
    } catch (const toolpath::InputError& e) {
      ++errors;
      EXPECT_EQ(std::string(e.what()).rfind("m.pas:", 0), 0u) << e.what();
    }
  }
  EXPECT_GT(errors, 100);
  EXPECT_GT(runs, 10);
}

}  // namespace
