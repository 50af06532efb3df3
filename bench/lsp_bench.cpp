// The language server's answer time for a big post: an editor changes one line, the server checks
// the whole post again and publishes its diagnostics. The bar is 50 ms for an 80 KB post.
// usage: lsp_bench [POST.gpp] [CHANGES=30]   (Release build). Without a post, an 80 KB one is made
// of the shipped Fanuc post's procedures, renamed, as long real posts repeat their procedures.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lsp/server.hpp"

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Copies of a post's own procedures (not the toolpath's: those may be defined once) up to `bytes`.
std::string big_post(std::size_t bytes) {
  const std::string fanuc = slurp("machines/fanuc/fanuc.gpp");
  std::string out = fanuc;
  for (int copy = 1; out.size() < bytes; ++copy) {
    std::istringstream lines(fanuc);
    std::string line;
    bool in_procedure = false;
    while (std::getline(lines, line)) {
      if (!line.empty() && line[0] == '@') {
        in_procedure = true;
        const std::size_t end = line.find_first_of(" (\t");
        line = fmt::format("@copy{}_{}{}", copy, line.substr(1, end == std::string::npos ? end : end - 1),
                           end == std::string::npos ? "" : line.substr(end));
      }
      if (in_procedure) out += line + '\n';
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string post = argc > 1 ? slurp(argv[1]) : big_post(80 * 1024);
  const int changes = argc > 2 ? std::stoi(argv[2]) : 30;
  if (post.empty()) {
    fmt::print(stderr, "lsp_bench: cannot read {} (run from the source folder without a post)\n", argc > 1 ? argv[1] : "");
    return 2;
  }
  std::size_t published = 0, problems = 0;
  lsp::Server server([&](std::string m) {
    const auto j = nlohmann::json::parse(m);
    if (j.value("method", "") == "textDocument/publishDiagnostics") {
      ++published;
      problems = j["params"]["diagnostics"].size();
    }
  });
  using json = nlohmann::json;
  // A real post is opened where it lies, so that the machine file beside it is used, as in an editor.
  const std::string uri =
      argc > 1 ? "file://" + std::filesystem::absolute(argv[1]).string() : std::string("file:///bench/post.gpp");
  server.handle(json{{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}, {"params", json::object()}}.dump());
  server.handle(json{{"jsonrpc", "2.0"}, {"method", "textDocument/didOpen"},
                     {"params", {{"textDocument", {{"uri", uri}, {"version", 1}, {"text", post}}}}}}.dump());
  std::vector<double> ms;
  for (int i = 0; i < changes; ++i) {  // an edit on the first line: a comment that grows
    const json change = {{"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}}},
                         {"text", i % 2 ? "; \n" : ";x\n"}};
    const std::string message = json{{"jsonrpc", "2.0"}, {"method", "textDocument/didChange"},
                                     {"params", {{"textDocument", {{"uri", uri}, {"version", i + 2}}},
                                                 {"contentChanges", json::array({change})}}}}.dump();
    const auto start = std::chrono::steady_clock::now();
    server.handle(message);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  fmt::print("post {} KB, {} changes: change to diagnostics median {:.1f} ms, max {:.1f} ms ({} published, {} "
             "diagnostics each)\n",
             post.size() / 1024, changes, ms[ms.size() / 2], ms.back(), published, problems);
  return 0;
}
