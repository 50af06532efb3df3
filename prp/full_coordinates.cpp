#include "prp/full_coordinates.hpp"

namespace prp {

bool FullCoordinates::next(toolpath::Command& out) {
  if (!input_.next(out)) return false;
  if (out.is_stream_command() && is_motion_block(out) && !is(out, "@drill")) {
    const bool cartesian = is(out, "@rapid_move") || is(out, "@line") || is(out, "@arc") || is(out, "@line_on");
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
  position_.update(out);
  return true;
}

}  // namespace prp
