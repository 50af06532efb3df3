#include "prp/filters/init_cpos.hpp"

#include <cmath>

#include "prp/filters/motion.hpp"

namespace prp {
namespace {

bool is_4x_move(const toolpath::Command& c) {
  for (std::string_view n : {"@move_4x", "@line_4x", "@move4x_cartesian", "@move4x_polar", "@move4x_dir",
                             "@line4x_cartesian", "@line4x_polar", "@line4x_dir", "@arc4x_cartesian", "@arc4x_polar"})
    if (is(c, n)) return true;
  return false;
}

}  // namespace

double best_cpos(double prev_cpos, double first) {
  return prev_cpos + 360.0 * std::round((first - prev_cpos) / 360.0 - 1e-12);
}

bool InitCpos::next(toolpath::Command& out) {
  if (has_held_) {
    has_held_ = false;
    swap(out, held_);
  } else if (!input_.next(out)) {
    return false;
  } else if (out.is_stream_command()) {
    if (is(out, "@start_of_job") || is(out, "@rotary_info") || (is(out, "@proc"))) new_job_ = true;
    if (is(out, "@init_cpos")) new_job_ = false;  // the toolpath sends its own
    auto c = number(out, "cpos");
    if (new_job_ && is_4x_move(out) && c) {
      new_job_ = false;
      if (cpos_) {
        swap(held_, out);
        has_held_ = true;
        out.clear();
        out.name = "@init_cpos";
        out.index = held_.index;
        out.line = held_.line;
        out.set("prev_cpos", toolpath::Value::make_numeric(*cpos_));
        out.set("best_cpos", toolpath::Value::make_numeric(best_cpos(*cpos_, *c)));
        cpos_ = best_cpos(*cpos_, *c);  // the machine's C now reads best_cpos
        return true;
      }
    }
  }
  if (out.is_stream_command())
    if (auto c = number(out, "cpos")) cpos_ = *c;
  return true;
}

}  // namespace prp
