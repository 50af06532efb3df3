// The editor's index of a post's names (gppl/symbols.hpp): every declaration and use the compiler
// resolved, with its symbol, also when the compile fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "gppl/gppl.hpp"
#include "gppl/symbols.hpp"

namespace {

std::string_view kind_name(gppl::SymbolKind k) {
  switch (k) {
    case gppl::SymbolKind::System: return "system";
    case gppl::SymbolKind::Host: return "host";
    case gppl::SymbolKind::Global: return "global";
    case gppl::SymbolKind::Local: return "local";
    case gppl::SymbolKind::Procedure: return "procedure";
  }
  return "?";
}

// "line:column+length name (kind)[ decl]" for every use, in compile order.
std::vector<std::string> uses(const gppl::SymbolIndex& index) {
  std::vector<std::string> out;
  for (const auto& u : index.uses) {
    const gppl::Symbol& s = index.symbols[u.symbol];
    out.push_back(fmt::format("{}:{}+{} {} ({}){}", u.line, u.column, u.length, s.name, kind_name(s.kind),
                              u.declaration ? " decl" : ""));
  }
  return out;
}

TEST(SymbolIndex, DeclarationsAndUsesAsTheCompilerResolvesThem) {
  gppl::SymbolIndex index;
  gppl::CompileOptions options;
  options.symbols = &index;
  gppl::compile_source(
      "@init_post\n"                // 1
      "  global numeric cut\n"      // 2
      "endp\n"                      // 3
      "@line\n"                     // 4
      "  local integer n\n"         // 5
      "  n = 2\n"                   // 6
      "  cut = xpos * N\n"          // 7
      "  call @helper(n)\n"         // 8
      "endp\n"                      // 9
      "@helper(integer k)\n"        // 10
      "  {nb, 'X' cut, k}\n"        // 11
      "  blknum = 1\n"              // 12
      "endp\n",
      "p.gpp", options);
  EXPECT_EQ(uses(index), (std::vector<std::string>{
                             "1:1+10 @init_post (procedure) decl",
                             "4:1+5 @line (procedure) decl",
                             "10:1+7 @helper (procedure) decl",
                             "2:18+3 cut (global) decl",
                             "5:17+1 n (local) decl",
                             "10:17+1 k (local) decl",
                             "6:3+1 n (local)",
                             "7:3+3 cut (global)",
                             "7:9+4 xpos (system)",
                             "7:16+1 n (local)",
                             "8:8+7 @helper (procedure)",
                             "8:16+1 n (local)",
                             "11:12+3 cut (global)",
                             "11:17+1 k (local)",
                             "12:3+6 blknum (system)",
                         }));
  ASSERT_EQ(index.files, std::vector<std::string>{"p.gpp"});
  // A local knows its procedure; a global its declaration wherever it is first used.
  const auto& symbols = index.symbols;
  const auto n = std::find_if(symbols.begin(), symbols.end(), [](const auto& s) { return s.name == "n"; });
  ASSERT_NE(n, symbols.end());
  EXPECT_EQ(symbols[n->procedure].name, "@line");
  EXPECT_EQ(n->type, gppl::Type::Integer);
  const auto blknum = std::find_if(symbols.begin(), symbols.end(), [](const auto& s) { return s.name == "blknum"; });
  ASSERT_NE(blknum, symbols.end());
  EXPECT_FALSE(blknum->declared);
}

TEST(SymbolIndex, KeptWhenTheCompileFails) {
  gppl::SymbolIndex index;
  gppl::CompileOptions options;
  options.symbols = &index;
  options.implicit_host_variables = false;
  EXPECT_THROW(gppl::compile_source("@line\n  global integer count\n  count = cuont + 1\n  call @nowhere\nendp\n",
                                    "p.gpp", options),
               gppl::Errors);
  EXPECT_EQ(uses(index), (std::vector<std::string>{"1:1+5 @line (procedure) decl", "2:18+5 count (global) decl",
                                                   "3:3+5 count (global)"}));
}

TEST(SymbolIndex, NothingIsKeptWithoutAnIndex) {
  // The default options keep no index (and cost nothing for it).
  EXPECT_NO_THROW(gppl::compile_source("@line\n  blknum = 1\nendp\n", "p.gpp", {}));
}

}  // namespace
