#include "machines/pikocnc/model/reader.hpp"

#include <fstream>
#include <sstream>
#include <initializer_list>
#include <string_view>
#include <utility>

#include "machines/pikocnc/model/interpreter.hpp"

namespace pikocnc {

PikoReader::PikoReader(std::istream& in, std::string file_name, Options options)
    : interpreter_(std::make_unique<Interpreter>(in, std::move(file_name), std::move(options))) {}

PikoReader::~PikoReader() = default;

std::unique_ptr<PikoReader> PikoReader::open(const std::string& path, Options options) {
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file) throw toolpath::InputError({path, 0, 0}, "cannot open file");
  auto reader = std::make_unique<PikoReader>(*file, path, std::move(options));
  reader->owned_ = std::move(file);
  return reader;
}

std::unique_ptr<PikoReader> PikoReader::from_string(std::string text, std::string file_name, Options options) {
  auto in = std::make_unique<std::istringstream>(std::move(text));
  auto reader = std::make_unique<PikoReader>(*in, std::move(file_name), std::move(options));
  reader->owned_ = std::move(in);
  return reader;
}

bool PikoReader::pull(toolpath::Command& out, std::size_t& line) {
  if (!interpreter_->run()) return false;
  return interpreter_->emitter().pop(out, line);
}

bool PikoReader::next(toolpath::Command& out) {
  if (!pending_.empty()) {
    swap(out, pending_.front().command);
    line_ = pending_.front().line;
    pending_.pop_front();
  } else if (!pull(out, line_)) {
    return false;
  }
  // As a string_view, the length is compared first: no memcmp call for every other command.
  if (std::string_view(out.name) == "@change_tool" && !out.find("silent")) complete_tool_change(out);
  return true;
}

namespace {

bool is_one_of(const toolpath::Command& c, std::initializer_list<std::string_view> names) {
  for (auto n : names)
    if (c.name == n) return true;
  return false;
}

}  // namespace

void PikoReader::complete_tool_change(toolpath::Command& change) {
  // Far enough for any tool-change sequence (messages, spindle, coolant, offsets), small enough
  // that a program that never moves after M6 costs nothing noticeable.
  constexpr std::size_t kLookahead = 256;
  change.set("first_tool", toolpath::Value::make_logical(!seen_tool_));
  seen_tool_ = true;
  bool spin_known = false, direction_known = false;
  // Looks at one following command; false once the search is over.
  auto look = [&](const toolpath::Command& c) {
    if (is_one_of(c, {"@rapid_move", "@line", "@arc"})) {
      for (auto [from, to] : {std::pair{"xpos", "xnext"}, {"ypos", "ynext"}, {"zpos", "znext"}})
        if (const auto* v = c.find(from)) change.set(to, *v);
      return false;
    }
    if (is_one_of(c, {"@change_tool", "@end_program", "@end_of_file"})) return false;
    if (!spin_known && is_one_of(c, {"@start_tool", "@m_feed_spin"})) {
      if (const auto* v = c.find("spin")) {
        change.set("spin", *v);
        spin_known = true;
      }
    }
    if (!direction_known && c.name == "@start_tool") {
      if (const auto* v = c.find("spin_direction")) {
        change.set("tool_direction", *v);
        direction_known = true;
      }
    }
    return true;
  };
  for (const auto& p : pending_)  // already read ahead for an earlier tool change
    if (!look(p.command)) return;
  while (pending_.size() < kLookahead) {
    Pending p;
    if (!pull(p.command, p.line)) return;
    if (!look(pending_.emplace_back(std::move(p)).command)) return;
  }
}

const Diagnostics& PikoReader::diagnostics() const { return interpreter_->diagnostics(); }
const std::string& PikoReader::file_name() const { return interpreter_->file_name(); }

}  // namespace pikocnc
