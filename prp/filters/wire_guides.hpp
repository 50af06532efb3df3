// Wire EDM (machine_type = WIRE_CUT, spec 3.6 and 3.16): the machine's guides. @wc_abs_rel gets the
// PRP's xy_abs and uv_abs when the stream leaves them out, and every move of the upper guide
// (upos, vpos of @wc_move, @wc_line, @wc_arc, @wc_pos_pnt) must stay within u_max and v_max of the
// lower guide: a taper the machine cannot tilt to is an error at its command, never a silent cut.
#pragma once

#include <optional>

#include "prp/prp.hpp"

namespace prp {

class WireGuides final : public toolpath::CommandSource {
public:
  WireGuides(toolpath::CommandSource& input, const MachineParameters& params);
  // Only a wire machine, or a PRP that limits the guides, needs it.
  static bool needed(const MachineParameters& params);
  bool next(toolpath::Command& out) override;

private:
  void check_guides(const toolpath::Command& c) const;

  toolpath::CommandSource& input_;
  bool xy_abs_, uv_abs_;
  std::optional<double> u_max_, v_max_;
};

}  // namespace prp
