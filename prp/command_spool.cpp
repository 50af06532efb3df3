#include "prp/command_spool.hpp"

#include <cstring>
#include <stdexcept>

namespace prp {
namespace {

void put_u64(std::string& b, std::uint64_t v) {
  char bytes[8];
  std::memcpy(bytes, &v, 8);
  b.append(bytes, 8);
}
void put_text(std::string& b, const std::string& s) {
  put_u64(b, s.size());
  b += s;
}

}  // namespace

CommandSpool::CommandSpool() : file_(std::tmpfile()) {
  if (!file_) throw std::runtime_error("cannot create a temporary file to hold jobs being reordered");
}

std::int64_t CommandSpool::write(const toolpath::Command& c) {
  buffer_.clear();
  put_text(buffer_, c.name);
  put_u64(buffer_, c.index);
  put_u64(buffer_, static_cast<std::uint64_t>(static_cast<std::int64_t>(c.depth)));
  put_u64(buffer_, c.parameters.size());
  for (const auto& p : c.parameters) {
    put_text(buffer_, p.name);
    buffer_ += static_cast<char>(p.value.kind);
    buffer_ += static_cast<char>(p.value.flag);
    put_u64(buffer_, static_cast<std::uint64_t>(p.value.integer));
    std::uint64_t bits;
    std::memcpy(&bits, &p.value.numeric, 8);
    put_u64(buffer_, bits);
    buffer_ += static_cast<char>(p.value.logical);
    put_text(buffer_, p.value.text);
  }
  put_u64(buffer_, c.trace.size());
  for (const auto& t : c.trace) {
    buffer_ += static_cast<char>(t.kind);
    put_text(buffer_, t.text);
  }
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
  auto bytes = [&](void* to, std::size_t n) {
    if (std::fread(to, 1, n, file_.get()) != n) throw std::runtime_error("the temporary file of jobs was cut short");
    position_ += static_cast<std::int64_t>(n);
  };
  auto u64 = [&] {
    std::uint64_t v;
    bytes(&v, 8);
    return v;
  };
  auto text = [&](std::string& s) {
    s.resize(u64());
    if (!s.empty()) bytes(s.data(), s.size());
  };
  auto byte = [&] {
    unsigned char c;
    bytes(&c, 1);
    return c;
  };
  text(out.name);
  out.index = u64();
  out.depth = static_cast<int>(static_cast<std::int64_t>(u64()));
  out.parameters.resize(u64());
  for (auto& p : out.parameters) {
    text(p.name);
    p.value.kind = static_cast<toolpath::ValueKind>(byte());
    p.value.flag = static_cast<toolpath::ChangeFlag>(byte());
    p.value.integer = static_cast<std::int64_t>(u64());
    const std::uint64_t bits = u64();
    std::memcpy(&p.value.numeric, &bits, 8);
    p.value.logical = byte() != 0;
    text(p.value.text);
  }
  out.trace.resize(u64());
  for (auto& t : out.trace) {
    t.kind = static_cast<toolpath::TraceLine::Kind>(byte());
    text(t.text);
  }
  return true;
}

}  // namespace prp
