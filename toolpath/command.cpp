#include "toolpath/command.hpp"

namespace toolpath {

const Value* Command::find(std::string_view parameter) const {
  for (const auto& p : parameters)
    if (iequals(p.name, parameter)) return &p.value;
  return nullptr;
}

void Command::set(std::string_view parameter, Value value) {
  for (auto& p : parameters) {
    if (iequals(p.name, parameter)) {
      p.value = std::move(value);
      return;
    }
  }
  parameters.push_back(Parameter{std::string(parameter), std::move(value)});
}

void Command::clear() {
  name.clear();
  index = 0;
  depth = 1;
  parameters.clear();
  trace.clear();
}

}  // namespace toolpath
