#include "prp/filters/full_coordinates.hpp"

namespace prp {

bool FullCoordinates::next_with_kind(toolpath::Command& out, CommandKind& kind) {
  using K = CommandKind;
  if (!input_.next(out, kind)) return false;
  if (out.is_stream_command() && has(kMotionBlock, kind) && kind != K::drill) {
    const bool cartesian = kind == K::rapid_move || kind == K::line || kind == K::arc || kind == K::line_on;
    static constexpr std::string_view names[] = {"xpos", "ypos", "zpos"};
    for (int i = 0; i < 3; ++i) {
      if (const toolpath::Value* v = out.find(names[i])) {
        toolpath::Value changed = *v;
        changed.flag = toolpath::ChangeFlag::Changed;
        out.set(names[i], std::move(changed));
      } else if (auto here = position_.axis(i); cartesian && here) {
        out.set(names[i], toolpath::Value::make_numeric(*here, toolpath::ChangeFlag::Changed));
      }
    }
  }
  position_.update(out, kind);
  return true;
}

}  // namespace prp
