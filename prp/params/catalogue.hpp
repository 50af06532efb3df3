// Every PRP key the spec documents, with the kind of value it takes and the engine's default when
// the file does not set it (spec sections 2 and 3.0).
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "prp/prp.hpp"

namespace prp {

struct KeyInfo {
  std::string_view name;           // spelled as the spec spells it
  ValueKind kind;
  std::span<const std::string_view> choices;  // Enumeration only
  bool unknown_choice_is_warning = false;     // default_lang, machine_type (spec 1.7)
  std::string_view default_text;              // parsed like a file value; empty: no default
};

// Every documented key, in the order of the spec.
std::span<const KeyInfo> all_keys();

// The documented key (case-insensitive), or nullptr.
const KeyInfo* find_key(std::string_view key);

// Repeatable record keys, with an optional language suffix (`drill_type_ger`). Returns the base
// key (`drill_type`) and writes the suffix (`ger`) to `lang`; nullopt when `key` is no record key.
std::optional<std::string_view> record_base(std::string_view key, std::string_view& lang);

// Drill base types (spec 1.5.2), in their canonical spelling; nullopt when `word` is none of them.
std::optional<std::string_view> drill_base(std::string_view word);

}  // namespace prp
