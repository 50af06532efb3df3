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

void ParameterBinding::assign_each(const toolpath::Command& command, Positions& positions) {
  const std::size_t count = command.parameters.size();
  std::size_t i = 0;
  try {
    for (; i < count; ++i) {
      const toolpath::Parameter& p = command.parameters[i];
      assign_bound(p.key != toolpath::ParamKey::none ? keyed(p) : at_position(positions, i, p.name), p.value);
    }
  } catch (const gppl::Error& e) {
    fail(command, command.parameters[i], e);
  }
}

void ParameterBinding::assign(Bound& b, const toolpath::Value& v) {
  if (static_cast<std::uint8_t>(v.kind) == b.slot.skipped_kind) return;
  const gppl::VariableId id = *b.slot.id;
  const gppl::ChangeOverride change = change_override(v.flag);
  switch (v.kind) {
    case toolpath::ValueKind::Integer: return interpreter_.assign_integer(id, v.integer, change);
    case toolpath::ValueKind::Numeric: return interpreter_.assign_numeric(id, v.numeric, change);
    case toolpath::ValueKind::Logical: return interpreter_.assign_logical(id, v.logical, change);
    case toolpath::ValueKind::String: return interpreter_.assign_string(id, v.text, change);
    case toolpath::ValueKind::Enum:
      if (b.slot.is_string) return interpreter_.assign_string(id, v.text, change);
      return interpreter_.assign_integer(id, enum_code(b, v.text), change);
  }
}

// What assign_bound() does with each kind of value under p's name, once for the steps that follow.
ParameterBinding::Step ParameterBinding::step_for(const toolpath::Parameter& p) {
  Step s;
  if (p.key == toolpath::ParamKey::none) return s;
  s.key = p.key;
  s.bound = &keyed(p);
  if (s.bound->slot.id) s.variable = interpreter_.host_slot(*s.bound->slot.id);
  for (std::size_t k = 0; k < kKinds; ++k) s.actions[k] = action_for(*s.bound, static_cast<toolpath::ValueKind>(k));
  return s;
}

ParameterBinding::Action ParameterBinding::action_for(const Bound& b, toolpath::ValueKind kind) const {
  if (!b.slot.id) return b.array ? Action::Element : Action::Skip;
  if (static_cast<std::uint8_t>(kind) == b.slot.skipped_kind) return Action::Skip;
  switch (kind) {
    case toolpath::ValueKind::Integer: return Action::Integer;
    case toolpath::ValueKind::Numeric: return Action::Numeric;
    case toolpath::ValueKind::Logical: return Action::Logical;
    case toolpath::ValueKind::String: return Action::String;
    case toolpath::ValueKind::Enum: return b.slot.is_string ? Action::String : Action::Enum;
  }
  return Action::Skip;
}

std::int64_t ParameterBinding::other_word(Bound& b, std::string_view word) {
  if (b.enum_word.empty() || !toolpath::iequals(b.enum_word, word)) b.enum_code = enums_.code(word);
  b.enum_word = word;
  return b.enum_code;
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
