#include "prp/filters/command_spool.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string_view>

namespace prp {
namespace {

// Record layout: a u32 payload length, then the payload: name, index, depth, line, the parameters
// (name, kind and flag in one byte, then only the field of that kind, then line and column), the
// trace lines. Texts are a u32
// length and the bytes. A parameter name is a u16: its ParamKey when the name is spelled exactly as
// the catalogue spells it (no hashing when it is read back), else 0 and the name as text.
constexpr std::size_t kBlock = std::size_t{1} << 20;

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
  std::size_t n = 4 + 4 + c.name.size() + 8 + 4 + 4 + 4 + 4;
  for (const auto& p : c.parameters) n += 2 + 4 + p.name.size() + 1 + 8 + p.value.text.size() + 4 + 8;
  for (const auto& t : c.trace) n += 1 + 4 + t.text.size();
  return n;
}

// Reads the payload of one record.
class Cursor {
public:
  explicit Cursor(std::string_view bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  void text(std::string& s) { s.assign(text()); }
  std::string_view text() {
    const auto n = get<std::uint32_t>();
    return {take(n), n};
  }

private:
  const char* take(std::size_t n) {
    if (n > bytes_.size()) throw std::runtime_error("the temporary file of jobs is damaged");
    const char* p = bytes_.data();
    bytes_.remove_prefix(n);
    return p;
  }
  std::string_view bytes_;
};

}  // namespace

CommandSpool::CommandSpool() : file_(std::tmpfile()) {
  if (!file_) throw std::runtime_error("cannot create a temporary file to hold jobs being reordered");
  std::setvbuf(file_.get(), nullptr, _IONBF, 0);  // whole blocks only: our own buffers are the cache
  out_.reserve(kBlock);
}

void CommandSpool::flush() {
  if (out_.empty()) return;
  if (std::fseek(file_.get(), static_cast<long>(flushed_), SEEK_SET) != 0 ||
      std::fwrite(out_.data(), 1, out_.size(), file_.get()) != out_.size())
    throw std::runtime_error("cannot write the temporary file of jobs being reordered (disk full?)");
  flushed_ += static_cast<std::int64_t>(out_.size());
  out_.clear();
}

std::int64_t CommandSpool::write(const toolpath::Command& c) {
  const std::size_t most = bound(c);
  if (out_.size() + most > kBlock) flush();
  const std::int64_t at = end();
  const std::size_t start = out_.size();
  out_.resize(start + most);  // within the reserved block unless the command alone is larger
  Writer w(out_.data() + start + 4);
  w.text(c.name);
  w.put(static_cast<std::uint64_t>(c.index));
  w.put(static_cast<std::int32_t>(c.depth));
  w.put(c.line);  // positions travel with the job, for errors found when it is posted
  w.put(static_cast<std::uint32_t>(c.parameters.size()));
  for (const auto& p : c.parameters) {
    if (p.key != toolpath::ParamKey::none && p.name == toolpath::param_name(p.key)) {
      w.put(static_cast<std::uint16_t>(p.key));
    } else {
      w.put(std::uint16_t{0});
      w.text(p.name);
    }
    const toolpath::Value& v = p.value;
    w.put(static_cast<std::uint8_t>(static_cast<unsigned>(v.kind) | static_cast<unsigned>(v.flag) << 4));
    switch (v.kind) {
      case toolpath::ValueKind::Integer: w.put(v.integer); break;
      case toolpath::ValueKind::Numeric: w.put(v.numeric); break;
      case toolpath::ValueKind::Logical: w.put(static_cast<std::uint8_t>(v.logical)); break;
      case toolpath::ValueKind::String:
      case toolpath::ValueKind::Enum: w.text(v.text); break;
    }
    w.put(p.line);
    w.put(p.column);
  }
  w.put(static_cast<std::uint32_t>(c.trace.size()));
  for (const auto& t : c.trace) {
    w.put(static_cast<std::uint8_t>(t.kind));
    w.text(t.text);
  }
  const std::size_t used = static_cast<std::size_t>(w.at() - out_.data());
  const auto payload = static_cast<std::uint32_t>(used - start - 4);
  std::memcpy(out_.data() + start, &payload, 4);
  out_.resize(used);
  return at;
}

void CommandSpool::seek(std::int64_t offset) { position_ = offset; }

// From memory when not yet flushed, else from the window, refilled from the file when the record
// is not wholly inside it.
const char* CommandSpool::record_at(std::int64_t offset, std::uint32_t& size) {
  if (offset >= flushed_) {
    const auto at = static_cast<std::size_t>(offset - flushed_);
    if (at + 4 > out_.size()) throw std::runtime_error("the temporary file of jobs is damaged");
    std::memcpy(&size, out_.data() + at, 4);
    if (at + 4 + size > out_.size()) throw std::runtime_error("the temporary file of jobs is damaged");
    return out_.data() + at + 4;
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

bool CommandSpool::read(toolpath::Command& out) {
  if (position_ >= end()) return false;
  std::uint32_t payload = 0;
  const char* record = record_at(position_, payload);
  position_ += 4 + static_cast<std::int64_t>(payload);

  Cursor in(std::string_view(record, payload));
  in.text(out.name);
  out.index = static_cast<std::size_t>(in.get<std::uint64_t>());
  out.depth = in.get<std::int32_t>();
  out.line = in.get<std::uint32_t>();
  out.parameters.resize(in.get<std::uint32_t>());
  for (auto& p : out.parameters) {
    if (const auto code = in.get<std::uint16_t>(); code != 0) {
      if (code > toolpath::param_key_count) throw std::runtime_error("the temporary file of jobs is damaged");
      const auto key = static_cast<toolpath::ParamKey>(code);
      p.name.assign(toolpath::param_name(key));  // the catalogue spelling, as written
      p.key = key;                                // already known: no rename(), no hashing
    } else {
      p.rename(in.text());
    }
    toolpath::Value& v = p.value;
    const auto kind_and_flag = in.get<std::uint8_t>();
    v.kind = static_cast<toolpath::ValueKind>(kind_and_flag & 0xf);
    v.flag = static_cast<toolpath::ChangeFlag>(kind_and_flag >> 4);
    v.integer = 0;
    v.numeric = 0.0;
    v.logical = false;
    v.text.clear();
    switch (v.kind) {
      case toolpath::ValueKind::Integer: v.integer = in.get<std::int64_t>(); break;
      case toolpath::ValueKind::Numeric: v.numeric = in.get<double>(); break;
      case toolpath::ValueKind::Logical: v.logical = in.get<std::uint8_t>() != 0; break;
      case toolpath::ValueKind::String:
      case toolpath::ValueKind::Enum: in.text(v.text); break;
    }
    p.line = in.get<std::uint32_t>();
    p.column = in.get<std::uint32_t>();
  }
  out.trace.resize(in.get<std::uint32_t>());
  for (auto& t : out.trace) {
    t.kind = static_cast<toolpath::TraceLine::Kind>(in.get<std::uint8_t>());
    in.text(t.text);
  }
  return true;
}

}  // namespace prp
