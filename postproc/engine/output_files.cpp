#include "postproc/engine/output_files.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "toolpath/value.hpp"

namespace postproc {
namespace fs = std::filesystem;

namespace {

constexpr std::size_t npos = static_cast<std::size_t>(-1);
constexpr std::size_t kBufferSize = std::size_t{1} << 16;

// Hands each complete line of `chunk` (LF or CR LF ends) to `line`; an unfinished one stays in `partial`.
constexpr std::size_t kMaxCopiedLine = std::size_t{16} << 20;

void split_lines(std::string_view chunk, std::string& partial, const OutputFiles::LineCallback& line) {
  for (;;) {
    std::size_t end = chunk.find('\n');
    if (end == std::string_view::npos) {
      partial.append(chunk);
      return;
    }
    partial.append(chunk.substr(0, end));
    if (!partial.empty() && partial.back() == '\r') partial.pop_back();
    line(partial);
    partial.clear();
    chunk.remove_prefix(end + 1);
  }
}

// A line's bytes without a library call (which costs more than copying a 20-byte NC block): word
// copies, the last one overlapping the one before. No byte outside the line is read.
[[gnu::always_inline]] inline void copy_line(char* to, std::string_view line) {
  const char* from = line.data();
  const std::size_t n = line.size();
  auto copy = [&]<std::size_t Word>(std::size_t at) {
    char word[Word];
    std::memcpy(word, from + at, Word);
    std::memcpy(to + at, word, Word);
  };
  if (n >= 16) {
    for (std::size_t at = 0; at + 16 < n; at += 16) copy.template operator()<16>(at);
    copy.template operator()<16>(n - 16);
  } else if (n >= 8) {
    copy.template operator()<8>(0);
    copy.template operator()<8>(n - 8);
  } else if (n >= 4) {
    copy.template operator()<4>(0);
    copy.template operator()<4>(n - 4);
  } else if (n > 0) {
    to[0] = from[0], to[n / 2] = from[n / 2], to[n - 1] = from[n - 1];  // 1 to 3 bytes: all of them
  }
}

// A line's break (`eol` bytes: none, LF or CR LF) and then its bytes, from `out`.
[[gnu::always_inline]] inline void put_line(char* out, std::size_t eol, std::string_view line) {
  if (eol == 2) *out++ = '\r';
  if (eol > 0) *out++ = '\n';
  copy_line(out, line);
}

[[noreturn]] void io_failure(const std::string& what, const fs::path& path) {
  throw std::runtime_error("cannot " + what + " `" + path.string() + "`: " + std::strerror(errno));
}

fs::path make_private_dir(const fs::path& parent) {
  std::string pattern = (parent / ".postproc-XXXXXX").string();
  if (!mkdtemp(pattern.data())) io_failure("create a temporary folder in", parent);
  return pattern;
}

}  // namespace

OutputFiles::OutputFiles(fs::path directory, LineEnd line_end, bool for_stream)
    : directory_(std::move(directory)), line_end_(line_end), buffer_(kBufferSize) {
  if (directory_.empty()) directory_ = ".";
  temp_dir_ = make_private_dir(for_stream ? fs::temp_directory_path() : directory_);
  create("");
  open_handle(entries_.front(), "wb");
}

OutputFiles::~OutputFiles() {
  buffered_ = 0;  // the run failed or was committed: the temporaries go
  for (auto& e : entries_) close_handle(e);
  std::error_code ignored;
  fs::remove_all(temp_dir_, ignored);
}

void OutputFiles::discard() {
  buffered_ = 0;
  for (auto& e : entries_) {
    if (e.file) std::fclose(e.file);
    e.file = nullptr;
    std::error_code ignored;
    fs::remove(e.temp_path, ignored);
  }
  entries_.clear();
  current_ = 0;
  next_slot_ = 0;
  unwritten_slots_ = 0;
  open_slots_.clear();
  early_slots_.clear();
  oversize_slots_.clear();
  break_taken_ = false;
  create("");
  open_handle(entries_.front(), "wb");
}

void OutputFiles::set_main_path(fs::path path) { entries_.front().final_path = std::move(path); }

std::size_t OutputFiles::find(std::string_view name) const {
  for (std::size_t i = 1; i < entries_.size(); ++i)
    if (toolpath::iequals(entries_[i].name, name)) return i;
  return npos;
}

// Names are relative to the output folder. Windows paths are accepted: backslashes separate folders,
// and an absolute path (`C:\NC\O1.SPF`, `/tmp/x`) keeps only its file name, so that a post written
// for a Windows workstation never writes outside the chosen folder.
fs::path OutputFiles::resolve(std::string_view name) const {
  std::string n(name);
  for (char& c : n)
    if (c == '\\') c = '/';
  bool absolute = (!n.empty() && n.front() == '/') || (n.size() >= 2 && n[1] == ':');
  fs::path p(n);
  return directory_ / (absolute ? p.filename() : p);
}

std::size_t OutputFiles::create(std::string_view name) {
  Entry e;
  e.name = std::string(name);
  if (!name.empty()) e.final_path = resolve(name);
  e.temp_path = temp_dir_ / std::to_string(entries_.size());
  entries_.push_back(std::move(e));
  return entries_.size() - 1;
}

void OutputFiles::open_handle(Entry& e, const char* mode) {
  if (e.file) return;
  e.file = std::fopen(e.temp_path.c_str(), mode);
  if (!e.file) io_failure("create", e.temp_path);
  std::setvbuf(e.file, nullptr, _IOFBF, 1 << 16);
}

void OutputFiles::close_handle(Entry& e) {
  drain();
  if (!e.file) return;
  bool failed = std::fclose(e.file) != 0;
  e.file = nullptr;
  if (failed && !committed_) io_failure("write", e.temp_path);
}

void OutputFiles::switch_to(std::size_t index) {
  if (index == current_) return;
  drain();
  if (current_ != 0) close_handle(entries_[current_]);  // the main file stays open, others are reopened
  current_ = index;
  open_handle(entries_[current_], "ab");
}

[[gnu::noinline]] std::size_t OutputFiles::write_slowly(std::string_view line, std::size_t eol, std::size_t lines) {
  if (unwritten_slots_ > 0 && line.find('\x02') != std::string_view::npos) {
    append(std::string_view("\r\n").substr(2 - eol));  // placeholders are found by offset: the break first
    append(place_slots(line, slot_line_));
    return lines;
  }
  put_line(room(eol + line.size()), eol, line);
  return lines;
}

std::size_t OutputFiles::write_line(std::string_view line, bool after_break) {
  const std::size_t eol = after_break && !break_taken_ ? (line_end_ == LineEnd::CRLF ? 2 : 1) : 0;
  const std::size_t lines = break_starts_file(after_break) ? 2 : 1;
  break_taken_ = false;
  const std::size_t n = eol + line.size();
  // Placeholders, or a buffer to drain first: out of line, so that the usual line calls nothing.
  if (unwritten_slots_ > 0 || buffer_.size() - buffered_ < n) return write_slowly(line, eol, lines);
  // The usual line: its break and its text in one copy.
  entries_[current_].size += n;
  put_line(buffer_.data() + buffered_, eol, line);
  buffered_ += n;
  return lines;
}

void OutputFiles::append(std::string_view bytes) {
  if (!bytes.empty()) std::memcpy(room(bytes.size()), bytes.data(), bytes.size());
}

char* OutputFiles::room(std::size_t n) {
  entries_[current_].size += n;
  if (buffered_ + n > buffer_.size()) {
    drain();
    if (n > buffer_.size()) buffer_.resize(n);
  }
  char* out = buffer_.data() + buffered_;
  buffered_ += n;
  return out;
}

void OutputFiles::drain() {
  if (buffered_ == 0) return;
  const std::size_t n = std::exchange(buffered_, 0);
  Entry& e = entries_[current_];
  if (!e.file || fwrite_unlocked(buffer_.data(), 1, n, e.file) != n) io_failure("write", e.temp_path);
}

void OutputFiles::execute(const Directive& d, const LineCallback& copied_line, bool after_break) {
  write_line({}, after_break);
  run(d, copied_line);
  break_taken_ = true;
}

void OutputFiles::run(const Directive& d, const LineCallback& copied_line) {
  std::size_t index = find(d.name);
  switch (d.verb) {
    case Directive::Verb::Open:
      if (index == npos) {
        index = create(d.name);
      } else if (entries_[index].deleted) {  // deleted earlier in this run: starts empty again
        entries_[index].deleted = false;
        std::error_code ignored;
        fs::remove(entries_[index].temp_path, ignored);
      }
      switch_to(index);  // an existing file of this run is appended to
      return;
    case Directive::Verb::Close:
      if (index != npos && index == current_) switch_to(0);
      return;
    case Directive::Verb::Delete:
      if (index == npos) index = create(d.name);  // a file of an earlier run: removed on commit
      if (index == current_) switch_to(0);
      close_handle(entries_[index]);
      entries_[index].deleted = true;
      entries_[index].size = 0;
      ++entries_[index].generation;
      {
        std::error_code ignored;
        fs::remove(entries_[index].temp_path, ignored);
      }
      return;
    case Directive::Verb::Copy:
      copy_into_current(d.name, copied_line);
      return;
    case Directive::Verb::MakeDir: {
      std::error_code error;
      fs::create_directories(resolve(d.name), error);
      if (error) throw std::runtime_error("cannot make folder `" + resolve(d.name).string() + "`: " + error.message());
      return;
    }
  }
}

void OutputFiles::copy_into_current(std::string_view name, const LineCallback& copied_line) {
  std::size_t index = find(name);
  fs::path source;
  if (index != npos && !entries_[index].deleted) {
    if (index == current_) throw std::runtime_error("cannot copy `" + std::string(name) + "` into itself");
    if (entries_[index].file && std::fflush(entries_[index].file) != 0) io_failure("write", entries_[index].temp_path);
    source = entries_[index].temp_path;
  } else {
    source = resolve(name);  // a file made before this run
  }
  std::ifstream in(source, std::ios::binary);
  if (!in) throw std::runtime_error("cannot copy `" + std::string(name) + "`: no such file in this run or in `" +
                                    directory_.string() + "`");
  drain();
  std::FILE* out = entries_[current_].file;
  std::string partial;  // a line cut by the end of a buffer
  std::string carry;    // a placeholder cut by the end of a buffer
  const bool slots = !open_slots_.empty() || !oversize_slots_.empty();
  char buffer[1 << 14];
  while (in) {
    in.read(buffer, sizeof buffer);
    auto n = static_cast<std::size_t>(in.gcount());
    if (n && fwrite_unlocked(buffer, 1, n, out) != n) io_failure("write", entries_[current_].temp_path);
    if (slots) note_copied_slots(std::string_view(buffer, n), entries_[current_].size, carry, !in);
    entries_[current_].size += n;
    if (copied_line) split_lines(std::string_view(buffer, n), partial, copied_line);
    // The lines are handed on one by one: a file in the folder without line ends (a binary
    // file, a link to a device) must not gather in memory.
    if (partial.size() > kMaxCopiedLine)
      throw std::runtime_error("cannot copy `" + std::string(name) + "`: line longer than 16 MiB: not an NC file?");
  }
  if (copied_line && !partial.empty()) copied_line(partial);
}

std::string OutputFiles::display_name(const Entry& e) const {
  if (!e.name.empty()) return e.name;
  return e.final_path.empty() ? std::string("(main file)") : e.final_path.filename().string();
}

std::string OutputFiles::current_name() const { return display_name(entries_[current_]); }

// Two phases, so that a failure leaves every final name as it was: first each file is staged next
// to its final name (rename, or copy when the temporary folder is on another file system: a full
// disk fails here) and devices are written through; only then are the staged files renamed onto
// their names, which within one folder cannot run out of space.
std::vector<fs::path> OutputFiles::commit() {
  for (auto& e : entries_) close_handle(e);
  if (entries_.front().final_path.empty()) throw std::runtime_error("the main output file has no name");
  std::vector<std::pair<fs::path, fs::path>> staged;  // staged file -> final name
  auto discard_staged = [&] {
    std::error_code ignored;
    for (const auto& s : staged) fs::remove(s.first, ignored);
  };
  std::vector<const Entry*> devices;
  for (auto& e : entries_) {
    if (e.deleted) continue;
    std::error_code error;
    if (e.final_path.has_parent_path()) fs::create_directories(e.final_path.parent_path(), error);
    if (fs::exists(e.final_path, error) && !fs::is_regular_file(e.final_path, error)) {
      devices.push_back(&e);  // a device or a pipe: replacing it would destroy it
      continue;
    }
    fs::path stage = e.final_path;
    stage += ".postproc-new";
    fs::rename(e.temp_path, stage, error);
    if (error) {
      error.clear();
      fs::copy_file(e.temp_path, stage, fs::copy_options::overwrite_existing, error);
    }
    if (error) {
      fs::remove(stage, error);
      discard_staged();
      throw std::runtime_error("cannot write `" + e.final_path.string() + "`: " + error.message());
    }
    staged.emplace_back(std::move(stage), e.final_path);
  }
  try {
    for (const Entry* d : devices) write_through(d->temp_path, d->final_path);
  } catch (...) {
    discard_staged();
    throw;
  }
  std::vector<fs::path> written;
  for (const Entry* d : devices) written.push_back(d->final_path);
  for (const auto& [stage, final_path] : staged) {
    std::error_code error;
    fs::rename(stage, final_path, error);
    if (error) throw std::runtime_error("cannot write `" + final_path.string() + "`: " + error.message());
    written.push_back(final_path);
  }
  for (auto& e : entries_) {
    std::error_code ignored;
    if (e.deleted) fs::remove(e.final_path, ignored);
  }
  committed_ = true;
  std::error_code ignored;
  fs::remove_all(temp_dir_, ignored);
  return written;
}

// Copies a finished temporary into a file that is not a regular file (/dev/stdout, /dev/full, a
// FIFO): no rename is possible, so a failed write must at least be an error.
void OutputFiles::write_through(const fs::path& from, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  std::ofstream out(to, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write `" + to.string() + "`: " + std::strerror(errno));
  if (in.peek() != std::ifstream::traits_type::eof()) out << in.rdbuf();
  out.flush();
  if (!out) throw std::runtime_error("cannot write `" + to.string() + "`: " + std::strerror(errno));
}

void OutputFiles::commit_to(std::ostream& out) {
  for (auto& e : entries_) close_handle(e);
  std::size_t live = 0;
  for (const auto& e : entries_) live += !e.deleted;
  bool first = true;
  for (const auto& e : entries_) {
    if (e.deleted) continue;
    if (live > 1) out << (first ? "" : "\n") << "==> " << display_name(e) << " <==\n";
    first = false;
    std::ifstream in(e.temp_path, std::ios::binary);
    if (in.peek() != std::ifstream::traits_type::eof()) out << in.rdbuf();  // an empty file would fail `out`
  }
  out.flush();
  committed_ = true;
  std::error_code ignored;
  fs::remove_all(temp_dir_, ignored);
  if (!out) throw std::runtime_error(std::string("cannot write the output: ") + std::strerror(errno));  // a full disk
}

}  // namespace postproc
