#include "prp/filters/wire_guides.hpp"

#include <cmath>

#include <fmt/format.h>

#include "prp/filters/motion.hpp"

namespace prp {

using toolpath::iequals;

namespace {

std::optional<double> limit(const MachineParameters& p, std::string_view key) {
  if (!p.has(key)) return std::nullopt;
  const double v = p.numeric(key);
  return v > 0 ? std::optional<double>(v) : std::nullopt;  // 0: no limit given
}

bool moves_guides(const toolpath::Command& c) {
  return iequals(c.name, "@wc_move") || iequals(c.name, "@wc_line") || iequals(c.name, "@wc_arc") ||
         iequals(c.name, "@wc_pos_pnt");
}

}  // namespace

WireGuides::WireGuides(toolpath::CommandSource& input, const MachineParameters& params)
    : input_(input),
      xy_abs_(params.logical("xy_abs")),
      uv_abs_(params.logical("uv_abs")),
      u_max_(limit(params, "u_max")),
      v_max_(limit(params, "v_max")) {}

bool WireGuides::needed(const MachineParameters& params) {
  return (params.has("machine_type") && iequals(params.text("machine_type"), "WIRE_CUT")) || limit(params, "u_max") ||
         limit(params, "v_max");
}

bool WireGuides::next(toolpath::Command& out) {
  if (!input_.next(out)) return false;
  if (!out.is_stream_command()) return true;
  if (iequals(out.name, "@wc_abs_rel")) {
    if (!out.find("xy_abs")) out.set("xy_abs", toolpath::Value::make_logical(xy_abs_));
    if (const toolpath::Value* uv = out.find("uv_abs")) {
      uv_abs_ = uv->kind == toolpath::ValueKind::Logical ? uv->logical : uv->as_number() != 0;
    } else {
      out.set("uv_abs", toolpath::Value::make_logical(uv_abs_));
    }
  } else if (moves_guides(out)) {
    check_guides(out);
  }
  return true;
}

void WireGuides::check_guides(const toolpath::Command& c) const {
  // The upper guide's distance from the lower one: upos itself when U/V are relative (uv_abs = N),
  // upos - xpos when they are absolute.
  auto check = [&](std::string_view upper, std::string_view lower, const std::optional<double>& max,
                   std::string_view key) {
    if (!max) return;
    const std::optional<double> u = number(c, upper);
    if (!u) return;
    double offset = *u;
    if (uv_abs_) {
      const std::optional<double> x = number(c, lower);
      if (!x) return;
      offset -= *x;
    }
    if (std::abs(offset) > *max + 1e-9)
      throw StreamError(c, fmt::format("the upper guide is {:g} from the lower one in {}, beyond {} = {:g}: the "
                                       "machine cannot tilt the wire that far",
                                       std::abs(offset), upper == "upos" ? "U" : "V", key, *max));
  };
  check("upos", "xpos", u_max_, "u_max");
  check("vpos", "ypos", v_max_, "v_max");
}

}  // namespace prp
