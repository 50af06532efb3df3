// Placeholders in the output for text known only later (start_line/end_line, docs/engine.md).
//
// A slot is kWidth bytes in the output file. Until its text is known it holds a marker,
// STX SOH <10-digit id> ETX...; once known, the text is written over it in place, STX <text>
// ETX... (padded with ETX to the same width), and the final pass over the file drops the framing.
// Control characters never occur in NC text, so a marker cannot be confused with what a post writes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace postproc::slot {

constexpr std::size_t kWidth = 24;
constexpr char kStart = '\x02', kOpen = '\x01', kPad = '\x03';

// The marker of slot `id`, as written into a line.
std::string marker(std::uint32_t id);

struct Found {
  std::size_t position = 0;
  std::uint32_t id = 0;
};
// The first marker (unresolved slot) at or after `from`.
std::optional<Found> find_marker(std::string_view text, std::size_t from = 0);

// True when `text` can be written in place of a marker (short enough, no framing characters).
bool fits(std::string_view text);
// The bytes written over a marker: kStart, the text, kPad up to kWidth. Requires fits(text).
std::string filled(std::string_view text);

// The text of the slot that starts at `at` (kStart) when it is a filled slot; nullopt when it is
// an unresolved marker or not a slot at all.
std::optional<std::string_view> filled_text(std::string_view line, std::size_t at);

// For people reading unresolved lines (`postproc explain`): every marker becomes `{?N}`.
std::string readable(std::string_view line);

}  // namespace postproc::slot
