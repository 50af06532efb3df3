// Internal to the language server: the open documents, what `check` finds in each, and the
// positions the protocol speaks in (0-based lines, UTF-16 code units) against ours (1-based lines,
// byte columns).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "gppl/symbols.hpp"
#include "toolpath/diagnostic.hpp"

namespace lsp {

using json = nlohmann::json;

// "file:///a/b%20c.gpp" <-> "/a/b c.gpp". Other schemes keep their URI as the name.
std::string uri_to_path(std::string_view uri);
std::string path_to_uri(std::string_view path);

// A file's text split in lines, to turn byte columns into UTF-16 characters and back.
class Lines {
public:
  explicit Lines(std::string text = {});
  const std::string& text() const { return text_; }
  std::size_t count() const { return starts_.size(); }
  std::string_view line(std::size_t number) const;  // 1-based; empty beyond the end
  // Protocol position -> 1-based line and byte column (clamped to the line).
  std::pair<std::uint32_t, std::uint32_t> from_protocol(const json& position) const;
  json to_protocol(std::uint32_t line, std::uint32_t column) const;
  json range(std::uint32_t line, std::uint32_t column, std::uint32_t length) const;
  // The byte offset in the text of a protocol position (for incremental changes).
  std::size_t offset(const json& position) const;

private:
  std::string text_;
  std::vector<std::size_t> starts_;
};

enum class FileKind { Post, Machine, Other };
FileKind kind_of(std::string_view path);

struct Document {
  std::string uri, path;
  FileKind kind = FileKind::Other;
  Lines lines;
  std::int64_t version = 0;
  // What the last check found; for posts also the index of every name (it may be from an older
  // text when the post stopped compiling early: kept while the new one has no symbols).
  std::vector<toolpath::Diagnostic> diagnostics;
  gppl::SymbolIndex symbols;
};

class Workspace {
public:
  Document& open(std::string uri, std::string text, std::int64_t version);
  Document* find(std::string_view uri);
  void close(std::string_view uri);
  // Checks the document as `postproc check` would, with the machine file beside a post (same name,
  // .prp, .vmid or .mac; its editor buffer when it is open).
  void analyse(Document& doc);
  // The text of a file: an open document's, else read from disk (kept until it changes).
  const Lines& lines_of(const std::string& path);
  // The posts that are open, for re-checking when their machine file changes.
  std::vector<Document*> posts();

private:
  std::map<std::string, Document, std::less<>> documents_;  // by URI
  std::map<std::string, Lines, std::less<>> disk_;            // by path
};

}  // namespace lsp
