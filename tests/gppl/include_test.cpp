// Include files and @init_inc (spec 10): placement, nesting, recursion, positions in included files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support.hpp"

using namespace gppl_test;

namespace {

TEST(Include, ProceduresAndInitIncJoin) {
  auto program = gppl::compile_file("gppl/data/include/main.gpp", {});
  CapturedLines out;
  gppl::Interpreter run(program, out);
  run.start();
  run.call(*run.find_procedure("@line"));
  run.finish();
  EXPECT_EQ(out.lines, std::vector<std::string>{"L12 S"});
  EXPECT_EQ(out.procedures, std::vector<std::string>{"@line"});
}

TEST(Include, Errors) {
  EXPECT_EQ(first_file_error("gppl/data/include/self.gpp"),
            "gppl/data/include/self.gpp:1:1: error 385: Unrecognized statement: 'self.gpp' includes itself "
            "(directly or through other files)");
  EXPECT_EQ(first_file_error("gppl/data/include/ring_a.gpp"),
            "gppl/data/include/ring_b.gpp:1:1: error 385: Unrecognized statement: 'ring_a.gpp' includes itself "
            "(directly or through other files)");
  EXPECT_EQ(first_file_error("gppl/data/include/missing.gpp"),
            "gppl/data/include/missing.gpp:4:1: error 399: Can't open file 'nothere.gpp'");
  EXPECT_EQ(first_file_error("gppl/data/include/broken.gpp"),
            "gppl/data/include/broken_sub.gpp:2:9: error 389: Invalid ASSIGNMENT statement: expected ')'");
}

TEST(Include, NestingLimit) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "gppl_include_depth";
  std::filesystem::create_directories(dir);
  for (int i = 0; i <= 17; ++i) {
    std::ofstream f(dir / ("f" + std::to_string(i) + ".gpp"), std::ios::binary);
    if (i < 17) f << "inc \"f" << i + 1 << "\"\n";
    f << "@p" << i << "\nendp\n";
  }
  EXPECT_EQ(first_file_error((dir / "f1.gpp").string()), "no error");  // f1 .. f17: 16 levels of inclusion
  const std::string deep = first_file_error((dir / "f0.gpp").string());
  EXPECT_NE(deep.find("f16.gpp:1:1: error 385: Unrecognized statement: includes nest deeper than 16 levels"),
            std::string::npos)
      << deep;
}

TEST(Include, IncludePathsAndExtension) {
  gppl::CompileOptions options;
  options.include_paths.push_back("gppl/data/include");
  auto program = gppl::compile_source("inc 'sub.gpp'\n@t\ncall @from_sub\nendp\n", "elsewhere/x.gpp", options);
  CapturedLines out;
  gppl::Interpreter run(program, out);
  run.start();
  run.call(*run.find_procedure("@t"));
  run.finish();
  EXPECT_EQ(out.lines, std::vector<std::string>{" S"});
}

}  // namespace
