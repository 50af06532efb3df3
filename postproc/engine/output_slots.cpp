// OutputFiles: placeholders filled in place (start_line/end_line) and the final pass over the
// files that removes their framing and replaces $$file_size$$ (docs/engine.md, "File size" and
// "start_line and end_line").
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "postproc/engine/output_files.hpp"
#include "postproc/engine/slot_marker.hpp"

namespace postproc {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void io_failure(const std::string& what, const fs::path& path) {
  throw std::runtime_error("cannot " + what + " `" + path.string() + "`: " + std::strerror(errno));
}

constexpr std::string_view kFileSize = "$$file_size$$";

std::size_t decimal_digits(std::uintmax_t n) {
  std::size_t d = 1;
  while (n >= 10) n /= 10, ++d;
  return d;
}

// The size the file has once each of its `count` placeholders is replaced by that size: the smallest
// fixed point of size = base - count * placeholder + count * digits(size).
std::uintmax_t self_consistent_size(std::uintmax_t base, std::uintmax_t count) {
  std::uintmax_t without = base - count * kFileSize.size();
  for (std::size_t digits = 1; digits <= 20; ++digits) {
    std::uintmax_t size = without + count * digits;
    if (decimal_digits(size) == digits) return size;
  }
  return base;  // unreachable for real sizes
}

}  // namespace

std::uint32_t OutputFiles::new_slot(std::string& marker) {
  const std::uint32_t id = next_slot_++;
  marker = slot::marker(id);
  ++unwritten_slots_;
  return id;
}

void OutputFiles::fill_slot(std::uint32_t id, std::string_view text) {
  auto it = open_slots_.find(id);
  if (it == open_slots_.end()) {  // its line is not written yet: write_line puts the text in
    early_slots_.emplace(id, std::string(text));
    return;
  }
  drain();  // the line may still be in the buffer
  std::vector<SlotLocation> locations = std::move(it->second);
  open_slots_.erase(it);
  if (!slot::fits(text)) {  // the marker stays; the final pass writes the text
    oversize_slots_.emplace(id, std::string(text));
    return;
  }
  const std::string bytes = slot::filled(text);
  for (const SlotLocation& at : locations) {
    Entry& e = entries_[at.entry];
    if (e.deleted || e.generation != at.generation) continue;  // the file was deleted since
    if (e.file && std::fflush(e.file) != 0) io_failure("write", e.temp_path);
    const int fd = ::open(e.temp_path.c_str(), O_WRONLY);
    if (fd < 0) io_failure("write", e.temp_path);
    const bool ok = ::pwrite(fd, bytes.data(), bytes.size(), off_t(at.offset)) == ssize_t(bytes.size());
    if (::close(fd) != 0 || !ok) io_failure("write", e.temp_path);
  }
}

// A line with markers: texts known already go in now, the others are remembered by file offset.
std::string_view OutputFiles::place_slots(std::string_view line, std::string& scratch) {
  Entry& e = entries_[current_];
  scratch.clear();
  std::size_t from = 0;
  while (auto m = slot::find_marker(line, from)) {
    scratch.append(line.substr(from, m->position - from));
    from = m->position + slot::kWidth;
    if (unwritten_slots_ > 0) --unwritten_slots_;
    if (auto early = early_slots_.find(m->id); early != early_slots_.end()) {
      scratch += early->second;
      early_slots_.erase(early);
      continue;
    }
    open_slots_[m->id].push_back(SlotLocation{current_, e.generation, e.size + scratch.size()});
    e.has_slots = true;
    scratch.append(line.substr(m->position, slot::kWidth));
  }
  scratch.append(line.substr(from));
  return scratch;
}

// Markers of open slots in text a `copy` inserted at `offset` of the current file are new places
// to fill. `carry` holds a tail that may be the start of a marker cut by the buffer.
void OutputFiles::note_copied_slots(std::string_view chunk, std::uint64_t offset, std::string& carry, bool last) {
  std::string window = carry + std::string(chunk);
  const std::uint64_t base = offset - carry.size();
  std::size_t from = 0;
  while (auto m = slot::find_marker(window, from)) {
    from = m->position + slot::kWidth;
    if (auto it = open_slots_.find(m->id); it != open_slots_.end()) {
      it->second.push_back(SlotLocation{current_, entries_[current_].generation, base + m->position});
      entries_[current_].has_slots = true;
    } else if (oversize_slots_.count(m->id) != 0) {
      entries_[current_].has_slots = true;
    }
  }
  const std::size_t keep = last ? 0 : std::min(window.size() - std::min(from, window.size()), slot::kWidth - 1);
  carry = window.substr(window.size() - keep);
}

// Rewrites one line for the final pass: filled slots lose their framing, oversize ones get their text.
void OutputFiles::compact(std::string& line) const {
  for (std::size_t at = line.find(slot::kStart); at != std::string::npos; at = line.find(slot::kStart, at)) {
    if (auto text = slot::filled_text(line, at)) {
      const std::string t(*text);
      line.replace(at, slot::kWidth, t);
      at += t.size();
    } else if (auto m = slot::find_marker(std::string_view(line).substr(at, slot::kWidth)); m && m->position == 0) {
      auto it = oversize_slots_.find(m->id);
      if (it == oversize_slots_.end())
        throw std::runtime_error("internal error: placeholder " + std::to_string(m->id) + " was never filled");
      line.replace(at, slot::kWidth, it->second);
      at += it->second.size();
    } else {
      ++at;
    }
  }
}

void OutputFiles::finish_placeholders(bool file_size) {
  for (auto& e : entries_) {
    if (e.deleted || (!e.has_slots && !file_size)) continue;
    close_handle(e);
    std::uintmax_t count = 0, size = 0;
    if (file_size) {
      std::ifstream in(e.temp_path, std::ios::binary);
      for (std::string line; std::getline(in, line);) {
        if (e.has_slots) compact(line);
        size += line.size() + (in.eof() ? 0 : 1);
        for (auto at = line.find(kFileSize); at != std::string::npos; at = line.find(kFileSize, at + kFileSize.size()))
          ++count;
      }
    }
    if (count == 0 && !e.has_slots) continue;
    const std::string size_text = std::to_string(self_consistent_size(size, count));
    fs::path rewritten = e.temp_path;
    rewritten += ".final";
    {
      std::ifstream in(e.temp_path, std::ios::binary);
      std::ofstream out(rewritten, std::ios::binary);
      for (std::string line; std::getline(in, line);) {
        if (e.has_slots) compact(line);
        for (auto at = line.find(kFileSize); count > 0 && at != std::string::npos;
             at = line.find(kFileSize, at + size_text.size()))
          line.replace(at, kFileSize.size(), size_text);
        out << line;
        if (!in.eof()) out << '\n';
      }
      if (!out.flush()) io_failure("write", rewritten);
    }
    fs::rename(rewritten, e.temp_path);
    e.has_slots = false;
  }
  if (!entries_.front().deleted) open_handle(entries_.front(), "ab");
  if (!entries_[current_].deleted) open_handle(entries_[current_], "ab");
}

}  // namespace postproc
