#include "machines/templates/post_templates.hpp"

#include <algorithm>

namespace machines {

const PostTemplate* find_post_template(std::string_view name) {
  const auto& all = post_templates();
  auto it = std::find_if(all.begin(), all.end(), [&](const PostTemplate& t) { return t.name == name; });
  return it == all.end() ? nullptr : &*it;
}

std::string renamed_machine_file(const PostTemplate& t, std::string_view post_name) {
  std::string out;
  out.reserve(t.prp.size() + 64);
  std::string_view rest = t.prp;
  while (!rest.empty()) {
    const auto end = rest.find('\n');
    std::string_view line = rest.substr(0, end == std::string_view::npos ? rest.size() : end + 1);
    rest.remove_prefix(line.size());
    for (std::string_view key : {"post_processor", "doc_processor"}) {
      if (line.starts_with(key) && line.find('=') != std::string_view::npos &&
          line.substr(key.size(), line.find('=') - key.size()).find_first_not_of(" \t") == std::string_view::npos) {
        out.append(key).append(" = ").append(post_name).append("\n");
        line = {};
        break;
      }
    }
    out.append(line);
  }
  return out;
}

}  // namespace machines
