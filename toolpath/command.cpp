#include "toolpath/command.hpp"

namespace toolpath {

// Plain text comparison, so that it finds any name without hashing it first: callers that look up
// on every command use find(ParamKey) instead.
const Value* Command::find(std::string_view parameter) const {
  for (const auto& p : parameters)
    if (iequals(p.name, parameter)) return &p.value;
  return nullptr;
}

std::optional<double> Command::number(std::string_view parameter) const {
  const Value* v = find(parameter);
  if (!v || (v->kind != ValueKind::Integer && v->kind != ValueKind::Numeric)) return std::nullopt;
  return v->as_number();
}

void Command::set(std::string_view parameter, Value value) {
  const ParamKey key = param_key(parameter);
  for (auto& p : parameters) {
    if (key != ParamKey::none ? p.key == key : p.key == ParamKey::none && iequals(p.name, parameter)) {
      p.value = std::move(value);
      p.line = p.column = 0;  // no longer the value that was read there
      return;
    }
  }
  parameters.emplace_back(std::string(parameter), std::move(value));  // spelled as given
}

void Command::set(ParamKey key, Value value) {
  if (key == ParamKey::none) return;
  for (auto& p : parameters) {
    if (p.key == key) {
      p.value = std::move(value);
      p.line = p.column = 0;  // no longer the value that was read there
      return;
    }
  }
  parameters.emplace_back(key, std::move(value));
}

void Command::clear() {
  name.clear();
  index = 0;
  depth = 1;
  line = 0;
  parameters.clear();
  trace.clear();
}

}  // namespace toolpath
