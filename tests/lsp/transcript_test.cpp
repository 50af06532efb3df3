// Language server conversations as golden transcripts: transcripts/<case>/client.jsonl holds what
// the editor sends, one message a line, and server.jsonl what the server must answer, one message a
// line, in order. `${TESTS}` stands for the absolute path of tests/ (file URIs); a line
// {"$open": "PATH"} opens that file (relative to tests/) with its text, as an editor does.
// POSTPROC_UPDATE_GOLDEN=1 rewrites server.jsonl (review the diff before committing).
//
// And the promise of the server: its diagnostics are `postproc check`'s, for every post we have.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "lsp/server.hpp"
#include "postproc/checks/post_check.hpp"
#include "prp/prp.hpp"
#include "tests/support/golden_file.hpp"

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

const fs::path kRoot = "lsp/transcripts";

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

class Transcript : public ::testing::TestWithParam<std::string> {};

TEST_P(Transcript, ServerAnswersAsRecorded) {
  const fs::path dir = kRoot / GetParam();
  const std::string tests = fs::absolute(".").lexically_normal().string();
  const std::string tests_dir = tests.back() == '/' ? tests.substr(0, tests.size() - 1) : tests;
  std::string answers;
  lsp::Server server([&](std::string m) { answers += replace_all(std::move(m), tests_dir, "${TESTS}") + '\n'; });
  std::istringstream client(test_support::slurp(dir / "client.jsonl"));
  std::string line;
  while (std::getline(client, line)) {
    if (line.empty()) continue;
    line = replace_all(line, "${TESTS}", tests_dir);
    const json message = json::parse(line, nullptr, false);
    if (!message.is_discarded() && message.is_object() && message.contains("$open")) {
      const std::string path = message["$open"].get<std::string>();
      server.handle(json{{"jsonrpc", "2.0"},
                         {"method", "textDocument/didOpen"},
                         {"params", {{"textDocument", {{"uri", "file://" + tests_dir + "/" + path},
                                                       {"languageId", "gppl"},
                                                       {"version", 1},
                                                       {"text", test_support::slurp(path)}}}}}}
                        .dump());
      continue;
    }
    server.handle(line);
  }
  test_support::expect_golden(dir / "server.jsonl", answers);
}

INSTANTIATE_TEST_SUITE_P(Lsp, Transcript, ::testing::ValuesIn(test_support::subfolders(kRoot)), [](const auto& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

// The server's diagnostics for a post are `postproc check --prp <the machine file beside it>`'s:
// the same positions (for ASCII text), severities, numbers and messages.
TEST(LspDiagnostics, EqualCheckForEveryPostWeHave) {
  std::size_t posts = 0;
  for (const char* root : {"../machines", "golden", "lsp"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      if (entry.path().extension() != ".gpp") continue;
      ++posts;
      const std::string path = fs::absolute(entry.path()).lexically_normal().string();
      SCOPED_TRACE(path);
      // check's side, with the machine file beside the post as --prp
      std::optional<prp::MachineParameters> machine;
      for (const char* ext : {".prp", ".vmid", ".mac"}) {
        const fs::path candidate = fs::path(path).replace_extension(ext);
        if (!fs::exists(candidate)) continue;
        try {
          machine = prp::load_file(candidate.string(), prp::Units::Metric);
        } catch (const std::exception&) {
        }
        break;
      }
      postproc::PostCheckOptions options;
      if (machine) options.machine = &*machine;
      std::vector<std::string> expected;
      for (const auto& d : postproc::check_post_file(path, options))
        if (d.where.file == path)
          expected.push_back(fmt::format("{}:{} {} {} {}", d.where.line, d.where.column, d.error() ? "error" : "warning",
                                         d.number, d.message));
      // the server's side
      std::vector<std::string> got;
      bool published = false;
      const std::string uri = "file://" + path;
      lsp::Server server([&](std::string m) {
        const json j = json::parse(m);
        if (j.value("method", "") != "textDocument/publishDiagnostics" || j["params"]["uri"] != uri) return;
        published = true;
        for (const auto& d : j["params"]["diagnostics"])
          got.push_back(fmt::format("{}:{} {} {} {}", d["range"]["start"]["line"].get<int>() + 1,
                                    d["range"]["start"]["character"].get<int>() + 1, d["severity"] == 1 ? "error" : "warning",
                                    d.value("code", 0), d["message"].get<std::string>()));
      });
      server.handle(R"({"jsonrpc":"2.0","id":1,"method":"initialize","params":{}})");
      server.handle(json{{"jsonrpc", "2.0"},
                         {"method", "textDocument/didOpen"},
                         {"params", {{"textDocument", {{"uri", uri}, {"version", 1}, {"text", test_support::slurp(path)}}}}}}
                        .dump());
      EXPECT_TRUE(published);
      EXPECT_EQ(got, expected);
    }
  }
  EXPECT_GE(posts, 15u);
}

}  // namespace
