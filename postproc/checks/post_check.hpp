// `postproc check` as a library: the static checks of a post or a machine file, as diagnostics
// (file, line, column, severity, GPPTool number). The CLI prints them; the language server
// (`postproc lsp`) publishes them: one check, never a second opinion.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "gppl/gppl.hpp"
#include "prp/prp.hpp"
#include "toolpath/diagnostic.hpp"

namespace postproc {

struct PostCheckOptions {
  // The machine file whose external variables and drill cycles the post may use; null: none.
  const prp::MachineParameters* machine = nullptr;
  std::vector<gppl::HostVariable> job_variables;  // names a job carries (`check --job`)
  std::vector<std::string> include_paths;         // besides the including file's folder
  gppl::SymbolIndex* symbols = nullptr;           // an editor's index, filled by the same compile
};

// A post read from `path`, or held in memory (an editor's buffer) under the name `path`, whose
// includes are looked up beside it. Every name must be declared and constant assignments are
// checked where they stand; a procedure no command has and nothing calls is a warning with the
// nearest command name. Errors first when the post does not compile (its warnings are then not
// known), else the warnings.
std::vector<toolpath::Diagnostic> check_post_file(const std::string& path, const PostCheckOptions& options);
std::vector<toolpath::Diagnostic> check_post_text(std::string_view text, const std::string& path,
                                                  const PostCheckOptions& options);

// Machine files: PRP, its pre-2010 name .mac, and VMID (by extension; the loader tells PRP and
// VMID apart by content).
bool is_machine_file(const std::string& path);
// Its load errors, else its warnings.
std::vector<toolpath::Diagnostic> check_machine_file(const std::string& path, prp::Units units);
std::vector<toolpath::Diagnostic> check_machine_text(std::string_view text, const std::string& path, prp::Units units);

}  // namespace postproc
