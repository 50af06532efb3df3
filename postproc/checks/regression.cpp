#include "postproc/checks/regression.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "postproc/engine/slot_marker.hpp"
#include "toolpath/bounded_read.hpp"

namespace postproc {
namespace {

class FileLines final : public ExpectedLines {
public:
  explicit FileLines(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) throw std::runtime_error(path + ": cannot open the expected output");
  }
  bool next(ExpectedLine& out) override {
    // NC lines are short: a longer one (/dev/zero, a binary file) would only take memory.
    const toolpath::LineRead got = toolpath::read_line(in_, out.text, kMaxLine);
    if (got == toolpath::LineRead::End) return false;
    ++line_;
    if (got == toolpath::LineRead::TooLong)
      throw std::runtime_error(fmt::format("{}:{}:1: line longer than 16 MiB: not an NC file?", path_, line_));
    if (!out.text.empty() && out.text.back() == '\r') out.text.pop_back();
    return true;
  }

private:
  static constexpr std::size_t kMaxLine = std::size_t{16} << 20;
  std::string path_;
  std::ifstream in_;
  std::size_t line_ = 0;
};

class TraceLines final : public ExpectedLines {
public:
  explicit TraceLines(const std::string& path) : reader_(toolpath::TraceReader::open(path)) {}
  bool next(ExpectedLine& out) override {
    for (;;) {
      while (line_ < command_.trace.size()) {
        const auto& t = command_.trace[line_++];
        if (t.kind == toolpath::TraceLine::Kind::Partial) {
          pending_ = t.text;
          pending_source_ = source();
        }
        if (t.kind != toolpath::TraceLine::Kind::Output) continue;
        pending_.clear();  // the finished line is printed whole
        out.text = t.text;
        out.source = source();
        return true;
      }
      if (!reader_->next(command_)) {
        // A line still unfinished at the end of the trace is the last line of the file.
        if (pending_.empty()) return false;
        out.text = std::move(pending_);
        out.source = std::move(pending_source_);
        pending_.clear();
        return true;
      }
      line_ = 0;
    }
  }

private:
  std::string source() const {
    return fmt::format("trace command #{} {}", command_.index, command_.name);
  }
  std::unique_ptr<toolpath::TraceReader> reader_;
  std::string pending_, pending_source_;
  toolpath::Command command_;
  std::size_t line_ = 0;
};

// NC lines are short; a line of megabytes (a wrong file) is shown by its start.
std::string quoted(std::string_view s) { return fmt::format("`{}`", toolpath::excerpt(s, 200)); }

}  // namespace

std::unique_ptr<ExpectedLines> expected_from_file(const std::string& path) { return std::make_unique<FileLines>(path); }
std::unique_ptr<ExpectedLines> expected_from_trace(const std::string& path) { return std::make_unique<TraceLines>(path); }

RegressionComparer::RegressionComparer(Opener opener, CompareOptions options, std::string post_name)
    : opener_(std::move(opener)), options_(options), post_name_(std::move(post_name)) {}

std::string RegressionComparer::describe(const LineOrigin& o) const {
  if (o.command.empty()) return o.procedure.empty() ? "" : fmt::format("procedure {}", o.procedure);
  std::string s = fmt::format("command #{} {}", o.command_index, o.command);
  if (!o.procedure.empty()) s += fmt::format(", procedure {} ({}:{})", o.procedure, post_name_, o.source_line);
  return s;
}

void RegressionComparer::record(Difference d, std::uint64_t order) {
  if (differences_++ == 0 || order < first_order_) {
    first_ = std::move(d);
    first_order_ = order;
  }
}

void RegressionComparer::compare(Deferred& deferred) {
  Difference& d = deferred.d;
  if (!lines_match(d.expected->text, *d.actual, options_)) record(std::move(d), deferred.order);
}

void RegressionComparer::filled(std::uint32_t id, std::string_view text) {
  for (std::size_t i = 0; i < deferred_.size();) {
    std::string& actual = *deferred_[i].d.actual;
    for (auto m = slot::find_marker(actual); m; m = slot::find_marker(actual, m->position + 1))
      if (m->id == id) actual.replace(m->position, slot::kWidth, text);
    if (slot::find_marker(actual)) {
      ++i;
      continue;
    }
    compare(deferred_[i]);
    deferred_.erase(deferred_.begin() + std::ptrdiff_t(i));
  }
}

void RegressionComparer::produced(const std::string& stream, std::string_view text, const LineOrigin& origin) {
  auto it = streams_.find(stream);
  if (it == streams_.end()) {
    it = streams_.emplace(stream, Stream{}).first;
    it->second.expected = opener_(stream);
    if (!it->second.expected) unmatched_.push_back(stream);
  }
  Stream& s = it->second;
  ++s.line;
  const std::uint64_t order = produced_++;
  if (!s.expected) return;
  ++compared_;
  if (!s.expected_done && s.expected->next(scratch_)) {
    if (slot::find_marker(text))
      deferred_.push_back({{stream, s.line, scratch_, std::string(text), describe(origin)}, order});
    else if (!lines_match(scratch_.text, text, options_))
      record({stream, s.line, scratch_, std::string(text), describe(origin)}, order);
  } else {
    s.expected_done = true;
    record({stream, s.line, std::nullopt, std::string(text), describe(origin)}, order);
  }
}

void RegressionComparer::discarded(const std::string& stream) {
  auto it = streams_.find(stream);
  if (it == streams_.end() || it->second.expected) return;
  std::erase(unmatched_, stream);
  streams_.erase(it);
}

void RegressionComparer::finish() {
  for (auto& d : deferred_) {  // placeholders never filled (the run failed): shown as `{?N}`
    *d.d.actual = slot::readable(*d.d.actual);
    compare(d);
  }
  deferred_.clear();
  for (auto& [name, s] : streams_) {
    if (!s.expected || s.expected_done) continue;
    while (s.expected->next(scratch_)) record({name, ++s.line, scratch_, std::nullopt, ""}, produced_++);
    s.expected_done = true;
  }
}

std::string RegressionComparer::report() const {
  if (!first_) return {};
  const Difference& d = *first_;
  std::string r = fmt::format("{}:{}: ", d.stream, d.line);
  if (d.expected && d.actual)
    r += "the output differs from the expected line\n";
  else if (d.actual)
    r += "the output has more lines than expected\n";
  else
    r += "the output ended before the expected line\n";
  if (d.expected) {
    r += fmt::format("  expected: {}", quoted(d.expected->text));
    if (!d.expected->source.empty()) r += fmt::format("  ({})", d.expected->source);
    r += '\n';
  }
  if (d.actual) r += fmt::format("  actual:   {}\n", quoted(*d.actual));
  if (!d.origin.empty()) r += fmt::format("  produced by {}\n", d.origin);
  if (differences_ > 1) r += fmt::format("{} differing lines in all\n", differences_);
  return r;
}

}  // namespace postproc
