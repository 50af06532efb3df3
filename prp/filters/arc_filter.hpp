// Arc admission, linearisation and splitting (spec 3.2-3.4): each @arc the machine cannot take is
// replaced by chords or by smaller arcs, every piece with all its arc values recomputed.
#pragma once

#include <optional>
#include <vector>

#include "prp/filters/command_fields.hpp"
#include "prp/filters/kind_source.hpp"
#include "prp/filters/kinematic_sets.hpp"
#include "prp/filters/motion.hpp"
#include "prp/prp.hpp"
#include "toolpath/geometry.hpp"

namespace prp {

struct ArcSettings {
  bool arc_exist = true;      // N: every arc becomes chords
  bool arc_3d = true;         // N: helical arcs become chords
  bool quadrants = false;     // Y: cut at every multiple of 90 degrees
  bool gt_180 = true;         // N: arcs over 180 degrees are halved
  bool zx_yz = true;          // N: arcs outside the machine plane become chords
  bool arc_5x = true;         // N: @arc_5x (an arc while the rotary axes turn) becomes @line_5x chords
  bool main_planes = false;   // arc_in_main_planes = Y set in the PRP (or pos_to_coord = Y): an arc
                              // whose machine plane (arc_plane_m) is none of XY, YZ, ZX becomes chords
  toolpath::geometry::Plane machine_plane = toolpath::geometry::Plane::XY;
  std::optional<double> max_radius;  // larger arcs become chords
  double max_angle = 10.0;    // chord limits when linearising
  double max_chord = 30.0;
  double max_deviation = 0.0;  // arc_max_deviation (ours): the chords stay this close to the arc; 0: unused
  double min_length = 0.0;    // shorter arcs (or pieces) become one line
  double eps_angle = 0.0;     // smaller sweeps become one line
  double zero_value = 0.0;    // a rise below this is not helical
  bool limits_defaulted = false;  // neither arc_max_angle nor arc_max_chord is in the PRP
  bool work_out_every_arc = false;  // tests: no arc_surely_passes() shortcut, and the circle check with
                                    // hypot only (same results, slower)
  // How far apart the start's and the end's distances from the centre (and the stream's radius)
  // may be: 0.005 mm, or 0.0002 inch for an inch job (growing by 1e-4 of the radius).
  double circle_tolerance = 0.005;
  bool check_circles = true;  // tests of the arc rules on made-up arcs turn it off

  static ArcSettings from(const MachineParameters& params);
  // True when no arc can be changed (every switch passes arcs through).
  bool passes_everything() const;
};

// True when the filter surely passes this arc unchanged (start, end and centre as the filter
// completes them from the tool position; tilted: its arc_plane_m is none of XY, YZ, ZX); false
// when not sure. The filter then skips working out the arc's angles, radius and length.
bool arc_surely_passes(const ArcSettings& settings, const Eigen::Vector3d& start, const Eigen::Vector3d& end,
                       const Eigen::Vector3d& centre, toolpath::geometry::Plane plane,
                       toolpath::geometry::Direction direction, bool five_axis, bool tilted);

class ArcFilter final : public KindSource {
public:
  ArcFilter(toolpath::CommandSource& input, ArcSettings settings, WarningSink warn = {});
  bool next_with_kind(toolpath::Command& out, CommandKind& kind) override;

private:
  void plan(const toolpath::Command& arc, CommandKind kind, const CommandFields& f);
  void emit(toolpath::Command& out, CommandKind& kind);
  inline void follow(const toolpath::Command& out, CommandKind kind, const CommandFields& f);  // arc_filter.cpp

  KindedInput input_;
  ArcSettings settings_;
  WarningSink warn_;
  ToolPosition position_;
  SetHistory history_;          // recent points of the kinematic sets
  ArcSets sets_;                // how the arc being replaced maps to each kinematic set
  std::optional<double> apos_, bpos_;  // rotary angles of the last command that gave them
  bool five_axis_ = false;      // the arc being replaced is an @arc_5x
  std::optional<double> rotary_from_[2], rotary_to_[2];  // apos, bpos at its start and end
  CommandFields handed_;        // of the command handed out last (KindSource::fields())
  toolpath::Command original_;  // the arc being replaced
  toolpath::geometry::Arc arc_;
  std::vector<double> cuts_;    // piece boundaries as offsets from the start, 0 .. sweep
  int chords_ = 0;              // > 0: linearising into this many chords
  int piece_ = 0;               // next piece to emit
  int pieces_ = 0;              // 0: nothing pending
};

}  // namespace prp
