// Test helpers: a command source over a list, draining a filter, and building commands.
#pragma once

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "prp/filters/arc_filter.hpp"
#include "toolpath/command.hpp"
#include "toolpath/source.hpp"

namespace prp_test {

class ListSource final : public toolpath::CommandSource {
public:
  explicit ListSource(std::vector<toolpath::Command> commands) : commands_(std::move(commands)) {}
  bool next(toolpath::Command& out) override {
    if (at_ >= commands_.size()) return false;
    out = commands_[at_++];
    return true;
  }

private:
  std::vector<toolpath::Command> commands_;
  std::size_t at_ = 0;
};

inline std::vector<toolpath::Command> drain(toolpath::CommandSource& source) {
  std::vector<toolpath::Command> out;
  toolpath::Command c;
  while (source.next(c)) out.push_back(c);
  return out;
}

using Pair = std::pair<const char*, toolpath::Value>;

inline toolpath::Command command(std::string name, std::initializer_list<Pair> parameters, std::size_t index = 0) {
  toolpath::Command c;
  c.name = std::move(name);
  c.index = index;
  for (const auto& [n, v] : parameters) c.parameters.push_back({n, v});
  return c;
}

inline toolpath::Value num(double v) { return toolpath::Value::make_numeric(v); }
inline toolpath::Value word(const char* w) { return toolpath::Value::make_enum(w); }
inline toolpath::Value logical(bool b) { return toolpath::Value::make_logical(b); }

inline double get(const toolpath::Command& c, const char* name) {
  const toolpath::Value* v = c.find(name);
  return v ? v->as_number() : -999999.0;
}

// Runs `in` through one ArcFilter with settings `s` and returns everything it produced.
inline std::vector<toolpath::Command> run_arc_filter(std::vector<toolpath::Command> in, const prp::ArcSettings& s) {
  ListSource source(std::move(in));
  prp::ArcFilter filter(source, s);
  return drain(filter);
}

}  // namespace prp_test
