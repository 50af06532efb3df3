// `postproc lsp`: a Language Server Protocol server for GPPL posts and their machine files, built on
// the compiler and `postproc check` (docs/editors.md). Diagnostics as the user types, completion,
// hover, go to definition, references, rename, document symbols and folding.
#pragma once

#include <functional>
#include <istream>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

namespace lsp {

class Server {
public:
  // `send` takes each message the server sends (a JSON text): responses and notifications.
  explicit Server(std::function<void(std::string)> send);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // One message from the client. A malformed one is answered with a JSON-RPC error (a request) or
  // dropped (a notification); it never throws.
  void handle(std::string_view message);
  bool exited() const;   // `exit` came
  int exit_code() const;  // 0 when `shutdown` came before `exit`, else 1

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Runs a server over a byte stream until `exit` or the end of the input; returns the exit code.
// What is wrong with the stream itself (a malformed header) goes to `log`.
int serve(std::istream& in, std::ostream& out, std::ostream& log);

}  // namespace lsp
