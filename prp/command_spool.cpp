#include "prp/command_spool.hpp"

#include <cstring>
#include <stdexcept>
#include <string_view>

namespace prp {
namespace {

// Record layout: a u32 payload length, then the payload: name, index, depth, the parameters (name,
// kind and flag in one byte, then only the field of that kind), the trace lines. Every command of a
// job goes through the spool, so a record is small and is read back with two fread calls.
template <class T>
void put(std::string& b, T v) {
  char bytes[sizeof v];
  std::memcpy(bytes, &v, sizeof v);
  b.append(bytes, sizeof v);
}
void put_text(std::string& b, std::string_view s) {
  put(b, static_cast<std::uint32_t>(s.size()));
  b.append(s);
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
  void text(std::string& s) {
    const auto n = get<std::uint32_t>();
    s.assign(take(n), n);
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
  std::setvbuf(file_.get(), nullptr, _IOFBF, 1 << 18);
}

std::int64_t CommandSpool::write(const toolpath::Command& c) {
  buffer_.assign(4, '\0');  // the payload length, filled in below
  put_text(buffer_, c.name);
  put(buffer_, static_cast<std::uint64_t>(c.index));
  put(buffer_, static_cast<std::int32_t>(c.depth));
  put(buffer_, static_cast<std::uint32_t>(c.parameters.size()));
  for (const auto& p : c.parameters) {
    put_text(buffer_, p.name);
    const toolpath::Value& v = p.value;
    buffer_ += static_cast<char>(static_cast<unsigned>(v.kind) | static_cast<unsigned>(v.flag) << 4);
    switch (v.kind) {
      case toolpath::ValueKind::Integer: put(buffer_, v.integer); break;
      case toolpath::ValueKind::Numeric: put(buffer_, v.numeric); break;
      case toolpath::ValueKind::Logical: buffer_ += static_cast<char>(v.logical); break;
      case toolpath::ValueKind::String:
      case toolpath::ValueKind::Enum: put_text(buffer_, v.text); break;
    }
  }
  put(buffer_, static_cast<std::uint32_t>(c.trace.size()));
  for (const auto& t : c.trace) {
    buffer_ += static_cast<char>(t.kind);
    put_text(buffer_, t.text);
  }
  const auto payload = static_cast<std::uint32_t>(buffer_.size() - 4);
  std::memcpy(buffer_.data(), &payload, 4);
  if (!writing_ || end_ == 0) std::fseek(file_.get(), static_cast<long>(end_), SEEK_SET);
  writing_ = true;
  if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_.get()) != buffer_.size())
    throw std::runtime_error("cannot write the temporary file of jobs being reordered (disk full?)");
  const std::int64_t at = end_;
  end_ += static_cast<std::int64_t>(buffer_.size());
  return at;
}

void CommandSpool::seek(std::int64_t offset) {
  position_ = offset;
  std::fflush(file_.get());
  std::fseek(file_.get(), static_cast<long>(offset), SEEK_SET);
  writing_ = false;
}

bool CommandSpool::read(toolpath::Command& out) {
  if (writing_) seek(position_);
  if (position_ >= end_) return false;
  std::uint32_t payload = 0;
  if (std::fread(&payload, 1, 4, file_.get()) != 4) throw std::runtime_error("the temporary file of jobs was cut short");
  buffer_.resize(payload);
  if (std::fread(buffer_.data(), 1, payload, file_.get()) != payload)
    throw std::runtime_error("the temporary file of jobs was cut short");
  position_ += 4 + static_cast<std::int64_t>(payload);

  Cursor in(buffer_);
  in.text(out.name);
  out.index = static_cast<std::size_t>(in.get<std::uint64_t>());
  out.depth = in.get<std::int32_t>();
  out.parameters.resize(in.get<std::uint32_t>());
  for (auto& p : out.parameters) {
    in.text(p.name);
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
  }
  out.trace.resize(in.get<std::uint32_t>());
  for (auto& t : out.trace) {
    t.kind = static_cast<toolpath::TraceLine::Kind>(in.get<std::uint8_t>());
    in.text(t.text);
  }
  return true;
}

}  // namespace prp
