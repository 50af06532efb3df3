#include "postproc/engine/line_numbers.hpp"

#include <fmt/format.h>

#include <cmath>

namespace postproc {

LineNumbers::LineNumbers(gppl::Interpreter& interpreter, OutputFiles& files, LineObserver* observer,
                         std::function<std::string()> command)
    : interpreter_(interpreter),
      command_(std::move(command)),
      label_(interpreter.find_variable("label")),
      ranges_([&files](std::string& marker) { return files.new_slot(marker); },
              [&files, observer](std::uint32_t id, std::string_view text) {
                files.fill_slot(id, text);
                if (observer) observer->on_slot_filled(id, text);
              }) {
  for (std::string_view name : {"@proc", "@turn_proc", "@end_proc", "@turn_endproc", "@loop", "@end_loop", "@call_proc",
                                "@call_prms", "@start_of_job", "@turning", "@thread"})
    if (auto id = interpreter.find_procedure(name)) roles_[*id] = BlockRanges::role_of(name);
}

std::int64_t LineNumbers::label() const {
  if (!label_) return 0;
  const gppl::Value& v = interpreter_.value(*label_);
  switch (v.type) {
    case gppl::Type::Integer: return v.integer;
    case gppl::Type::Numeric: return std::llround(v.numeric);
    case gppl::Type::Logical: return v.logical ? 1 : 0;
    case gppl::Type::String: break;
  }
  return 0;
}

void LineNumbers::procedure_boundary(gppl::ProcedureId id, bool entering) {
  auto it = roles_.find(id);
  if (it == roles_.end()) return;
  if (entering) ranges_.enter(it->second, label());
  else ranges_.leave(it->second);
}

void LineNumbers::command_without_procedure(std::string_view name) {
  const BlockRanges::Role role = BlockRanges::role_of(name);
  if (role == BlockRanges::Role::None) return;
  ranges_.enter(role, label());
  ranges_.leave(role);
}

void LineNumbers::line_function(gppl::LineFunction which, std::string_view format, const gppl::Position& item,
                                std::string& out) {
  std::string where = fmt::format("{}:{}:{}", item.file, item.line, item.column);
  if (std::string c = command_(); !c.empty()) where += " (" + c + ")";
  ranges_.line_function(which, format, label(), std::move(where), out);
}

}  // namespace postproc
