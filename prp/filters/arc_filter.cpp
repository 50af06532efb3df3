#include "prp/filters/arc_filter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

namespace prp {

using toolpath::geometry::Arc;
using toolpath::geometry::Direction;
using toolpath::geometry::Plane;

using toolpath::ParamKey;
using F = CommandFields;

namespace {

// In the arc plane, from the centre: (ux, uy) to the start, (vx, vy) to the end, their squares and
// lengths as square roots (within a few units in the last place of hypot's). The circle check and
// the shortcut both work from these.
struct Spokes {
  Spokes(const Eigen::Vector3d& start, const Eigen::Vector3d& end, const Eigen::Vector3d& centre,
         toolpath::geometry::PlaneAxes a)
      : ux(start[a.first] - centre[a.first]),
        uy(start[a.second] - centre[a.second]),
        vx(end[a.first] - centre[a.first]),
        vy(end[a.second] - centre[a.second]),
        u2(ux * ux + uy * uy),
        v2(vx * vx + vy * vy),
        u(std::sqrt(u2)),
        v(std::sqrt(v2)) {}
  double ux, uy, vx, vy, u2, v2, u, v;
};

// An arc is one only when its start and end lie on one circle about its centre, and its `radius`
// (when the stream gives it) is that circle's: otherwise the post writes an arc the machine
// refuses or, with an R word, one through other points. Trace numbers carry 3 decimals or more,
// so their rounding stays well inside the tolerance.
void check_circle(const toolpath::Command& c, const Spokes& d, std::optional<double> radius, double circle_tolerance,
                  bool shortcut) {
  // Surely within the tolerance, told from the square roots: they differ from hypot's distances by
  // a few units in the last place (1e-15 of the radius), far inside the margins (1e-12) taken here.
  // Any other arc (near a limit, or of squares out of range; NaN fails every comparison) is
  // checked with hypot as below.
  constexpr double kMargin = 1e-12;
  const double room = circle_tolerance * (1 + 1e-4 * d.u) * (1 - kMargin);
  if (shortcut && d.u2 < 1e100 && d.v2 < 1e100 && d.u > 1e-6 * (1 + kMargin) &&
      std::abs(d.v - d.u) + kMargin * (d.u + d.v) < room &&
      (!radius || std::abs(*radius - d.u) + kMargin * (std::abs(*radius) + d.u) < room))
    return;
  const double r_start = std::hypot(d.ux, d.uy), r_end = std::hypot(d.vx, d.vy);
  const double tolerance = circle_tolerance * (1 + 1e-4 * r_start);
  if (r_start <= 1e-6)  // below any machine's resolution; smaller real arcs are still arcs
    throw StreamError(c, "arc with zero radius: its centre is where it starts");
  if (std::abs(r_end - r_start) > tolerance)
    throw StreamError(c, fmt::format("the arc's end point is not on its circle: {:g} from the centre, its start {:g} "
                                     "(more than {:g} apart)",
                                     r_end, r_start, tolerance));
  if (radius && std::abs(*radius - r_start) > tolerance)
    throw StreamError(c, fmt::format("radius {:g} is not the arc's: its start is {:g} from its centre (more than {:g} "
                                     "apart)",
                                     *radius, r_start, tolerance));
}

// arc_surely_passes(), told without make_arc's atan2, fmod and hypot. The switches that could
// change an arc are off, or settled by the exact expressions plan() uses; the sweep and the radius
// are bounded from products of the coordinates. Their rounding errors (a few units in the last
// place: 1e-13 degrees, 1e-15 of the radius) are far below the margins (1e-9), and an arc near 0,
// 180 or 360 degrees, or of a radius below 1e-50 or above 1e50, is worked out in full. NaN fails
// every comparison here, so it is worked out too. `rise`: the end minus the start along the normal.
bool surely_passes(const ArcSettings& s, const Spokes& d, double rise, Plane plane, Direction direction,
                   bool five_axis, bool tilted) {
  if (!s.arc_exist || s.quadrants || (five_axis && !s.arc_5x) || (tilted && s.main_planes) ||
      (plane != s.machine_plane && !s.zx_yz))
    return false;
  if (!s.arc_3d && std::abs(rise) > std::max(s.zero_value, 1e-9)) return false;  // helical
  const double ux = d.ux, uy = d.uy, vx = d.vx, vy = d.vy, u2 = d.u2, v2 = d.v2;
  if (!(u2 > 1e-100 && u2 < 1e100 && v2 > 1e-100 && v2 < 1e100)) return false;
  const double n = d.u * d.v;
  // n sin(sweep): positive for a sweep below 180 degrees in the arc's direction.
  const double turn = direction == Direction::CCW ? ux * vy - uy * vx : uy * vx - ux * vy;
  constexpr double kMargin = 1e-9;
  double low;  // the sweep is at least this (degrees)
  if (turn > kMargin * n) {
    // 0 < sweep < 180: at least 90 when the dot product is not positive, else at least its sine (radians).
    low = ux * vx + uy * vy <= 0 ? 90.0 : turn / n * (180.0 / std::numbers::pi);
  } else if (turn < -kMargin * n && s.gt_180) {
    low = 180.0;  // 180 < sweep < 360, which only gt_180 = N would cut
  } else {
    return false;
  }
  low = low * (1 - kMargin) - kMargin;
  if (!(low > s.eps_angle)) return false;                             // plan(): one line below eps_angle
  const double radius = d.u;                                          // hypot(ux, uy), within 1e-15
  if (s.max_radius && !(radius * (1 + kMargin) <= *s.max_radius)) return false;  // chords above the limit
  // length() is at least the radius times the sweep in radians (its helical part only adds).
  return s.min_length <= 0 || radius * low * (std::numbers::pi / 180.0) * (1 - kMargin) > s.min_length;
}

}  // namespace

ArcSettings ArcSettings::from(const MachineParameters& p) {
  ArcSettings s;
  s.arc_exist = p.logical("arc_exist");
  s.arc_3d = p.logical("arc_3d");
  s.quadrants = p.logical("arc_quadrants");
  s.gt_180 = p.logical("arc_gt_180");
  s.zx_yz = p.logical("arc_zx_yz");
  s.arc_5x = p.logical("arc_5x");
  // The engine default of arc_in_main_planes (Y) must not change a stream, so only a PRP that says
  // it (or pos_to_coord = Y) makes tilted machine-plane arcs into chords.
  s.main_planes = (p.has("arc_in_main_planes") && p.logical("arc_in_main_planes")) || p.logical("pos_to_coord");
  s.machine_plane = toolpath::geometry::parse_plane(p.text("machine_plane")).value_or(Plane::XY);
  if (p.has("arc_max_radius")) s.max_radius = p.numeric("arc_max_radius");
  s.max_angle = p.numeric("arc_max_angle");
  s.max_chord = p.numeric("arc_max_chord");
  if (p.has("arc_max_deviation")) s.max_deviation = p.numeric("arc_max_deviation");
  s.min_length = p.numeric("arc_min_length");
  s.eps_angle = p.numeric("eps_angle");
  s.zero_value = p.numeric("zero_value");
  s.limits_defaulted = !p.has("arc_max_angle") && !p.has("arc_max_chord") && !p.has("arc_max_deviation");
  s.circle_tolerance = p.units() == Units::Inch ? 0.0002 : 0.005;
  return s;
}

bool ArcSettings::passes_everything() const {
  return arc_exist && arc_3d && !quadrants && gt_180 && zx_yz && arc_5x && !main_planes && !max_radius &&
         min_length <= 0 && eps_angle <= 0;
}

ArcFilter::ArcFilter(toolpath::CommandSource& input, ArcSettings settings, WarningSink warn)
    : input_(input), settings_(settings), warn_(std::move(warn)) {}

bool ArcFilter::next_with_kind(toolpath::Command& out, CommandKind& kind) {
  if (piece_ < pieces_) {
    emit(out, kind);
    return true;
  }
  fields_ = nullptr;
  if (!input_.next(out, kind)) return false;
  if (!out.is_stream_command()) return true;  // followed by nothing here, the set history included
  CommandFields& f = handed_;
  f.find(out);
  fields_ = &f;
  if (kind == CommandKind::arc || kind == CommandKind::arc_5x) {
    plan(out, kind, f);
    if (pieces_ > 0) {
      sets_.prepare(out, arc_, history_);
      history_.observe(out, kind);
      swap(original_, out);
      emit(out, kind);
      return true;
    }
  }
  follow(out, kind, f);
  return true;
}

// Follows a stream command: the tool position (moves only, as ToolPosition::update), apos/bpos
// (any command) and the kinematic-set history. Inlined into next_with_kind(), which every command
// takes.
[[gnu::always_inline]] inline void ArcFilter::follow(const toolpath::Command& out, CommandKind kind,
                                                     const CommandFields& f) {
  const bool moves = has(kMovesTool, kind);
  if (!moves || f.names_set_end_point()) history_.observe(out, kind);
  if (moves)
    for (int i = 0; i < 3; ++i)
      if (const toolpath::Value* v = f[static_cast<std::uint8_t>(F::xpos + i)]; v && is_number(*v))
        position_.set_axis(i, number_of(*v));
  if (const toolpath::Value* v = f[F::apos]; v && is_number(*v)) apos_ = number_of(*v);
  if (const toolpath::Value* v = f[F::bpos]; v && is_number(*v)) bpos_ = number_of(*v);
}

// Decides what replaces the arc (spec 3.2 process_arc); pieces_ stays 0 when it passes unchanged.
void ArcFilter::plan(const toolpath::Command& c, CommandKind kind, const CommandFields& f) {
  piece_ = pieces_ = chords_ = 0;
  cuts_.clear();
  five_axis_ = kind == CommandKind::arc_5x;
  if (five_axis_) {  // emit() turns the rotary axes of an @arc_5x's pieces only
    rotary_from_[0] = apos_;
    rotary_from_[1] = bpos_;
    rotary_to_[0] = f.number(F::apos);
    rotary_to_[1] = f.number(F::bpos);
  }

  Plane plane = Plane::XY;
  if (const toolpath::Value* v = f[F::arc_plane]) {
    auto p = toolpath::geometry::parse_plane(v->text);
    if (!p) throw StreamError(c, fmt::format("arc_plane `{}` is none of XY, YZ, ZX", v->text));
    plane = *p;
  }
  const toolpath::Value* dir = f[F::arc_direction];
  if (!dir || !(toolpath::iequals(dir->text, "CW") || toolpath::iequals(dir->text, "CCW")))
    throw StreamError(c, "expected arc_direction CW or CCW");
  const Direction direction = toolpath::iequals(dir->text, "CW") ? Direction::CW : Direction::CCW;
  const auto a = toolpath::geometry::axes(plane);

  // End point: missing coordinates stay where the tool is.
  static constexpr std::string_view pos_names[] = {"xpos", "ypos", "zpos"};
  Eigen::Vector3d end;
  for (int i = 0; i < 3; ++i) {
    auto v = f.number(static_cast<F::Field>(F::xpos + i));
    if (!v) v = position_.axis(i);
    if (!v) throw StreamError(c, fmt::format("the arc has no {} and the tool position is unknown", pos_names[i]));
    end[i] = *v;
  }
  // Centre and start in the arc plane: xcenter/ycenter and the *_rel values are the plane's first
  // and second coordinates (XY: x y, YZ: y z, ZX: z x).
  auto cx = f.number(F::xcenter), cy = f.number(F::ycenter);
  auto rx = f.number(F::xcenter_rel), ry = f.number(F::ycenter_rel);
  Eigen::Vector3d start, centre;
  for (int k = 0; k < 2; ++k) {
    const int axis = k == 0 ? a.first : a.second;
    auto cen = k == 0 ? cx : cy;
    auto rel = k == 0 ? rx : ry;
    auto here = position_.axis(axis);
    if (!cen && rel && here) cen = *here + *rel;
    if (!cen) throw StreamError(c, "the arc has no centre (xcenter/ycenter, or xcenter_rel/ycenter_rel)");
    centre[axis] = *cen;
    start[axis] = rel ? *cen - *rel : here.value_or(*cen);
    if (!rel && !here) throw StreamError(c, "the arc's start is unknown (no xcenter_rel/ycenter_rel)");
  }
  auto zstart = plane == Plane::XY ? f.number(F::zstart) : std::nullopt;
  start[a.normal] = zstart ? *zstart : position_.axis(a.normal).value_or(end[a.normal]);
  centre[a.normal] = start[a.normal];
  const Spokes spokes(start, end, centre, a);
  if (settings_.check_circles)
    check_circle(c, spokes, f.number(F::radius), settings_.circle_tolerance, !settings_.work_out_every_arc);

  bool tilted = false;  // in the machine's axes the arc lies in none of XY, YZ, ZX
  if (const toolpath::Value* m = f[F::arc_plane_m]) tilted = !toolpath::geometry::parse_plane(m->text);
  if (!settings_.work_out_every_arc &&
      surely_passes(settings_, spokes, end[a.normal] - start[a.normal], plane, direction, five_axis_, tilted))
    return;

  arc_ = toolpath::geometry::make_arc(start, end, centre, plane, direction, f.number(F::arc_size));
  const ArcSettings& s = settings_;
  const bool helical = std::abs(arc_.rise()) > std::max(s.zero_value, 1e-9);
  const bool in_machine_plane = plane == s.machine_plane;

  if (arc_.sweep < s.eps_angle || arc_.length() < s.min_length) {
    chords_ = pieces_ = 1;  // one straight line to the end
    return;
  }
  if (!s.arc_exist || (helical && !s.arc_3d) || (!in_machine_plane && !s.zx_yz) ||
      (s.max_radius && arc_.radius > *s.max_radius) || (five_axis_ && !s.arc_5x) || (tilted && s.main_planes)) {
    chords_ = pieces_ = toolpath::geometry::chord_count(arc_, s.max_angle, s.max_chord, s.max_deviation);
    if (settings_.limits_defaulted && warn_) {
      warn_(c, "arcs are linearised but the PRP sets neither arc_max_angle nor arc_max_chord: using 10 degrees "
               "and 30 mm / 1.1811 inch");
      settings_.limits_defaulted = false;  // once
    }
    return;
  }
  std::vector<double> inner;
  // A cut that would leave a piece below eps_angle, or shorter than zero_value, is not made: that
  // sliver is rounding in the toolpath (an arc starting at 180.002 degrees), not a real crossing.
  const double sliver = std::max({1e-6, s.eps_angle, s.zero_value / arc_.radius * 180.0 / std::numbers::pi});
  if (s.quadrants) inner = toolpath::geometry::quadrant_crossings(arc_, sliver);
  else if (!s.gt_180 && arc_.sweep > 180.0 + 1e-9) inner = {arc_.sweep / 2.0};
  if (inner.empty()) return;  // the arc passes unchanged
  cuts_.push_back(0.0);
  cuts_.insert(cuts_.end(), inner.begin(), inner.end());
  cuts_.push_back(arc_.sweep);
  pieces_ = static_cast<int>(cuts_.size()) - 1;
}

bool arc_surely_passes(const ArcSettings& s, const Eigen::Vector3d& start, const Eigen::Vector3d& end,
                       const Eigen::Vector3d& centre, Plane plane, Direction direction, bool five_axis, bool tilted) {
  const auto a = toolpath::geometry::axes(plane);
  return surely_passes(s, Spokes(start, end, centre, a), end[a.normal] - start[a.normal], plane, direction,
                       five_axis, tilted);
}

// Hands out the next piece and its kind: a chord is a @line (@line_5x), a smaller arc keeps the
// original's name.
void ArcFilter::emit(toolpath::Command& out, CommandKind& kind) {
  const int i = piece_++;
  const bool last = piece_ == pieces_;
  const double to = chords_ > 0 ? (last ? arc_.sweep : arc_.sweep * (i + 1) / chords_)
                                : cuts_[static_cast<std::size_t>(i) + 1];
  const Arc piece = arc_.piece(chords_ > 0 ? arc_.sweep * i / chords_ : cuts_[static_cast<std::size_t>(i)], to);
  const bool as_line = chords_ > 0 || piece.sweep < settings_.eps_angle || piece.length() < settings_.min_length;
  if (as_line) {
    make_motion(out, five_axis_ ? "@line_5x" : "@line", original_, piece.end, number(original_, ParamKey::feed));
    kind = five_axis_ ? CommandKind::line_5x : CommandKind::line;
    sets_.write_vertex(out, piece.end, last);
  } else {
    out = original_;
    out.trace.clear();
    kind = five_axis_ ? CommandKind::arc_5x : CommandKind::arc;
    const auto a = toolpath::geometry::axes(piece.plane);
    set_point(out, piece.end);
    set_number(out, ParamKey::xcenter_rel, piece.centre[a.first] - piece.start[a.first]);
    set_number(out, ParamKey::ycenter_rel, piece.centre[a.second] - piece.start[a.second]);
    set_number(out, ParamKey::start_angle, piece.start_angle());
    set_number(out, ParamKey::end_angle, piece.end_angle());
    set_number(out, ParamKey::arc_size, piece.sweep);
    // SolidCAM sends an arc with its start point, from which real posts work the arc out (a
    // Sinumerik post recomputes the end and aborts on a mismatch): each piece starts where the
    // one before ended.
    if (out.find(ParamKey::zstart)) set_number(out, ParamKey::zstart, piece.start.z());
    if (out.find("xstart")) set_number(out, "xstart", piece.start.x());
    if (out.find("ystart")) set_number(out, "ystart", piece.start.y());
    sets_.write_piece(out, piece, i == 0, last);
  }
  if (five_axis_) {
    // The rotary axes turn in step with the arc angle, from where the previous command left them.
    static constexpr ParamKey names[] = {ParamKey::apos, ParamKey::bpos};
    for (int k = 0; k < 2; ++k) {
      const auto& from = rotary_from_[k];
      const auto& end = rotary_to_[k];
      if (!end) continue;
      set_number(out, names[k], last || !from ? *end : *from + (*end - *from) * (to / arc_.sweep));
    }
  }
  if (last) out.trace = original_.trace;  // the original post's output belongs to the whole arc
  handed_.find(out);
  fields_ = &handed_;
  follow(out, kind, handed_);
}

}  // namespace prp
