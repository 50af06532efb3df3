// The NC files of one run. Lines go to the current file; directives switch, delete and copy files the
// way SolidCAM does (solidcam-behaviour.md section 2). Everything is written to temporaries in a
// private folder and only moved onto the real names by commit(): a run that fails leaves the files of
// the previous run untouched.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "postproc/engine/directive.hpp"

namespace postproc {

class OutputFiles {
public:
  enum class LineEnd { LF, CRLF };

  // Files that directives name are placed in `directory` (which must exist). With `for_stream`, the
  // temporaries live in the system's temporary folder and the run ends with commit_to(stream).
  explicit OutputFiles(std::filesystem::path directory, LineEnd line_end = LineEnd::LF, bool for_stream = false);
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  // The final path of the main file (it may be set late: its name comes with @start_of_file).
  void set_main_path(std::filesystem::path path);
  const std::filesystem::path& main_path() const { return entries_.front().final_path; }

  // Appends one line to the current file. SolidCAM writes the line break before a block, not after
  // it (`nl` and `nb` start a line): with `after_break` the break goes first, unless the directive
  // just executed took it (the break that ends a `!! ... !!` line goes with it). So a file begins
  // with an empty line and ends without a final break, as SolidCAM's do (docs/engine.md, "Line breaks").
  // Returns the lines the file gained: 2 when the break began it (break_starts_file), else 1.
  std::size_t write_line(std::string_view line, bool after_break = true);
  // True when write_line(…, after_break) would begin the current file with an empty line.
  bool break_starts_file(bool after_break) const {
    return after_break && !break_taken_ && entries_[current_].size == 0;
  }
  // Executes a directive line. The break before it (`after_break`, as for a line) stays in the file
  // current before it; the break after it goes with it. Throws std::runtime_error when it cannot (a
  // file to copy that does not exist). `copied_line`, when given, receives each line a `copy`
  // inserted (without its line end), so that observers see the copied text as lines of the current file.
  using LineCallback = std::function<void(std::string_view)>;
  void execute(const Directive& directive, const LineCallback& copied_line = {}, bool after_break = true);

  // The current file's name: as the directive wrote it, or the main file's name.
  std::string current_name() const;
  bool current_is_main() const { return current_ == 0; }

  // Text known only after its line is written (start_line/end_line, docs/engine.md): new_slot()
  // reserves a placeholder and gives the marker to put in the line; fill_slot() supplies the text,
  // before or after the line is written, and writes it into the file in place. Memory holds only
  // the slots not yet filled (and a filled text too long for its slot, until the end).
  std::uint32_t new_slot(std::string& marker);
  void fill_slot(std::uint32_t id, std::string_view text);
  // The final pass, after the last line and before commit: every file with placeholders is
  // rewritten without their framing; with `file_size` (`print_file_size = 1`), each `$$file_size$$`
  // becomes that file's final size in bytes (line ends included). Streams, two passes at most.
  void finish_placeholders(bool file_size);
  // Forgets everything written: the files are as they were when this was made (a run that starts
  // again from the beginning).
  void discard();
  // Moves every file onto its final name and removes the files the run deleted. Returns the paths written.
  std::vector<std::filesystem::path> commit();
  // Writes every file, in the order they were created, to `out`; when there are several, each starts
  // with a `==> NAME <==` line, as `head` does. Nothing is written to disk.
  void commit_to(std::ostream& out);

private:
  static void write_through(const std::filesystem::path& from, const std::filesystem::path& to);
  struct Entry {
    std::string name;  // as the post wrote it ("" for the main file)
    std::filesystem::path final_path;
    std::filesystem::path temp_path;
    std::FILE* file = nullptr;  // open while it is the current file (the main file stays open)
    bool deleted = false;
    std::uint64_t size = 0;       // bytes written so far (placeholders are found by offset)
    std::uint32_t generation = 0; // counts deletions: a placeholder in a deleted file is dropped
    bool has_slots = false;       // placeholders were written: the final pass rewrites the file
  };
  struct SlotLocation {
    std::size_t entry = 0;
    std::uint32_t generation = 0;
    std::uint64_t offset = 0;
  };

  std::size_t find(std::string_view name) const;  // npos when the run has no such file
  std::filesystem::path resolve(std::string_view name) const;
  std::size_t create(std::string_view name);
  void open_handle(Entry& e, const char* mode);
  void close_handle(Entry& e);
  void switch_to(std::size_t index);
  void run(const Directive& directive, const LineCallback& copied_line);
  std::size_t write_slowly(std::string_view line, std::size_t eol, std::size_t lines);  // write_line's rare cases
  void append(std::string_view bytes);  // to the current file, through the buffer
  char* room(std::size_t n);            // n bytes of the buffer for the current file, counted in its size
  void drain();  // the buffered lines into the current file's stream
  void copy_into_current(std::string_view name, const LineCallback& copied_line);
  std::string display_name(const Entry& e) const;
  // output_slots.cpp
  std::string_view place_slots(std::string_view line, std::string& scratch);
  void note_copied_slots(std::string_view chunk, std::uint64_t offset, std::string& carry, bool last);
  void compact(std::string& line) const;

  std::filesystem::path directory_;
  std::filesystem::path temp_dir_;
  LineEnd line_end_;
  std::vector<Entry> entries_;
  std::size_t current_ = 0;
  bool committed_ = false;
  std::uint32_t next_slot_ = 0;
  std::size_t unwritten_slots_ = 0;  // markers handed out and not yet seen in a written line
  std::unordered_map<std::uint32_t, std::vector<SlotLocation>> open_slots_;  // written, not filled
  std::unordered_map<std::uint32_t, std::string> early_slots_;     // filled before written
  std::unordered_map<std::uint32_t, std::string> oversize_slots_;  // filled, too long to write in place
  std::string slot_line_;
  // Lines of the current file wait here and go to its stream in large writes (one fwrite a line
  // cost more than the rest of the hand-off). Drained before anything else touches a stream.
  std::vector<char> buffer_;
  std::size_t buffered_ = 0;
  bool break_taken_ = false;  // a directive took the break before the next line
};

}  // namespace postproc
