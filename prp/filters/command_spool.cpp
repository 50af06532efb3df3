#include "prp/filters/command_spool.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include "toolpath/short_text.hpp"

namespace prp {
namespace {

using toolpath::ParamKey;
using toolpath::ValueKind;

// Record layout: a u32 payload length, then the payload: the command's kind (u8), name, index,
// depth, line, the parameters, the trace lines. A parameter is a u16 name code, its kind and flag
// in one byte, its line and column, only the field of its kind, then its name as text when the code
// is 0. The code is the ParamKey when the name is spelled exactly as the catalogue spells it (no
// hashing when it is read back), else 0. Texts are a u32 length and the bytes; numbers are raw.
constexpr std::size_t kBlock = std::size_t{1} << 20;
constexpr std::size_t kParameterFixed = 2 + 1 + 4 + 4;  // code, kind and flag, line, column
constexpr unsigned kKinds = 1
#define PRP_KIND_COUNT(kind, name) +1
    PRP_COMMAND_KINDS(PRP_KIND_COUNT)
#undef PRP_KIND_COUNT
    ;

[[noreturn]] void damaged() { throw std::runtime_error("the temporary file of jobs is damaged"); }

// Writes into a buffer already large enough (see bound()).
class Writer {
public:
  explicit Writer(char* at) : at_(at) {}
  template <class T>
  void put(T v) {
    std::memcpy(at_, &v, sizeof v);
    at_ += sizeof v;
  }
  void text(std::string_view s) {
    put(static_cast<std::uint32_t>(s.size()));
    std::memcpy(at_, s.data(), s.size());
    at_ += s.size();
  }
  char* at() const { return at_; }

private:
  char* at_;
};

// The largest record a command can make.
std::size_t bound(const toolpath::Command& c) {
  std::size_t n = 4 + 1 + 4 + c.name.size() + 8 + 4 + 4 + 4 + 4;
  for (const auto& p : c.parameters) n += kParameterFixed + 8 + 4 + p.value.text.size() + 4 + p.name.size();
  for (const auto& t : c.trace) n += 1 + 4 + t.text.size();
  return n;
}

// Reads the payload of one record: need() checks that the next bytes are there, once for the
// fields that follow, and get() takes them.
class Cursor {
public:
  Cursor(const char* at, std::size_t size) : at_(at), left_(size) {}
  void need(std::size_t n) const {
    if (n > left_) damaged();
  }
  template <class T>
  T get() {
    T v;
    std::memcpy(&v, at_, sizeof v);
    at_ += sizeof v;
    left_ -= sizeof v;
    return v;
  }
  std::string_view text() {
    need(4);
    const auto n = get<std::uint32_t>();
    need(n);
    const std::string_view s(at_, n);
    at_ += n;
    left_ -= n;
    return s;
  }

private:
  const char* at_;
  std::size_t left_;
};

// `s` holds `text` afterwards; its buffer is kept when it already does (a reused command's names).
void assign(std::string& s, std::string_view text) {
  if (!toolpath::same_short_text(s, text)) s.assign(text);
}

}  // namespace

CommandSpool::CommandSpool() : file_(std::tmpfile()), out_(new char[kBlock]), capacity_(kBlock) {
  if (!file_) throw std::runtime_error("cannot create a temporary file to hold jobs being reordered");
  std::setvbuf(file_.get(), nullptr, _IONBF, 0);  // whole blocks only: our own buffers are the cache
}

void CommandSpool::flush() {
  if (used_ == 0) return;
  if (std::fseek(file_.get(), static_cast<long>(flushed_), SEEK_SET) != 0 ||
      std::fwrite(out_.get(), 1, used_, file_.get()) != used_)
    throw std::runtime_error("cannot write the temporary file of jobs being reordered (disk full?)");
  flushed_ += static_cast<std::int64_t>(used_);
  used_ = 0;
}

std::int64_t CommandSpool::write(const toolpath::Command& c, CommandKind kind) {
  const std::size_t most = bound(c);
  if (used_ + most > capacity_) {
    flush();
    if (most > capacity_) {  // a command larger than a block
      out_.reset(new char[most]);
      capacity_ = most;
    }
  }
  const std::int64_t at = end();
  const std::size_t start = used_;
  Writer w(out_.get() + start + 4);
  w.put(static_cast<std::uint8_t>(kind));
  w.text(c.name);
  w.put(static_cast<std::uint64_t>(c.index));
  w.put(static_cast<std::int32_t>(c.depth));
  w.put(c.line);  // positions travel with the job, for errors found when it is posted
  w.put(static_cast<std::uint32_t>(c.parameters.size()));
  for (const auto& p : c.parameters) {
    const bool catalogued =
        p.key != ParamKey::none && toolpath::same_short_text(p.name, toolpath::param_name(p.key));
    w.put(static_cast<std::uint16_t>(catalogued ? static_cast<std::uint16_t>(p.key) : 0));
    const toolpath::Value& v = p.value;
    w.put(static_cast<std::uint8_t>(static_cast<unsigned>(v.kind) | static_cast<unsigned>(v.flag) << 4));
    w.put(p.line);
    w.put(p.column);
    switch (v.kind) {
      case ValueKind::Integer: w.put(v.integer); break;
      case ValueKind::Numeric: w.put(v.numeric); break;
      case ValueKind::Logical: w.put(static_cast<std::uint8_t>(v.logical)); break;
      case ValueKind::String:
      case ValueKind::Enum: w.text(v.text); break;
    }
    if (!catalogued) w.text(p.name);
  }
  w.put(static_cast<std::uint32_t>(c.trace.size()));
  for (const auto& t : c.trace) {
    w.put(static_cast<std::uint8_t>(t.kind));
    w.text(t.text);
  }
  const std::size_t used = static_cast<std::size_t>(w.at() - out_.get());
  const auto payload = static_cast<std::uint32_t>(used - start - 4);
  std::memcpy(out_.get() + start, &payload, 4);
  used_ = used;
  return at;
}

void CommandSpool::seek(std::int64_t offset) { position_ = offset; }

// From memory when not yet flushed, else from the window, refilled from the file when the record
// is not wholly inside it.
const char* CommandSpool::record_at(std::int64_t offset, std::uint32_t& size) {
  const std::int64_t window = static_cast<std::int64_t>(in_.size());
  if (const std::int64_t at = offset - in_start_; offset < flushed_ && at >= 0 && at + 4 <= window) {
    std::memcpy(&size, in_.data() + at, 4);  // the usual case when replaying: inside the window
    if (at + 4 + static_cast<std::int64_t>(size) <= window) return in_.data() + at + 4;
  }
  if (offset >= flushed_) {
    const auto at = static_cast<std::size_t>(offset - flushed_);
    if (at + 4 > used_) damaged();
    std::memcpy(&size, out_.get() + at, 4);
    if (at + 4 + size > used_) damaged();
    return out_.get() + at + 4;
  }
  auto inside = [&](std::int64_t from, std::int64_t n) {
    return from >= in_start_ && from + n <= in_start_ + static_cast<std::int64_t>(in_.size());
  };
  auto fill = [&](std::int64_t from, std::size_t n) {
    n = std::max(n, kBlock);
    n = static_cast<std::size_t>(std::min<std::int64_t>(static_cast<std::int64_t>(n), flushed_ - from));
    in_.resize(n);
    in_start_ = from;
    if (std::fseek(file_.get(), static_cast<long>(from), SEEK_SET) != 0 ||
        std::fread(in_.data(), 1, n, file_.get()) != n)
      throw std::runtime_error("the temporary file of jobs was cut short");
  };
  if (!inside(offset, 4)) fill(offset, 4);
  if (!inside(offset, 4)) throw std::runtime_error("the temporary file of jobs was cut short");
  std::memcpy(&size, in_.data() + (offset - in_start_), 4);
  if (!inside(offset, 4 + static_cast<std::int64_t>(size))) fill(offset, 4 + std::size_t{size});
  if (!inside(offset, 4 + static_cast<std::int64_t>(size))) throw std::runtime_error("the temporary file of jobs was cut short");
  return in_.data() + (offset - in_start_) + 4;
}

// Gives `parameters` n slots: a spare list of that length when there is one, and the list it had
// becomes a spare of its own length, else (no spare, or no room for another) by resizing it. While
// spares run short, a new list is made: the spares fill up to kSpares per length and stay.
void CommandSpool::shape(std::vector<toolpath::Parameter>& parameters, std::size_t n) {
  const std::size_t had = parameters.size();
  if (had == n) return;
  if (n < spare_.size() && had < spare_.size() && spare_[had].count < kSpares) {
    Spares& to = spare_[had];
    Spares& from = spare_[n];
    to.lists[to.count++].swap(parameters);  // `parameters` is now an empty list
    if (from.count == 0) parameters.resize(n);
    else parameters.swap(from.lists[--from.count]);
    return;
  }
  parameters.resize(n);
}

bool CommandSpool::read(toolpath::Command& out, CommandKind& kind) {
  if (position_ >= end()) return false;
  std::uint32_t payload = 0;
  const char* record = record_at(position_, payload);
  position_ += 4 + static_cast<std::int64_t>(payload);

  Cursor in(record, payload);
  in.need(1);
  const auto kind_code = in.get<std::uint8_t>();
  if (kind_code >= kKinds) damaged();
  kind = static_cast<CommandKind>(kind_code);
  assign(out.name, in.text());
  in.need(8 + 4 + 4 + 4);
  out.index = static_cast<std::size_t>(in.get<std::uint64_t>());
  out.depth = in.get<std::int32_t>();
  out.line = in.get<std::uint32_t>();
  shape(out.parameters, in.get<std::uint32_t>());
  for (auto& p : out.parameters) {
    in.need(kParameterFixed);
    const auto code = in.get<std::uint16_t>();
    const auto kind_and_flag = in.get<std::uint8_t>();
    p.line = in.get<std::uint32_t>();
    p.column = in.get<std::uint32_t>();
    toolpath::Value& v = p.value;
    v.kind = static_cast<ValueKind>(kind_and_flag & 0xf);
    v.flag = static_cast<toolpath::ChangeFlag>(kind_and_flag >> 4);
    v.integer = 0;
    v.numeric = 0.0;
    v.logical = false;
    switch (v.kind) {
      case ValueKind::Integer:
        in.need(8);
        v.integer = in.get<std::int64_t>();
        v.text.clear();
        break;
      case ValueKind::Numeric:
        in.need(8);
        v.numeric = in.get<double>();
        v.text.clear();
        break;
      case ValueKind::Logical:
        in.need(1);
        v.logical = in.get<std::uint8_t>() != 0;
        v.text.clear();
        break;
      case ValueKind::String:
      case ValueKind::Enum: assign(v.text, in.text()); break;
      default: damaged();
    }
    if (code != 0) {
      if (code > toolpath::param_key_count) damaged();
      p.rename(static_cast<ParamKey>(code));  // the catalogue spelling, as written: no hashing
    } else if (const std::string_view name = in.text(); !toolpath::same_short_text(p.name, name)) {
      p.rename(name);  // else the name is already there, and its key with it
    }
  }
  in.need(4);
  out.trace.resize(in.get<std::uint32_t>());
  for (auto& t : out.trace) {
    in.need(1);
    t.kind = static_cast<toolpath::TraceLine::Kind>(in.get<std::uint8_t>());
    t.text.assign(in.text());
  }
  return true;
}

}  // namespace prp
