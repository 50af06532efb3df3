// Interned parameter names. Every parameter name of the command catalogue (param_names.inc) has a
// small number, a ParamKey, so that the stream filters and the engine look parameters up with one
// integer compare instead of a case-insensitive string compare:
//
//   if (const Value* x = command.find(ParamKey::xpos)) ...   // same result as find("xpos")
//
// A Parameter computes its key once, when it is named (its constructor or rename()). Names outside
// the catalogue are allowed everywhere; their key is ParamKey::none and they are compared as text.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string_view>

namespace toolpath {

enum class ParamKey : std::uint16_t {
  none = 0,  // not a catalogue name
#define POSTPROC_PARAM(name) name,
#include "toolpath/param_names.inc"
#undef POSTPROC_PARAM
};

// The number of catalogue names (keys 1 .. param_key_count).
inline constexpr std::size_t param_key_count = static_cast<std::size_t>([] {
  std::uint16_t n = 0;
#define POSTPROC_PARAM(name) ++n;
#include "toolpath/param_names.inc"
#undef POSTPROC_PARAM
  return n;
}());

// The key of a name, ignoring ASCII case ("XPOS" is ParamKey::xpos); ParamKey::none when the
// name is not in the catalogue. A hash lookup: a few dozen instructions, no allocation.
ParamKey param_key(std::string_view name);

namespace detail {
inline constexpr std::string_view param_names[] = {
    "",
#define POSTPROC_PARAM(name) #name,
#include "toolpath/param_names.inc"
#undef POSTPROC_PARAM
};
static_assert(std::size(param_names) == param_key_count + 1);
}  // namespace detail

// The catalogue spelling of a key ("xpos"); empty for ParamKey::none. A table read, inline: the
// readers name recycled parameters by key, command after command.
constexpr std::string_view param_name(ParamKey key) {
  const auto k = static_cast<std::size_t>(key);
  return k < std::size(detail::param_names) ? detail::param_names[k] : std::string_view{};
}

}  // namespace toolpath
