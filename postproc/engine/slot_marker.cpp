#include "postproc/engine/slot_marker.hpp"

namespace postproc::slot {
namespace {

constexpr std::size_t kDigits = 10;

bool is_marker_at(std::string_view text, std::size_t at) {
  if (text.size() - at < kWidth || text[at] != kStart || text[at + 1] != kOpen) return false;
  for (std::size_t i = 2; i < 2 + kDigits; ++i)
    if (text[at + i] < '0' || text[at + i] > '9') return false;
  for (std::size_t i = 2 + kDigits; i < kWidth; ++i)
    if (text[at + i] != kPad) return false;
  return true;
}

}  // namespace

std::string marker(std::uint32_t id) {
  std::string m(kWidth, kPad);
  m[0] = kStart;
  m[1] = kOpen;
  for (std::size_t i = 0; i < kDigits; ++i, id /= 10) m[1 + kDigits - i] = char('0' + id % 10);
  return m;
}

std::optional<Found> find_marker(std::string_view text, std::size_t from) {
  for (std::size_t at = text.find(kStart, from); at != std::string_view::npos; at = text.find(kStart, at + 1)) {
    if (!is_marker_at(text, at)) continue;
    std::uint64_t id = 0;
    for (std::size_t i = 2; i < 2 + kDigits; ++i) id = id * 10 + std::uint64_t(text[at + i] - '0');
    if (id <= UINT32_MAX) return Found{at, std::uint32_t(id)};
  }
  return std::nullopt;
}

bool fits(std::string_view text) {
  return text.size() <= kWidth - 2 && text.find(kStart) == std::string_view::npos &&
         text.find(kPad) == std::string_view::npos;
}

std::string filled(std::string_view text) {
  std::string bytes(kWidth, kPad);
  bytes[0] = kStart;
  bytes.replace(1, text.size(), text);
  return bytes;
}

std::optional<std::string_view> filled_text(std::string_view line, std::size_t at) {
  if (line.size() - at < kWidth || line[at] != kStart || line[at + kWidth - 1] != kPad || is_marker_at(line, at))
    return std::nullopt;
  std::string_view slot = line.substr(at + 1, kWidth - 1);
  std::string_view text = slot.substr(0, slot.find(kPad));
  for (char c : slot.substr(text.size()))
    if (c != kPad) return std::nullopt;
  return text;
}

std::string readable(std::string_view line) {
  std::string out;
  std::size_t from = 0;
  while (auto m = find_marker(line, from)) {
    out.append(line.substr(from, m->position - from));
    out += "{?" + std::to_string(m->id) + "}";
    from = m->position + kWidth;
  }
  out.append(line.substr(from));
  return out;
}

}  // namespace postproc::slot
