#include "postproc/engine/engine_sink.hpp"

#include <filesystem>
#include <optional>

#include "postproc/engine/directive.hpp"

namespace postproc {

void EngineSink::write_line(std::string_view line, const gppl::LineOrigin& origin) {
  std::size_t first = 0;  // a directive may be indented (find_first_not_of costs a memchr per character)
  while (first < line.size() && (line[first] == ' ' || line[first] == '\t')) ++first;
  const bool maybe_directive = first < line.size() && line[first] == '!';
  if (!maybe_directive && !observer_) {  // the usual line: straight to the file
    write_to_file(line, origin.after_break);
    return;
  }
  write_observed(line, origin, maybe_directive);
}

std::string_view EngineSink::include_name(std::string_view file) {
  if (file.empty() || file == post_) return {};
  for (const auto& [path, name] : include_names_)
    if (path == file) return name;
  const std::filesystem::path included(file), folder = std::filesystem::path(post_).parent_path();
  std::string name = included.lexically_relative(folder.empty() ? "." : folder).generic_string();
  if (name.empty()) name = included.generic_string();  // another root: the path as it was opened
  return include_names_.emplace_back(std::string(file), std::move(name)).second;
}

// The count includes the empty first line the break before a file's first block makes.
void EngineSink::write_to_file(std::string_view line, bool after_break) {
  lines += files_.break_starts_file(after_break) ? 2 : 1;
  files_.write_line(line, after_break);
}

void EngineSink::write_observed(std::string_view line, const gppl::LineOrigin& origin, bool maybe_directive) {
  std::optional<Directive> directive = maybe_directive ? parse_directive(line) : std::nullopt;
  if (observer_) {
    // The line was started by the command that flushed the line before it (nb and nl flush the
    // open line and open the next one), unless this command already flushed one.
    bool own = wrote_in_command_;
    file_name_ = files_.current_name();
    LineEvent e{file_name_, line, directive.has_value(), files_.current_is_main(), false,
                {own ? command_index : opener_index_, own ? command_name : std::string_view(opener_name_),
                 origin.procedure, origin.source_line, include_name(origin.source_file)}};
    if (files_.break_starts_file(origin.after_break)) {
      LineEvent empty = e;
      empty.text = {};
      empty.directive = false;
      empty.leading_break = true;
      observer_->on_line(empty);
    }
    observer_->on_line(e);
    opener_index_ = command_index;
    opener_name_ = command_name;
    wrote_in_command_ = true;
  }
  if (directive) {
    lines += files_.break_starts_file(origin.after_break);
    if (observer_ && directive->verb == Directive::Verb::Copy) {
      // The copied text becomes lines of the current file, attributed to the command that copies.
      LineEvent copied{file_name_, {}, false, files_.current_is_main(), false,
                       {command_index, command_name, origin.procedure, origin.source_line,
                        include_name(origin.source_file)}};
      files_.execute(*directive, [&](std::string_view text) {
        copied.text = text;
        observer_->on_line(copied);
        ++lines;
      }, origin.after_break);
    } else {
      files_.execute(*directive, {}, origin.after_break);
    }
  } else {
    write_to_file(line, origin.after_break);
  }
}

}  // namespace postproc
