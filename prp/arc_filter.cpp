#include "prp/arc_filter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

namespace prp {

using toolpath::geometry::Arc;
using toolpath::geometry::Direction;
using toolpath::geometry::Plane;

namespace {

// The parameters plan() reads, found in one pass over the arc's parameters (the first of each
// name, as with Command::find).
enum ArcField { kX, kY, kZ, kApos, kBpos, kXcenter, kYcenter, kXrel, kYrel, kZstart, kSize, kPlane, kDirection,
                kPlaneM, kFieldCount };

using toolpath::ParamKey;

// Per key: the ArcField it is, or -1.
constexpr auto kArcFields = [] {
  KeyTable<std::int8_t> t{};
  t.fill(-1);
  const std::pair<ParamKey, ArcField> fields[] = {
      {ParamKey::xpos, kX},          {ParamKey::ypos, kY},
      {ParamKey::zpos, kZ},          {ParamKey::apos, kApos},
      {ParamKey::bpos, kBpos},       {ParamKey::xcenter, kXcenter},
      {ParamKey::ycenter, kYcenter}, {ParamKey::xcenter_rel, kXrel},
      {ParamKey::ycenter_rel, kYrel}, {ParamKey::zstart, kZstart},
      {ParamKey::arc_size, kSize},   {ParamKey::arc_plane, kPlane},
      {ParamKey::arc_direction, kDirection}, {ParamKey::arc_plane_m, kPlaneM}};
  for (auto [key, field] : fields) at(t, key) = static_cast<std::int8_t>(field);
  return t;
}();

// Per key, what track() follows: 0 nothing, 1..5 xpos ypos zpos apos bpos.
constexpr auto kTracked = [] {
  KeyTable<std::uint8_t> t{};
  at(t, ParamKey::xpos) = 1;
  at(t, ParamKey::ypos) = 2;
  at(t, ParamKey::zpos) = 3;
  at(t, ParamKey::apos) = 4;
  at(t, ParamKey::bpos) = 5;
  return t;
}();

struct ArcFields {
  explicit ArcFields(const toolpath::Command& c) {
    for (const toolpath::Parameter& p : c.parameters)
      if (const int f = at(kArcFields, p.key); f >= 0 && !values[f]) values[f] = &p.value;
  }
  const toolpath::Value* find(ArcField f) const { return values[f]; }
  // As prp::number().
  std::optional<double> number(ArcField f) const {
    const toolpath::Value* v = values[f];
    if (!v || (v->kind != toolpath::ValueKind::Integer && v->kind != toolpath::ValueKind::Numeric)) return std::nullopt;
    return number_of(*v);
  }
  const toolpath::Value* values[kFieldCount] = {};
};

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
  s.min_length = p.numeric("arc_min_length");
  s.eps_angle = p.numeric("eps_angle");
  s.zero_value = p.numeric("zero_value");
  s.limits_defaulted = !p.has("arc_max_angle") && !p.has("arc_max_chord");
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
  if (!input_.next(out, kind)) return false;
  if (out.is_stream_command() && (kind == CommandKind::arc || kind == CommandKind::arc_5x)) {
    plan(out, kind);
    if (pieces_ > 0) {
      sets_.prepare(out, arc_, history_);
      history_.observe(out, kind);
      swap(original_, out);
      emit(out, kind);
      return true;
    }
  }
  track(out, kind);
  return true;
}

// One pass over the parameters for the tool position (moves only, as ToolPosition::update) and
// for apos/bpos (any stream command); the first of each name counts, as with number().
void ArcFilter::track(const toolpath::Command& out, CommandKind kind) {
  history_.observe(out, kind);
  if (!out.is_stream_command()) return;
  const unsigned wanted = has(kMovesTool, kind) ? 0x1fu : 0x18u;  // bits: x y z a b
  unsigned seen = 0;
  for (const toolpath::Parameter& p : out.parameters) {
    const int code = at(kTracked, p.key);
    if (code == 0) continue;
    const unsigned bit = 1u << (code - 1);
    if (!(wanted & bit) || (seen & bit)) continue;
    seen |= bit;
    if (is_number(p.value)) {
      const double x = number_of(p.value);
      if (code <= 3) position_.set_axis(code - 1, x);
      else (code == 4 ? apos_ : bpos_) = x;
    }
    if (seen == wanted) break;
  }
}

// Decides what replaces the arc (spec 3.2 process_arc); pieces_ stays 0 when it passes unchanged.
void ArcFilter::plan(const toolpath::Command& c, CommandKind kind) {
  piece_ = pieces_ = chords_ = 0;
  cuts_.clear();
  five_axis_ = kind == CommandKind::arc_5x;
  const ArcFields f(c);
  rotary_from_[0] = apos_;
  rotary_from_[1] = bpos_;
  rotary_to_[0] = f.number(kApos);
  rotary_to_[1] = f.number(kBpos);

  Plane plane = Plane::XY;
  if (const toolpath::Value* v = f.find(kPlane)) {
    auto p = toolpath::geometry::parse_plane(v->text);
    if (!p) throw StreamError(c, fmt::format("arc_plane `{}` is none of XY, YZ, ZX", v->text));
    plane = *p;
  }
  const toolpath::Value* dir = f.find(kDirection);
  if (!dir || !(toolpath::iequals(dir->text, "CW") || toolpath::iequals(dir->text, "CCW")))
    throw StreamError(c, "expected arc_direction CW or CCW");
  const Direction direction = toolpath::iequals(dir->text, "CW") ? Direction::CW : Direction::CCW;
  const auto a = toolpath::geometry::axes(plane);

  // End point: missing coordinates stay where the tool is.
  static constexpr std::string_view pos_names[] = {"xpos", "ypos", "zpos"};
  Eigen::Vector3d end;
  for (int i = 0; i < 3; ++i) {
    auto v = f.number(static_cast<ArcField>(kX + i));
    if (!v) v = position_.axis(i);
    if (!v) throw StreamError(c, fmt::format("the arc has no {} and the tool position is unknown", pos_names[i]));
    end[i] = *v;
  }
  // Centre and start in the arc plane: xcenter/ycenter and the *_rel values are the plane's first
  // and second coordinates (XY: x y, YZ: y z, ZX: z x).
  auto cx = f.number(kXcenter), cy = f.number(kYcenter);
  auto rx = f.number(kXrel), ry = f.number(kYrel);
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
  auto zstart = plane == Plane::XY ? f.number(kZstart) : std::nullopt;
  start[a.normal] = zstart ? *zstart : position_.axis(a.normal).value_or(end[a.normal]);
  centre[a.normal] = start[a.normal];

  arc_ = toolpath::geometry::make_arc(start, end, centre, plane, direction, f.number(kSize));
  const ArcSettings& s = settings_;
  const bool helical = std::abs(arc_.rise()) > std::max(s.zero_value, 1e-9);
  const bool in_machine_plane = plane == s.machine_plane;

  if (arc_.sweep < s.eps_angle || arc_.length() < s.min_length) {
    chords_ = pieces_ = 1;  // one straight line to the end
    return;
  }
  bool tilted = false;  // in the machine's axes the arc lies in none of XY, YZ, ZX
  if (const toolpath::Value* m = f.find(kPlaneM)) tilted = !toolpath::geometry::parse_plane(m->text);
  if (!s.arc_exist || (helical && !s.arc_3d) || (!in_machine_plane && !s.zx_yz) ||
      (s.max_radius && arc_.radius > *s.max_radius) || (five_axis_ && !s.arc_5x) || (tilted && s.main_planes)) {
    chords_ = pieces_ = toolpath::geometry::chord_count(arc_, s.max_angle, s.max_chord);
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
    if (out.find(ParamKey::zstart)) set_number(out, ParamKey::zstart, piece.start.z());
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
  track(out, kind);
}

}  // namespace prp
