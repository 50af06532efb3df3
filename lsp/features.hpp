// Internal to the language server: the answers to the editor's requests about one document, from
// what the last check of it found (its diagnostics and its index of names).
#pragma once

#include "lsp/workspace.hpp"

namespace lsp {

// textDocument/publishDiagnostics params, one per file the document's check found something in
// (an included file gets its own), the document's own first (also when it is clean).
std::vector<json> diagnostics_by_file(Workspace& workspace, const Document& doc);

json completion(Workspace& workspace, const Document& doc, const json& params);
json hover(Workspace& workspace, const Document& doc, const json& params);
json signature_help(const Document& doc, const json& params);
json definition(Workspace& workspace, const Document& doc, const json& params);
json references(Workspace& workspace, const Document& doc, const json& params);
// Throws std::invalid_argument (a message for the user) when the name cannot be renamed.
json rename(Workspace& workspace, const Document& doc, const json& params);
json document_symbols(const Document& doc);
json folding_ranges(const Document& doc);
// Quick fixes where the fix is certain: the "did you mean" of a diagnostic; declaring an undefined
// name as a local of the procedure it is used in.
json code_actions(const Document& doc, const json& params);
// Indentation only (procedure bodies, if/while blocks), so a post's meaning cannot change.
json formatting(const Document& doc, const json& params);

}  // namespace lsp
