#include "postproc/engine/engine_sink.hpp"

#include <filesystem>
#include <optional>

#include "postproc/engine/directive.hpp"

namespace postproc {

namespace {

// A directive may be indented (blanks or tabs before its '!'). A line that starts with any other
// printable character, as NC blocks do, is settled by its first byte.
bool maybe_directive(std::string_view line) {
  if (!line.empty() && static_cast<unsigned char>(line[0]) > '!') return false;
  std::size_t first = 0;  // a loop: find_first_not_of costs a memchr per character
  while (first < line.size() && (line[first] == ' ' || line[first] == '\t')) ++first;
  return first < line.size() && line[first] == '!';
}

}  // namespace

void EngineSink::write_line(std::string_view line, const gppl::LineOrigin& origin) {
  const bool directive = maybe_directive(line);
  if (!directive && !observer_) {  // the usual line: straight to the file
    lines += files_.write_line(line, origin.after_break);
    return;
  }
  write_observed(line, origin, directive);
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
    lines += files_.write_line(line, origin.after_break);
  }
}

}  // namespace postproc
