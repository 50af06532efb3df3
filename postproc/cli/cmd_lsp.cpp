// `postproc lsp`: the language server on standard input and output (lsp/server.hpp).
#include <iostream>

#include "lsp/server.hpp"
#include "postproc/cli/cli.hpp"

namespace postproc::cli {
namespace {

int run_lsp(const Arguments& args, std::ostream& out, std::ostream& err) {
  if (!args.positional().empty()) throw UsageError{"lsp takes no files: the editor sends them"};
  std::ios::sync_with_stdio(false);
  return lsp::serve(std::cin, out, err);
}

}  // namespace

Subcommand lsp_command() {
  return {
      "lsp",
      "postproc lsp",
      "A Language Server Protocol server on stdin/stdout for GPPL posts and machine files (docs/editors.md).",
      {},
      run_lsp,
  };
}

}  // namespace postproc::cli
