#include "lsp/server.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include "lsp/features.hpp"
#include "lsp/transport.hpp"
#include "lsp/workspace.hpp"

namespace lsp {
namespace {

// JSON-RPC and LSP error codes.
constexpr int kParseError = -32700, kInvalidRequest = -32600, kMethodNotFound = -32601, kInvalidParams = -32602,
              kInternalError = -32603, kServerNotInitialized = -32002, kRequestFailed = -32803;

struct RequestError {
  int code;
  std::string message;
};

}  // namespace

struct Server::Impl {
  std::function<void(std::string)> send;
  Workspace workspace;
  bool initialized = false, shut_down = false, exited = false;
  std::map<std::string, std::set<std::string>> published;  // document -> other files it published for

  void reply(const json& id, json result) {
    send(json{{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}}.dump(-1, ' ', false, json::error_handler_t::replace));
  }
  void fail(const json& id, int code, const std::string& message) {
    send(json{{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}}.dump(
        -1, ' ', false, json::error_handler_t::replace));
  }
  void notify(std::string_view method, json params) {
    send(json{{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}}.dump(
        -1, ' ', false, json::error_handler_t::replace));
  }

  void check_and_publish(Document& doc) {
    workspace.analyse(doc);
    std::set<std::string> now;
    for (json& p : diagnostics_by_file(workspace, doc)) {
      const std::string uri = p.at("uri").get<std::string>();
      if (uri != doc.uri) now.insert(uri);
      notify("textDocument/publishDiagnostics", std::move(p));
    }
    for (const std::string& uri : published[doc.uri])  // an include that is clean now
      if (!now.count(uri)) notify("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", json::array()}});
    published[doc.uri] = std::move(now);
  }

  // A machine file changed: the posts beside it are checked again with it.
  void changed(Document& doc) {
    check_and_publish(doc);
    if (doc.kind == FileKind::Machine)
      for (Document* post : workspace.posts()) check_and_publish(*post);
  }

  Document& document(const json& params) {
    Document* doc = workspace.find(params.at("textDocument").at("uri").get<std::string>());
    if (!doc) throw RequestError{kRequestFailed, "the document is not open"};
    return *doc;
  }

  json capabilities() const {
    return {{"capabilities",
             {{"textDocumentSync", {{"openClose", true}, {"change", 2}, {"save", {{"includeText", false}}}}},
              {"completionProvider", {{"triggerCharacters", {"@"}}}},
              {"hoverProvider", true},
              {"signatureHelpProvider", {{"triggerCharacters", {"(", ","}}}},
              {"definitionProvider", true},
              {"referencesProvider", true},
              {"renameProvider", true},
              {"documentSymbolProvider", true},
              {"foldingRangeProvider", true},
              {"codeActionProvider", {{"codeActionKinds", {"quickfix"}}}},
              {"documentFormattingProvider", true}}},
            {"serverInfo", {{"name", "postproc lsp"}}}};
  }

  json request(const std::string& method, const json& params) {
    if (method == "initialize") {
      initialized = true;
      return capabilities();
    }
    if (!initialized) throw RequestError{kServerNotInitialized, "initialize first"};
    if (shut_down) throw RequestError{kInvalidRequest, "the server is shut down: only exit is taken"};
    if (method == "shutdown") {
      shut_down = true;
      return nullptr;
    }
    if (method == "textDocument/completion") return completion(workspace, document(params), params);
    if (method == "textDocument/hover") return hover(workspace, document(params), params);
    if (method == "textDocument/signatureHelp") return signature_help(document(params), params);
    if (method == "textDocument/definition") return definition(workspace, document(params), params);
    if (method == "textDocument/references") return references(workspace, document(params), params);
    if (method == "textDocument/rename") {
      try {
        return rename(workspace, document(params), params);
      } catch (const std::invalid_argument& e) {
        throw RequestError{kRequestFailed, e.what()};
      }
    }
    if (method == "textDocument/documentSymbol") return document_symbols(document(params));
    if (method == "textDocument/foldingRange") return folding_ranges(document(params));
    if (method == "textDocument/codeAction") return code_actions(document(params), params);
    if (method == "textDocument/formatting") return formatting(document(params), params);
    throw RequestError{kMethodNotFound, fmt::format("no method {}", method)};
  }

  void notification(const std::string& method, const json& params) {
    if (method == "exit") {
      exited = true;
      return;
    }
    if (!initialized || shut_down) return;
    if (method == "textDocument/didOpen") {
      const json& d = params.at("textDocument");
      changed(workspace.open(d.at("uri").get<std::string>(), d.at("text").get<std::string>(),
                             d.value("version", std::int64_t{0})));
    } else if (method == "textDocument/didChange") {
      Document& doc = document(params);
      std::string text = doc.lines.text();
      for (const json& change : params.at("contentChanges")) {
        if (!change.contains("range")) {
          text = change.at("text").get<std::string>();
          continue;
        }
        const Lines lines(text);
        const std::size_t begin = lines.offset(change.at("range").at("start"));
        const std::size_t end = std::max(begin, lines.offset(change.at("range").at("end")));
        text.replace(begin, end - begin, change.at("text").get<std::string>());
      }
      changed(workspace.open(doc.uri, std::move(text), params.at("textDocument").value("version", doc.version + 1)));
    } else if (method == "textDocument/didSave") {
      changed(document(params));  // its includes may have changed on disk
    } else if (method == "textDocument/didClose") {
      const std::string uri = params.at("textDocument").at("uri").get<std::string>();
      for (const std::string& other : published[uri])
        notify("textDocument/publishDiagnostics", {{"uri", other}, {"diagnostics", json::array()}});
      published.erase(uri);
      notify("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", json::array()}});
      workspace.close(uri);
    }
    // anything else ($/cancelRequest, initialized, workspace/didChangeConfiguration, ...): nothing to do
  }

  void handle(std::string_view text) {
    json message = json::parse(text, nullptr, false);
    if (message.is_discarded()) return fail(nullptr, kParseError, "the message is not JSON");
    if (!message.is_object()) return fail(nullptr, kInvalidRequest, "a message is a JSON object");
    const json id = message.contains("id") ? message["id"] : json();
    const bool is_request = message.contains("id");
    if (!message.contains("method") || !message["method"].is_string()) {
      if (is_request && !message.contains("result") && !message.contains("error"))
        fail(id, kInvalidRequest, "a request names its method");
      return;  // a response to a request of ours: we send none
    }
    const std::string method = message["method"].get<std::string>();
    const json params = message.contains("params") ? message["params"] : json::object();
    try {
      if (is_request) reply(id, request(method, params));
      else notification(method, params);
    } catch (const RequestError& e) {
      if (is_request) fail(id, e.code, e.message);
    } catch (const json::exception& e) {
      if (is_request) fail(id, kInvalidParams, fmt::format("{}: the parameters are not what the method takes ({})", method, e.what()));
    } catch (const std::exception& e) {
      if (is_request) fail(id, kInternalError, fmt::format("{}: {}", method, e.what()));
    }
  }
};

Server::Server(std::function<void(std::string)> send) : impl_(std::make_unique<Impl>()) {
  impl_->send = std::move(send);
}
Server::~Server() = default;
void Server::handle(std::string_view message) { impl_->handle(message); }
bool Server::exited() const { return impl_->exited; }
int Server::exit_code() const { return impl_->shut_down ? 0 : 1; }

int serve(std::istream& in, std::ostream& out, std::ostream& log) {
  Server server([&out](std::string body) { write_frame(out, body); });
  while (!server.exited()) {
    const Frame frame = read_frame(in);
    if (frame.status == FrameStatus::End) return 1;  // the client went away without `exit`
    if (frame.status == FrameStatus::Malformed) {
      log << "postproc lsp: a malformed message was skipped: " << frame.error << '\n';
      continue;
    }
    server.handle(frame.body);
  }
  return server.exit_code();
}

}  // namespace lsp
