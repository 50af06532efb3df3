#include "postproc/prp_settings.hpp"

#include <fstream>
#include <sstream>

#include "toolpath/error.hpp"
#include "toolpath/value.hpp"

namespace postproc {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string> words(std::string_view s) {
  std::vector<std::string> out;
  std::istringstream in{std::string(s)};
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace

PrpSettings PrpSettings::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw toolpath::InputError({path, 0, 0}, "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), path);
}

PrpSettings PrpSettings::parse(std::string_view text, const std::string& file_name) {
  PrpSettings prp;
  std::size_t line_number = 0;
  while (!text.empty()) {
    std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    ++line_number;
    std::string_view body = line.substr(0, line.find(';'));
    std::string_view content = trim(body);
    if (content.empty() || content.front() == '@' || toolpath::iequals(content, "endp")) continue;
    std::size_t eq = content.find('=');
    if (eq == std::string_view::npos) {
      std::size_t column = static_cast<std::size_t>(content.data() - line.data()) + 1;
      throw toolpath::InputError({file_name, line_number, column},
                                 "expected `name = value`, found `" + std::string(content) + "`");
    }
    std::string_view key = trim(content.substr(0, eq));
    if (key.empty()) {
      std::size_t column = static_cast<std::size_t>(content.data() - line.data()) + 1;
      throw toolpath::InputError({file_name, line_number, column}, "expected a parameter name before `=`");
    }
    prp.entries_.emplace_back(std::string(key), std::string(trim(content.substr(eq + 1))));
  }
  return prp;
}

std::optional<std::string> PrpSettings::value(std::string_view key) const {
  for (auto it = entries_.rbegin(); it != entries_.rend(); ++it)
    if (toolpath::iequals(it->first, key)) return it->second;
  return std::nullopt;
}

std::vector<std::string> PrpSettings::values(std::string_view key) const {
  std::vector<std::string> out;
  for (const auto& [k, v] : entries_)
    if (toolpath::iequals(k, key)) out.push_back(v);
  return out;
}

std::vector<std::string> PrpSettings::drill_type_names() const {
  std::vector<std::string> names;
  for (const auto& [name, parameters] : drill_cycle_parameters()) names.push_back(name);
  return names;
}

// `drill_type = <name> <internal type> <Y/N> <parameters...>`; the older form has no internal type
// (`drill_type = Peck Y Delay`): the Y/N flag tells which form a line uses.
std::vector<std::pair<std::string, std::vector<std::string>>> PrpSettings::drill_cycle_parameters() const {
  std::vector<std::pair<std::string, std::vector<std::string>>> out;
  for (const auto& v : values("drill_type")) {
    auto w = words(v);
    if (w.empty()) continue;
    std::size_t flag = 1;
    while (flag < w.size() && !toolpath::iequals(w[flag], "Y") && !toolpath::iequals(w[flag], "N")) ++flag;
    std::vector<std::string> parameters(w.begin() + static_cast<std::ptrdiff_t>(std::min(flag + 1, w.size())), w.end());
    out.emplace_back(w[0], std::move(parameters));
  }
  return out;
}

}  // namespace postproc
