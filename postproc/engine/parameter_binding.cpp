#include "postproc/engine/parameter_binding.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <span>
#include <stdexcept>

#include "postproc/engine/parameter_table.hpp"
#include "toolpath/error.hpp"
#include "toolpath/short_text.hpp"

namespace postproc {

ParameterBinding::ParameterBinding(gppl::Interpreter& interpreter, Enumerations& enums, std::vector<std::string> host_reads)
    : interpreter_(interpreter), enums_(enums), host_reads_(std::move(host_reads)), by_key_(toolpath::param_key_count + 1) {}

namespace {

// The value kind that goes into a variable of type `t` as it is (no conversion); kNoSkip for none.
std::uint8_t same_kind(gppl::Type t) {
  switch (t) {
    case gppl::Type::Integer: return static_cast<std::uint8_t>(toolpath::ValueKind::Integer);
    case gppl::Type::Numeric: return static_cast<std::uint8_t>(toolpath::ValueKind::Numeric);
    case gppl::Type::Logical: return static_cast<std::uint8_t>(toolpath::ValueKind::Logical);
    case gppl::Type::String: return static_cast<std::uint8_t>(toolpath::ValueKind::String);
  }
  return ParameterBinding::kNoSkip;
}

}  // namespace

const ParameterBinding::Slot& ParameterBinding::slot(std::string_view name) {
  auto it = slots_.find(name);
  if (it != slots_.end()) return it->second;
  Slot s;
  s.id = interpreter_.find_variable(name);
  if (const ParameterSpec* p = find_parameter(name))
    s.is_string = p->kind == ParameterKind::String;
  else if (s.id)
    s.is_string = interpreter_.value(*s.id).type == gppl::Type::String;
  if (s.id && std::none_of(host_reads_.begin(), host_reads_.end(), [&](const std::string& r) { return toolpath::iequals(r, name); }))
    if (const std::optional<gppl::Type> t = interpreter_.unread_type(*s.id)) s.skipped_kind = same_kind(*t);
  return slots_.emplace(std::string(name), s).first->second;
}

// Every spelling of a catalogue name has its key, and names the same variable (names are looked up
// without case): the first spelling seen binds the key.
void ParameterBinding::resolve(Bound& b, std::string_view name) {
  b.resolved = true;
  b.array.reset();
  const std::size_t open = name.find("<<");
  if (open == std::string_view::npos) {
    b.slot = slot(name);
    return;
  }
  // `name<<i>>` / `name<<i,j>>` (the reader checked the syntax): an element of a host array.
  b.slot = {};
  b.array = interpreter_.find_variable(name.substr(0, open));
  b.index_count = 0;
  for (std::size_t i = open + 2; i < name.size() && b.index_count < 2; ++i) {
    int v = 0;
    while (i < name.size() && name[i] >= '0' && name[i] <= '9') v = v * 10 + (name[i++] - '0');
    b.index[b.index_count++] = v;
    if (i >= name.size() || name[i] != ',') break;
  }
}

void ParameterBinding::assign_element(const Bound& b, const toolpath::Value& v) {
  const bool text = interpreter_.value(*b.array).type == gppl::Type::String;
  try {
    interpreter_.assign_element(*b.array, std::span<const int>(b.index.data(), b.index_count), convert(v, text),
                                change_override(v.flag));
  } catch (const std::out_of_range& e) {
    throw std::runtime_error(e.what());  // an index outside the array: an error of the job
  }
}

ParameterBinding::Bound& ParameterBinding::at_position(Positions& positions, std::size_t position,
                                                       std::string_view name) {
  if (position < positions.size() && positions[position].resolved &&
      toolpath::same_short_text(positions[position].name, name))
    return positions[position];
  if (position >= positions.size()) positions.resize(position + 1);
  Bound& b = positions[position];
  b = Bound{};
  b.name = std::string(name);
  resolve(b, name);
  return b;
}

void ParameterBinding::assign_enum(Bound& b, const toolpath::Value& v, gppl::ChangeOverride change) {
  const gppl::VariableId id = *b.slot.id;
  if (b.slot.is_string) return interpreter_.assign_string(id, v.text, change);
  if (b.enum_word.empty() || !toolpath::iequals(b.enum_word, v.text)) {  // words are looked up without case
    b.enum_code = enums_.code(v.text);
    b.enum_word = v.text;
  }
  interpreter_.assign_integer(id, b.enum_code, change);
}

void ParameterBinding::fail(const toolpath::Command& command, const toolpath::Parameter& p, const gppl::Error& e) const {
  const std::string what = fmt::format("parameter `{}` of {}: error {}: {}", p.name, command.name, e.number(), e.text());
  if (p.line != 0) throw toolpath::InputError({input_name_, p.line, p.column}, what);
  throw gppl::Error(e.number(), gppl::Position{}, fmt::format("parameter `{}`: {}", p.name, e.text()));
}

gppl::Value ParameterBinding::convert(const toolpath::Value& v, bool to_string) {
  switch (v.kind) {
    case toolpath::ValueKind::Integer: return gppl::Value::of_integer(v.integer);
    case toolpath::ValueKind::Numeric: return gppl::Value::of_numeric(v.numeric);
    case toolpath::ValueKind::Logical: return gppl::Value::of_logical(v.logical);
    case toolpath::ValueKind::String: break;
    case toolpath::ValueKind::Enum:
      if (!to_string) return gppl::Value::of_integer(enums_.code(v.text));
      break;
  }
  return gppl::Value::of_string(v.text);
}

}  // namespace postproc
