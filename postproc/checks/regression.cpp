#include "postproc/checks/regression.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "postproc/engine/slot_marker.hpp"
#include "toolpath/bounded_read.hpp"
#include "toolpath/value.hpp"

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
  if (!o.procedure.empty())
    s += fmt::format(", procedure {} ({}:{})", o.procedure, o.include_file.empty() ? std::string_view(post_name_) : o.include_file,
                     o.source_line);
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
    streams_[deferred_[i].d.stream].produced_lines[deferred_[i].d.line - 1] = actual;
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
  if (s.held) release(stream, s);
  if (file_lines_ && text.empty()) {
    // An empty line is a line of the file only once a break follows it (break_written or the next
    // line); the one `{nb, 'M2 ', nl}` leaves at the very end is not.
    s.held = true;
    s.held_origin = describe(origin);
    s.held_order = produced_++;
    return;
  }
  compare_line(stream, s, text, describe(origin), produced_++);
}

void RegressionComparer::break_written(const std::string& stream) {
  auto it = streams_.find(stream);
  if (it != streams_.end() && it->second.held) release(stream, it->second);
}

void RegressionComparer::release(const std::string& stream, Stream& s) {
  s.held = false;
  compare_line(stream, s, {}, std::move(s.held_origin), s.held_order);
}

void RegressionComparer::compare_line(const std::string& stream, Stream& s, std::string_view text, std::string origin,
                                      std::uint64_t order) {
  ++s.line;
  if (!s.expected) return;
  ++compared_;
  s.produced_lines.emplace_back(text);
  if (keep_origins_) s.origins.push_back(origin);
  if (!s.expected_done && s.expected->next(scratch_)) {
    s.expected_lines.push_back(scratch_.text);
    if (slot::find_marker(text))
      deferred_.push_back({{stream, s.line, scratch_, std::string(text), std::move(origin)}, order});
    else if (!lines_match(scratch_.text, text, options_))
      record({stream, s.line, scratch_, std::string(text), std::move(origin)}, order);
  } else {
    s.expected_done = true;
    record({stream, s.line, std::nullopt, std::string(text), std::move(origin)}, order);
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
    streams_[d.d.stream].produced_lines[d.d.line - 1] = *d.d.actual;
    compare(d);
  }
  deferred_.clear();
  for (auto& [name, s] : streams_) {
    if (!s.expected || s.expected_done) continue;
    while (s.expected->next(scratch_)) {
      s.expected_lines.push_back(scratch_.text);
      record({name, ++s.line, scratch_, std::nullopt, ""}, produced_++);
    }
    s.expected_done = true;
  }
}

bool RegressionComparer::has_stream(const std::string& name) const {
  for (const auto& [stream, s] : streams_)
    if (toolpath::iequals(stream, name)) return true;
  return false;
}

void RegressionComparer::not_written(const std::string& stream) {
  if (streams_.count(stream)) return;
  Stream& s = streams_[stream];
  s.expected = opener_(stream);
  s.written = false;
  if (!s.expected) return;
  while (s.expected->next(scratch_)) {
    s.expected_lines.push_back(scratch_.text);
    record({stream, ++s.line, scratch_, std::nullopt, "the run wrote no such file"}, produced_++);
  }
  s.expected_done = true;
}

// Myers' O(ND) difference algorithm on the lines as the comparison sees them (the options
// applied, each distinct line numbered once), stopping at kMaxEdits: past that the streams are
// too different for an alignment to mean much, and they are compared place by place.
RegressionComparer::Alignment RegressionComparer::align(const Stream& s) const {
  constexpr long kMaxEdits = 2000;
  std::unordered_map<std::string, int> ids;
  auto numbered = [&](const std::vector<std::string>& lines) {
    std::vector<int> out;
    out.reserve(lines.size());
    for (const auto& l : lines) out.push_back(ids.emplace(normalize_line(l, options_), int(ids.size())).first->second);
    return out;
  };
  const std::vector<int> a = numbered(s.expected_lines), b = numbered(s.produced_lines);
  const long n = long(a.size()), m = long(b.size());
  Alignment result;
  const long max = std::min(n + m, kMaxEdits);
  std::vector<long> v(std::size_t(2 * max + 2), 0);
  // For the way back, what round d-1 left for round d: v at k = -(d-1), -(d-1)+2, .., d-1 (d values,
  // 32-bit: about 8 MB at the 2000-edit limit).
  std::vector<std::vector<std::int32_t>> history;
  long found = -1;
  for (long d = 0; d <= max && found < 0; ++d) {
    std::vector<std::int32_t>& before = history.emplace_back(std::size_t(d));
    for (long k = -(d - 1), i = 0; k <= d - 1; k += 2, ++i) before[std::size_t(i)] = std::int32_t(v[std::size_t(k + max)]);
    for (long k = -d; k <= d; k += 2) {
      const std::size_t at = std::size_t(k + max);
      long x = (k == -d || (k != d && v[at - 1] < v[at + 1])) ? v[at + 1] : v[at - 1] + 1;
      long y = x - k;
      while (x < n && y < m && a[std::size_t(x)] == b[std::size_t(y)]) ++x, ++y;
      v[at] = x;
      if (x >= n && y >= m) {
        found = d;
        break;
      }
    }
  }
  if (found < 0) {  // place by place
    result.approximate = true;
    const std::size_t common = std::min(a.size(), b.size());
    for (std::size_t i = 0; i < common; ++i)
      if (a[i] != b[i]) result.hunks.push_back({i, 1, i, 1});
    if (a.size() != b.size())
      result.hunks.push_back({common, a.size() - common, common, b.size() - common});
    return result;
  }
  // Back from (n, m): each round adds one deleted or inserted line, then a run of equal ones.
  std::vector<DiffHunk> edits;  // one line each, from the end
  long x = n, y = m;
  for (long d = found; d > 0; --d) {
    const std::vector<std::int32_t>& before = history[std::size_t(d)];
    auto pv = [&](long kk) { return long(before[std::size_t((kk + d - 1) / 2)]); };
    const long k = x - y;
    const bool down = k == -d || (k != d && pv(k - 1) < pv(k + 1));
    const long pk = down ? k + 1 : k - 1;
    const long px = pv(pk), py = px - pk;
    while (x > px + (down ? 0 : 1) && y > py + (down ? 1 : 0)) --x, --y;  // the equal run
    if (down) edits.push_back({std::size_t(px), 0, std::size_t(py), 1});  // inserted b[py]
    else edits.push_back({std::size_t(px), 1, std::size_t(py), 0});      // deleted a[px]
    x = px;
    y = py;
  }
  // Adjacent single edits become hunks.
  for (auto it = edits.rbegin(); it != edits.rend(); ++it) {
    if (!result.hunks.empty()) {
      DiffHunk& last = result.hunks.back();
      if (last.expected_first + last.expected_count == it->expected_first &&
          last.produced_first + last.produced_count == it->produced_first) {
        last.expected_count += it->expected_count;
        last.produced_count += it->produced_count;
        continue;
      }
    }
    result.hunks.push_back(*it);
  }
  return result;
}

StreamParity RegressionComparer::figure(const std::string& name, const Stream& s) const {
  StreamParity p;
  p.stream = name;
  p.expected = s.expected_lines.size();
  p.produced = s.produced_lines.size();
  p.written = s.written;
  if (!s.written) {  // nothing to align: every line is missing
    p.first_difference = p.expected > 0 ? 1 : 0;
    return p;
  }
  const Alignment alignment = align(s);
  p.approximate = alignment.approximate;
  std::size_t missing = 0;
  auto differs_at = [&](std::size_t expected_line) {
    if (p.first_difference == 0) p.first_difference = expected_line + 1;
  };
  for (const DiffHunk& h : alignment.hunks) {
    // Lines that differ only where the options allow (a date, a number within tolerance) count as
    // identical when they stand in the same place of a hunk.
    if (h.expected_count == 0) differs_at(h.expected_first);  // lines of ours SolidCAM does not have
    for (std::size_t i = 0; i < h.expected_count; ++i) {
      if (i < h.produced_count &&
          lines_match(s.expected_lines[h.expected_first + i], s.produced_lines[h.produced_first + i], options_))
        continue;
      ++missing;
      differs_at(h.expected_first + i);
    }
    if (h.produced_count > h.expected_count) differs_at(h.expected_first + h.expected_count);
  }
  p.identical = p.expected - missing;
  return p;
}

std::vector<StreamParity> RegressionComparer::parity() const {
  std::vector<StreamParity> out;
  for (const auto& [name, s] : streams_)
    if (s.expected) out.push_back(figure(name, s));
  return out;
}

std::string RegressionComparer::diff_report() const {
  std::string r;
  for (const auto& [name, s] : streams_) {
    if (!s.expected) continue;
    if (!s.written) {  // the figure says it; its lines are the golden file's
      r += fmt::format("@@ {}: the run wrote no such file ({} lines expected) @@\n", name, s.expected_lines.size());
      continue;
    }
    const Alignment alignment = align(s);
    for (const DiffHunk& h : alignment.hunks) {
      bool same = h.expected_count == h.produced_count;
      for (std::size_t i = 0; same && i < h.expected_count; ++i)
        same = lines_match(s.expected_lines[h.expected_first + i], s.produced_lines[h.produced_first + i], options_);
      if (same) continue;
      r += fmt::format("@@ {} expected line {}, output line {} @@\n", name, h.expected_first + 1, h.produced_first + 1);
      for (std::size_t i = 0; i < h.expected_count; ++i)
        r += fmt::format("- {}\n", toolpath::excerpt(s.expected_lines[h.expected_first + i], 200));
      for (std::size_t i = 0; i < h.produced_count; ++i) {
        const std::size_t at = h.produced_first + i;
        r += fmt::format("+ {}", toolpath::excerpt(s.produced_lines[at], 200));
        if (at < s.origins.size() && !s.origins[at].empty()) r += fmt::format("    <- {}", s.origins[at]);
        r += '\n';
      }
    }
  }
  return r;
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
