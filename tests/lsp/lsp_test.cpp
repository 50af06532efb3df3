// The language server (`postproc lsp`), driven as an editor drives it: framed JSON-RPC messages in,
// responses and diagnostics out. Positions in the requests are the protocol's (0-based lines,
// UTF-16 characters).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lsp/server.hpp"
#include "lsp/transport.hpp"

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

// An editor: sends requests and notifications, keeps what the server sent.
class Client {
public:
  Client() : server_([this](std::string m) { sent_.push_back(json::parse(m)); }) {}

  json request(const std::string& method, json params = json::object()) {
    const int id = ++id_;
    server_.handle(json{{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}}.dump());
    for (auto it = sent_.rbegin(); it != sent_.rend(); ++it)
      if (it->contains("id") && (*it)["id"] == id) return *it;
    return json();
  }
  void notify(const std::string& method, json params = json::object()) {
    server_.handle(json{{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}}.dump());
  }
  void raw(std::string_view text) { server_.handle(text); }
  json initialize() { return request("initialize", {{"capabilities", json::object()}}); }
  void open(const std::string& uri, const std::string& text) {
    notify("textDocument/didOpen", {{"textDocument", {{"uri", uri}, {"languageId", "gppl"}, {"version", 1}, {"text", text}}}});
  }
  // The last diagnostics published for `uri`: "line:character-line:character severity code message".
  std::vector<std::string> diagnostics(const std::string& uri) const {
    for (auto it = sent_.rbegin(); it != sent_.rend(); ++it) {
      if (it->value("method", "") != "textDocument/publishDiagnostics" || (*it)["params"]["uri"] != uri) continue;
      std::vector<std::string> out;
      for (const auto& d : (*it)["params"]["diagnostics"]) {
        const auto& r = d["range"];
        out.push_back(std::to_string(r["start"]["line"].get<int>()) + ":" + std::to_string(r["start"]["character"].get<int>()) +
                      "-" + std::to_string(r["end"]["line"].get<int>()) + ":" + std::to_string(r["end"]["character"].get<int>()) +
                      (d["severity"] == 1 ? " error " : " warning ") + (d.contains("code") ? d["code"].dump() + " " : "") +
                      d["message"].get<std::string>());
      }
      return out;
    }
    return {"(none published)"};
  }
  lsp::Server& server() { return server_; }

private:
  lsp::Server server_;
  std::vector<json> sent_;
  int id_ = 0;
};

json at(const std::string& uri, int line, int character) {
  return {{"textDocument", {{"uri", uri}}}, {"position", {{"line", line}, {"character", character}}}};
}

json with(json params, const json& more) {
  params.update(more);
  return params;
}

// A folder with a post, its include and its machine file, removed at the end.
struct Folder {
  fs::path dir = fs::temp_directory_path() / ("postproc-lsp-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Folder() { fs::create_directories(dir); }
  ~Folder() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name, std::ios::binary) << text;
    return (dir / name).string();
  }
  std::string uri(const std::string& name) const { return "file://" + (dir / name).string(); }
};

const std::string kPost =
    "@init_post\n"                       // 0
    "  global numeric depth_left\n"      // 1
    "  numeric_def_f = '5.3(p)'\n"       // 2
    "endp\n"                             // 3
    "@line\n"                            // 4
    "  local integer passes\n"           // 5
    "  passes = 2\n"                     // 6
    "  depth_left = xpos * passes\n"     // 7
    "  call @helper(passes)\n"           // 8
    "  {nb, 'X' depth_left}\n"           // 9
    "endp\n"                             // 10
    "@helper(integer k)\n"               // 11
    "  if k > 1\n"                       // 12
    "    depth_left = sqrt(k)\n"         // 13
    "  endif\n"                          // 14
    "endp\n";                            // 15

TEST(LspTransport, FramesAsTheProtocolSendsThem) {
  struct Case {
    const char* name;
    std::string bytes;
    std::vector<std::string> frames;  // "message:<body>", "malformed:<error>", "end"
  } cases[] = {
      {"one message", "Content-Length: 2\r\n\r\n{}", {"message:{}", "end"}},
      {"with a content type, LF only", "Content-Type: application/vscode-jsonrpc; charset=utf-8\nContent-Length: 5\n\n[1,2]",
       {"message:[1,2]", "end"}},
      {"a length shorter than the body: the rest is no header", "Content-Length: 1\r\n\r\n12\r\n\r\n",
       {"message:1", "malformed:a header line without `:`: `2`", "end"}},
      {"two in a row", "Content-Length: 1\r\n\r\n1Content-Length: 1\r\n\r\n2", {"message:1", "message:2", "end"}},
      {"no length", "X: 1\r\n\r\n", {"malformed:no Content-Length header", "end"}},
      {"a length that is no number", "Content-Length: 1x\r\n\r\nContent-Length: 1\r\n\r\n7",
       {"malformed:Content-Length is not a number: `1x`", "message:7", "end"}},
      {"too long, skipped", "Content-Length: 40\r\n\r\n" + std::string(40, 'a') + "Content-Length: 1\r\n\r\n5",
       {"malformed:a message of 40 bytes, more than the 16 taken", "message:5", "end"}},
      {"the input ends inside a message", "Content-Length: 10\r\n\r\n{}", {"end"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    std::istringstream in(c.bytes);
    std::vector<std::string> got;
    for (int i = 0; i < 10; ++i) {
      const lsp::Frame f = lsp::read_frame(in, 16);
      if (f.status == lsp::FrameStatus::End) {
        got.push_back("end");
        break;
      }
      got.push_back(f.status == lsp::FrameStatus::Message ? "message:" + f.body : "malformed:" + f.error);
    }
    EXPECT_EQ(got, c.frames);
  }
  std::ostringstream out;
  lsp::write_frame(out, "{}");
  EXPECT_EQ(out.str(), "Content-Length: 2\r\n\r\n{}");
}

TEST(LspLifecycle, ErrorsForWhatIsNotARequestItCanAnswer) {
  Client c;
  EXPECT_EQ(c.request("textDocument/hover", at("file:///p.gpp", 0, 0))["error"]["code"], -32002);
  const json init = c.initialize();
  EXPECT_TRUE(init["result"]["capabilities"]["hoverProvider"].get<bool>());
  EXPECT_EQ(init["result"]["capabilities"]["textDocumentSync"]["change"], 2);
  EXPECT_EQ(c.request("no/such/method")["error"]["code"], -32601);
  EXPECT_EQ(c.request("textDocument/hover", {{"textDocument", {{"uri", "file:///p.gpp"}}}})["error"]["code"], -32803);
  c.open("file:///p.gpp", "@line\nendp\n");
  EXPECT_EQ(c.request("textDocument/hover", {{"textDocument", {{"uri", "file:///p.gpp"}}}})["error"]["code"], -32602);
  c.raw("{not json");
  c.raw("[1, 2]");
  c.raw("{\"jsonrpc\": \"2.0\", \"id\": 77}");
  EXPECT_FALSE(c.server().exited());
  EXPECT_TRUE(c.request("shutdown")["result"].is_null());
  EXPECT_EQ(c.request("textDocument/hover", at("file:///p.gpp", 0, 0))["error"]["code"], -32600);
  c.notify("exit");
  EXPECT_TRUE(c.server().exited());
  EXPECT_EQ(c.server().exit_code(), 0);
}

TEST(LspDiagnostics, WhatCheckFindsAsTheUserTypes) {
  Client c;
  c.initialize();
  const std::string uri = "file:///tmp/p.gpp";
  c.open(uri, "@line\n  n = blknun + 1\nendp\n@rapid_mvoe\nendp\n");
  EXPECT_EQ(c.diagnostics(uri), (std::vector<std::string>{
                                    "1:2-1:3 error 404 Symbol 'n' does not exist",
                                    "1:6-1:12 error 383 Variable 'blknun' is not defined: did you mean 'blknum'?",
                                }));
  // Incremental changes: fix the typo, declare n; the warnings of a compiling post come then.
  c.notify("textDocument/didChange",
           {{"textDocument", {{"uri", uri}, {"version", 2}}},
            {"contentChanges", json::array({{{"range", {{"start", {{"line", 1}, {"character", 6}}},
                                                        {"end", {{"line", 1}, {"character", 12}}}}},
                                             {"text", "blknum"}},
                                            {{"range", {{"start", {{"line", 1}, {"character", 0}}},
                                                        {"end", {{"line", 1}, {"character", 0}}}}},
                                             {"text", "  local integer n\n"}}})}});
  EXPECT_EQ(c.diagnostics(uri), (std::vector<std::string>{
                                    "4:0-4:11 warning @rapid_mvoe: not a command and never called; did you mean "
                                    "@rapid_move?"}));
  c.notify("textDocument/didChange", {{"textDocument", {{"uri", uri}, {"version", 3}}},
                                      {"contentChanges", json::array({{{"text", "@line\nendp\n"}}})}});
  EXPECT_EQ(c.diagnostics(uri), std::vector<std::string>{});
  c.notify("textDocument/didClose", {{"textDocument", {{"uri", uri}}}});
  EXPECT_EQ(c.diagnostics(uri), std::vector<std::string>{});
}

TEST(LspDiagnostics, TheMachineFileBesideThePostAndItsOwnErrors) {
  Folder f;
  f.write("mill.prp", "; machine\n@pre_processor\noptions = SpindleWarmup NUMERIC\nendp\n");
  Client c;
  c.initialize();
  c.open(f.uri("mill.gpp"), "@start_of_file\n  {nb, 'G4 P' SpindleWarmup}\nendp\n");
  EXPECT_EQ(c.diagnostics(f.uri("mill.gpp")), std::vector<std::string>{});
  c.open(f.uri("other.gpp"), "@start_of_file\n  {nb, 'G4 P' SpindleWarmup}\nendp\n");
  ASSERT_EQ(c.diagnostics(f.uri("other.gpp")).size(), 1u);
  c.open(f.uri("broken.prp"), "@pre_processor\narc_max_angle = abc\nendp\n");
  EXPECT_EQ(c.diagnostics(f.uri("broken.prp")),
            std::vector<std::string>{"1:16-1:19 error expected a number, or number ',' number, found `abc`"});
}

TEST(LspNavigation, DefinitionReferencesAndRenameAcrossAnInclude) {
  Folder f;
  f.write("common.inc", "@helper(integer k)\n  blknum = k\nendp\n");
  const std::string post = "@line\n  local integer passes\n  passes = 2\n  call @helper(passes)\nendp\ninclude 'common.inc'\n";
  f.write("post.gpp", post);
  Client c;
  c.initialize();
  const std::string uri = f.uri("post.gpp");
  c.open(uri, post);
  ASSERT_EQ(c.diagnostics(uri), std::vector<std::string>{});
  const json def = c.request("textDocument/definition", at(uri, 3, 10))["result"];  // @helper in the call
  EXPECT_EQ(def["uri"], f.uri("common.inc"));
  EXPECT_EQ(def["range"]["start"], (json{{"line", 0}, {"character", 0}}));
  const json refs = c.request("textDocument/references", with(at(uri, 2, 3), {{"context", {{"includeDeclaration", true}}}}))["result"];
  ASSERT_EQ(refs.size(), 3u);  // the declaration, the assignment, the argument
  EXPECT_EQ(refs[0]["range"]["start"], (json{{"line", 1}, {"character", 16}}));
  const json edit = c.request("textDocument/rename", with(at(uri, 3, 10), {{"newName", "@set_block"}}))["result"];
  ASSERT_EQ(edit["changes"].size(), 2u);
  EXPECT_EQ(edit["changes"][f.uri("common.inc")][0]["newText"], "@set_block");
  EXPECT_EQ(c.request("textDocument/rename", with(at(uri, 3, 10), {{"newName", "set_block"}}))["error"]["message"],
            "'set_block' is no procedure (@name) name");
  EXPECT_EQ(c.request("textDocument/rename", with(at(uri, 0, 2), {{"newName", "@other"}}))["error"]["message"],
            "@line runs for the toolpath's @line commands: renamed, it would never run");
}

TEST(LspEditing, CompletionHoverSymbolsFoldingSignatures) {
  Client c;
  c.initialize();
  const std::string uri = "file:///tmp/edit.gpp";
  c.open(uri, kPost);
  auto labels = [](const json& r) {
    std::vector<std::string> out;
    for (const auto& i : r["result"]["items"]) out.push_back(i["label"]);
    return out;
  };
  // In @helper, `dep` offers the post's global first, then SolidCAM's names; `pas` no local of @line.
  const auto dep = labels(c.request("textDocument/completion", at(uri, 13, 7)));
  ASSERT_FALSE(dep.empty());
  EXPECT_EQ(dep.front(), "depth_left");
  EXPECT_NE(std::find(dep.begin(), dep.end(), "depth"), dep.end());
  const json xp = c.request("textDocument/completion", at(uri, 7, 17));  // "xpos" typed up to "xp"
  const auto xpos = std::find_if(xp["result"]["items"].begin(), xp["result"]["items"].end(),
                                 [](const json& i) { return i["label"] == "xpos"; });
  ASSERT_NE(xpos, xp["result"]["items"].end());
  EXPECT_EQ((*xpos)["detail"], "system numeric");
  EXPECT_NE((*xpos)["documentation"]["value"].get<std::string>().find("from the trace"), std::string::npos);
  c.notify("textDocument/didChange", {{"textDocument", {{"uri", uri}, {"version", 2}}},
                                      {"contentChanges", json::array({{{"text", kPost + "@x\n  pas\n  call @he\nendp\n@ra"}}})}});
  EXPECT_EQ(labels(c.request("textDocument/completion", at(uri, 18, 10))), std::vector<std::string>{"@helper"});
  const auto commands = labels(c.request("textDocument/completion", at(uri, 20, 3)));
  EXPECT_NE(std::find(commands.begin(), commands.end(), "@rapid_move"), commands.end());
  // Hover: a global, a system variable, a display format, a built-in function.
  const auto hover = [&](int line, int character) {
    return c.request("textDocument/hover", at(uri, line, character))["result"]["contents"]["value"].get<std::string>();
  };
  EXPECT_EQ(hover(7, 4), "```gppl\nnumeric depth_left\n```\nglobal, declared at /tmp/edit.gpp:2");
  EXPECT_NE(hover(7, 16).find("numeric xpos"), std::string::npos);
  EXPECT_NE(hover(2, 20).find("| -0.125 | `-0.125` |"), std::string::npos);
  EXPECT_EQ(hover(13, 18), "```gppl\nnumeric sqrt(numeric)\n```\nbuilt-in function");
  EXPECT_EQ(hover(6, 4).find("```gppl\ninteger passes\n```\nlocal of @line"), 0u);
  // Signature help inside sqrt( ).
  const json sig = c.request("textDocument/signatureHelp", at(uri, 13, 22))["result"];
  EXPECT_EQ(sig["signatures"][0]["label"], "numeric sqrt(numeric)");
  EXPECT_EQ(sig["activeParameter"], 0);
  // Symbols: the procedures with their bodies, the global.
  const json symbols = c.request("textDocument/documentSymbol", {{"textDocument", {{"uri", uri}}}})["result"];
  std::vector<std::string> names;
  for (const auto& s : symbols) names.push_back(s["name"].get<std::string>() + "@" + s["range"]["end"]["line"].dump());
  EXPECT_EQ(names, (std::vector<std::string>{"@init_post@3", "@line@10", "@helper@15", "@x@19", "@ra@20", "depth_left@1"}));
  const json folds = c.request("textDocument/foldingRange", {{"textDocument", {{"uri", uri}}}})["result"];
  std::vector<std::string> spans;
  for (const auto& r : folds) spans.push_back(r["startLine"].dump() + "-" + r["endLine"].dump());
  EXPECT_EQ(spans, (std::vector<std::string>{"0-3", "4-10", "12-13", "11-15", "16-19"}));
}

// Inside the string of a format assignment, completion offers display formats with what they print.
TEST(LspEditing, DisplayFormatSnippets) {
  Client c;
  c.initialize();
  const std::string uri = "file:///tmp/formats.gpp";
  c.open(uri, "@init_post\n  xpos_f = '5.\n  {nb, 'X' xpos:'4}\nendp\n");
  const json r = c.request("textDocument/completion", at(uri, 1, 14))["result"];
  std::vector<std::string> labels;
  for (const auto& i : r["items"]) labels.push_back(i["label"]);
  EXPECT_EQ(labels, (std::vector<std::string>{"5.3", "5.3(p)", "4.3(p)", "5.0(p)", "2.0(p)", "5.3/1", "<X> 5.3 <>"}));
  const json& p = r["items"][1];
  EXPECT_EQ(p["textEdit"]["range"], (json{{"start", {{"line", 1}, {"character", 12}}}, {"end", {{"line", 1}, {"character", 14}}}}));
  EXPECT_NE(p["documentation"]["value"].get<std::string>().find("| 3 | `3` |"), std::string::npos);
  EXPECT_EQ(c.request("textDocument/completion", at(uri, 2, 17))["result"]["items"].size(), 7u);  // an item's :'format'
  EXPECT_GT(c.request("textDocument/completion", at(uri, 2, 10))["result"]["items"].size(), 0u);   // 'X': no format
  EXPECT_NE(c.request("textDocument/completion", at(uri, 2, 10))["result"]["items"][0]["kind"], 15);
}

TEST(LspEditing, QuickFixes) {
  Client c;
  c.initialize();
  const std::string uri = "file:///tmp/fix.gpp";
  c.open(uri, "@line\n  n = blknun\nendp\n");
  const json diagnostics = json::array({{{"range", {{"start", {{"line", 1}, {"character", 6}}}, {"end", {{"line", 1}, {"character", 12}}}}},
                                         {"code", 383},
                                         {"message", "Variable 'blknun' is not defined: did you mean 'blknum'?"}},
                                        {{"range", {{"start", {{"line", 1}, {"character", 2}}}, {"end", {{"line", 1}, {"character", 3}}}}},
                                         {"code", 404},
                                         {"message", "Symbol 'n' does not exist"}}});
  const json actions = c.request("textDocument/codeAction", {{"textDocument", {{"uri", uri}}},
                                                             {"range", diagnostics[0]["range"]},
                                                             {"context", {{"diagnostics", diagnostics}}}})["result"];
  std::vector<std::string> titles;
  for (const auto& a : actions) titles.push_back(a["title"]);
  EXPECT_EQ(titles, (std::vector<std::string>{"Change to blknum", "Declare 'blknun' as a local numeric of @line",
                                              "Declare 'blknun' as a local integer of @line",
                                              "Declare 'blknun' as a local string of @line",
                                              "Declare 'blknun' as a local logical of @line",
                                              "Declare 'n' as a local numeric of @line", "Declare 'n' as a local integer of @line",
                                              "Declare 'n' as a local string of @line", "Declare 'n' as a local logical of @line"}));
  EXPECT_EQ(actions[0]["edit"]["changes"][uri][0]["newText"], "blknum");
  EXPECT_EQ(actions[5]["edit"]["changes"][uri][0],
            (json{{"range", {{"start", {{"line", 1}, {"character", 0}}}, {"end", {{"line", 1}, {"character", 0}}}}},
                  {"newText", "  local numeric n\n"}}));
}

// Text edits applied as an editor applies them (from the last to the first).
std::string apply_edits(std::string text, const json& edits) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') starts.push_back(i + 1);
  std::vector<json> sorted(edits.begin(), edits.end());
  std::sort(sorted.begin(), sorted.end(), [](const json& a, const json& b) {
    return a["range"]["start"]["line"].get<int>() > b["range"]["start"]["line"].get<int>();
  });
  for (const json& e : sorted) {  // ASCII posts: characters are bytes
    const std::size_t begin = starts[e["range"]["start"]["line"].get<std::size_t>()] + e["range"]["start"]["character"].get<std::size_t>();
    const std::size_t end = starts[e["range"]["end"]["line"].get<std::size_t>()] + e["range"]["end"]["character"].get<std::size_t>();
    text.replace(begin, end - begin, e["newText"].get<std::string>());
  }
  return text;
}

TEST(LspEditing, FormattingIndentsBlocksAndNothingElse) {
  Client c;
  c.initialize();
  const std::string uri = "file:///tmp/format.gpp";
  c.open(uri, "; top\n@line\nif xpos > 0 ; cut\n{nb, 'G1'}\n      else\nwhile blknum < 3\n blknum = blknum + 1\n   endw\n  endif\n\n    endp\n");
  const json edits = c.request("textDocument/formatting", {{"textDocument", {{"uri", uri}}},
                                                           {"options", {{"tabSize", 2}, {"insertSpaces", true}}}})["result"];
  EXPECT_EQ(apply_edits("; top\n@line\nif xpos > 0 ; cut\n{nb, 'G1'}\n      else\nwhile blknum < 3\n blknum = blknum + 1\n   endw\n  endif\n\n    endp\n", edits),
            "; top\n@line\n  if xpos > 0 ; cut\n    {nb, 'G1'}\n  else\n    while blknum < 3\n      blknum = blknum + 1\n    endw\n  endif\n\nendp\n");
  // Whatever tab size the client sends, the indentation stays between 1 and 16 blanks.
  for (const std::int64_t tab : {std::int64_t{-1}, std::int64_t{1'000'000'000'000}}) {
    const json odd = c.request("textDocument/formatting", {{"textDocument", {{"uri", uri}}},
                                                           {"options", {{"tabSize", tab}, {"insertSpaces", true}}}});
    ASSERT_TRUE(odd["result"].is_array()) << odd.dump();
    EXPECT_EQ(odd["result"][0]["newText"], std::string(tab < 0 ? 1 : 16, ' '));
  }
}

// Every post we ship formats to a post with the same statements (only leading blanks change) and
// the same check result.
TEST(LspEditing, FormattingTheShippedPostsKeepsTheirMeaning) {
  std::size_t posts = 0;
  for (const auto& entry : fs::recursive_directory_iterator("../machines")) {
    if (entry.path().extension() != ".gpp") continue;
    ++posts;
    SCOPED_TRACE(entry.path().string());
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    Client c;
    c.initialize();
    const std::string uri = "file://" + fs::absolute(entry.path()).string();
    c.open(uri, text.str());
    const auto before = c.diagnostics(uri);
    const json edits = c.request("textDocument/formatting", {{"textDocument", {{"uri", uri}}},
                                                             {"options", {{"tabSize", 2}, {"insertSpaces", true}}}})["result"];
    const std::string formatted = apply_edits(text.str(), edits);
    auto statements = [](const std::string& t) {
      std::vector<std::string> out;
      std::istringstream lines(t);
      std::string line;
      while (std::getline(lines, line)) out.push_back(line.substr(std::min(line.size(), line.find_first_not_of(" \t"))));
      return out;
    };
    EXPECT_EQ(statements(formatted), statements(text.str()));
    c.notify("textDocument/didChange", {{"textDocument", {{"uri", uri}, {"version", 2}}},
                                        {"contentChanges", json::array({{{"text", formatted}}})}});
    EXPECT_EQ(c.diagnostics(uri), before);
  }
  EXPECT_GE(posts, 8u);
}

// Columns are UTF-16 characters in the protocol: a Polish comment before a name moves it.
TEST(LspPositions, Utf16ColumnsAgainstByteColumns) {
  Client c;
  c.initialize();
  const std::string uri = "file:///tmp/pl.gpp";
  c.open(uri, "@line\n  {nb, 'żółw' cuont}\nendp\n");
  EXPECT_EQ(c.diagnostics(uri), (std::vector<std::string>{
                                    "1:14-1:19 error 383 Variable 'cuont' is not defined"}));
}

// The server as `postproc lsp` runs it: framed bytes in, framed bytes out, the exit code.
TEST(LspServe, OverAByteStream) {
  auto frame = [](const json& m) {
    const std::string body = m.dump();
    return "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
  };
  std::istringstream in(frame({{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}, {"params", json::object()}}) +
                        "Content-Length: x\r\n\r\n" + frame({{"jsonrpc", "2.0"}, {"id", 2}, {"method", "shutdown"}}) +
                        frame({{"jsonrpc", "2.0"}, {"method", "exit"}}));
  std::ostringstream out, log;
  EXPECT_EQ(lsp::serve(in, out, log), 0);
  EXPECT_EQ(log.str(), "postproc lsp: a malformed message was skipped: Content-Length is not a number: `x`\n");
  EXPECT_NE(out.str().find("\"id\":2,\"jsonrpc\":\"2.0\",\"result\":null"), std::string::npos) << out.str();
  std::istringstream gone(frame({{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}, {"params", json::object()}}));
  EXPECT_EQ(lsp::serve(gone, out, log), 1);  // the input ended without shutdown and exit
}

}  // namespace
