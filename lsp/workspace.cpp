#include "lsp/workspace.hpp"

#include <algorithm>
#include <array>
#include <filesystem>

#include "postproc/checks/post_check.hpp"
#include "prp/prp.hpp"
#include "toolpath/bounded_read.hpp"
#include "toolpath/value.hpp"

namespace lsp {
namespace {

constexpr std::size_t kMaxDiskFile = 16u << 20;  // an include or machine file larger is not one

int hex(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// UTF-16 code units of the UTF-8 sequence that starts with `lead` (a malformed byte counts as one).
int utf16_units(unsigned char lead) { return lead >= 0xF0 ? 2 : 1; }
std::size_t utf8_length(unsigned char lead) {
  return lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
}

// A file on disk (an include, a machine file), or nullopt when it cannot be read or is too large.
std::optional<std::string> read_small_file(const std::string& path) {
  try {
    return toolpath::read_file_bounded(path, kMaxDiskFile, "too large for an include or a machine file");
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::string uri_to_path(std::string_view uri) {
  constexpr std::string_view kScheme = "file://";
  if (uri.substr(0, kScheme.size()) != kScheme) return std::string(uri);
  uri.remove_prefix(kScheme.size());
  if (const std::size_t slash = uri.find('/'); slash != 0 && slash != std::string_view::npos)
    uri.remove_prefix(slash);  // file://host/path: the host is dropped
  std::string path;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      path += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
      i += 2;
    } else {
      path += uri[i];
    }
  }
  return path;
}

std::string path_to_uri(std::string_view path) {
  if (path.find("://") != std::string_view::npos) return std::string(path);
  std::string uri = "file://";
  for (const char c : path) {
    const auto b = static_cast<unsigned char>(c);
    if (std::isalnum(b) || std::string_view("/-._~").find(c) != std::string_view::npos) {
      uri += c;
    } else {
      static constexpr char kDigits[] = "0123456789ABCDEF";
      uri += '%';
      uri += kDigits[b >> 4];
      uri += kDigits[b & 15];
    }
  }
  return uri;
}

Lines::Lines(std::string text) : text_(std::move(text)) {
  starts_.push_back(0);
  for (std::size_t i = 0; i < text_.size(); ++i)
    if (text_[i] == '\n') starts_.push_back(i + 1);
}

std::string_view Lines::line(std::size_t number) const {
  if (number == 0 || number > starts_.size()) return {};
  const std::size_t begin = starts_[number - 1];
  std::size_t end = number < starts_.size() ? starts_[number] - 1 : text_.size();
  if (end > begin && text_[end - 1] == '\r') --end;
  return std::string_view(text_).substr(begin, end - begin);
}

std::pair<std::uint32_t, std::uint32_t> Lines::from_protocol(const json& position) const {
  const auto line_index = position.at("line").get<std::int64_t>();
  const auto character = position.at("character").get<std::int64_t>();
  const auto line = static_cast<std::uint32_t>(std::clamp<std::int64_t>(line_index + 1, 1, std::int64_t(count())));
  const std::string_view text = this->line(line);
  std::int64_t units = 0;
  std::size_t byte = 0;
  while (byte < text.size() && units < character) {
    const auto lead = static_cast<unsigned char>(text[byte]);
    units += utf16_units(lead);
    byte += std::min(utf8_length(lead), text.size() - byte);
  }
  return {line, static_cast<std::uint32_t>(byte + 1)};
}

json Lines::to_protocol(std::uint32_t line, std::uint32_t column) const {
  const std::string_view text = this->line(line);
  std::int64_t units = 0;
  for (std::size_t byte = 0; byte + 1 < column && byte < text.size();) {
    const auto lead = static_cast<unsigned char>(text[byte]);
    units += utf16_units(lead);
    byte += utf8_length(lead);
  }
  return {{"line", line == 0 ? 0 : line - 1}, {"character", units}};
}

std::size_t Lines::offset(const json& position) const {
  const auto [line, column] = from_protocol(position);
  return std::min<std::size_t>(starts_[line - 1] + column - 1, text_.size());
}

json Lines::range(std::uint32_t line, std::uint32_t column, std::uint32_t length) const {
  return {{"start", to_protocol(line, column)}, {"end", to_protocol(line, column + length)}};
}

FileKind kind_of(std::string_view path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (toolpath::iequals(ext, ".gpp") || toolpath::iequals(ext, ".inc") || toolpath::iequals(ext, ".gpi"))
    return FileKind::Post;
  if (postproc::is_machine_file(std::string(path))) return FileKind::Machine;
  return FileKind::Other;
}

Document& Workspace::open(std::string uri, std::string text, std::int64_t version) {
  Document& doc = documents_[uri];
  doc.uri = uri;
  doc.path = uri_to_path(uri);
  doc.kind = kind_of(doc.path);
  doc.lines = Lines(std::move(text));
  doc.version = version;
  disk_.erase(doc.path);
  return doc;
}

Document* Workspace::find(std::string_view uri) {
  const auto it = documents_.find(uri);
  return it == documents_.end() ? nullptr : &it->second;
}

void Workspace::close(std::string_view uri) {
  if (const auto it = documents_.find(uri); it != documents_.end()) documents_.erase(it);
}

const Lines& Workspace::lines_of(const std::string& path) {
  for (const auto& [uri, doc] : documents_)
    if (doc.path == path) return doc.lines;
  auto it = disk_.find(path);
  if (it == disk_.end()) it = disk_.emplace(path, Lines(read_small_file(path).value_or(std::string()))).first;
  return it->second;
}

std::vector<Document*> Workspace::posts() {
  std::vector<Document*> out;
  for (auto& [uri, doc] : documents_)
    if (doc.kind == FileKind::Post) out.push_back(&doc);
  return out;
}

void Workspace::analyse(Document& doc) {
  disk_.clear();  // files on disk may have changed since: read again when asked
  if (doc.kind == FileKind::Machine) {
    doc.diagnostics = postproc::check_machine_text(doc.lines.text(), doc.path, prp::Units::Metric);
    return;
  }
  if (doc.kind != FileKind::Post) return;
  // The machine file beside the post gives its external variables and drill cycles, as `check`
  // takes the --prp of the post.
  std::optional<prp::MachineParameters> machine;
  const std::filesystem::path post(doc.path);
  static constexpr std::array<std::string_view, 6> kMachine = {".prp", ".PRP", ".vmid", ".VMID", ".mac", ".MAC"};
  for (std::string_view ext : kMachine) {
    const std::string candidate = std::filesystem::path(post).replace_extension(ext).string();
    std::optional<std::string> text;
    for (const auto& [uri, open] : documents_)
      if (open.path == candidate) text = open.lines.text();
    if (!text && std::filesystem::exists(candidate)) text = read_small_file(candidate);
    if (!text) continue;
    try {
      machine = prp::load_source(*text, candidate, prp::Units::Metric);
    } catch (const std::exception&) {
      // its own errors are its document's; the post is checked without it, as `check` does
    }
    break;
  }
  postproc::PostCheckOptions options;
  if (machine) options.machine = &*machine;
  gppl::SymbolIndex symbols;
  options.symbols = &symbols;
  doc.diagnostics = postproc::check_post_text(doc.lines.text(), doc.path, options);
  if (!symbols.uses.empty() || doc.symbols.uses.empty()) doc.symbols = std::move(symbols);
}

}  // namespace lsp
