#include "prp/filters/kinematic_sets.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "prp/filters/motion.hpp"
#include "prp/prp.hpp"

namespace prp {
namespace {

using toolpath::geometry::PlaneAxes;
using Eigen::Vector3d;

constexpr std::string_view kAxes = "xyz";
constexpr std::string_view kRoles[] = {"pos", "center", "start"};

struct SetNames {
  std::string point[3][3];  // [role][axis]
  std::string rel[2];       // x?center_rel y?center_rel
  std::string start_angle, end_angle, plane;
};

const std::array<SetNames, kSetCount>& names() {
  static const auto table = [] {
    std::array<SetNames, kSetCount> t;
    for (int s = 0; s < kSetCount; ++s) {
      auto& n = t[static_cast<std::size_t>(s)];
      const std::string p(kSetPrefixes[static_cast<std::size_t>(s)]);
      for (int r = 0; r < 3; ++r)
        for (int a = 0; a < 3; ++a) n.point[r][a] = std::string(1, kAxes[static_cast<std::size_t>(a)]) + p + std::string(kRoles[r]);
      n.rel[0] = "x" + p + "center_rel";
      n.rel[1] = "y" + p + "center_rel";
      n.start_angle = "start_angle_" + p;
      n.end_angle = "end_angle_" + p;
      n.plane = "arc_plane_" + p;
    }
    return t;
  }();
  return table;
}

bool ends_with_ci(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && toolpath::iequals(s.substr(s.size() - suffix.size()), suffix);
}

// Tolerance for comparing lengths that come from a trace (values rounded to 3 or 4 decimals).
double tolerance(double scale) { return 2e-3 + 1e-6 * scale; }

double sine_between(const Vector3d& a, const Vector3d& b) {
  const double n = a.norm() * b.norm();
  return n > 0 ? a.cross(b).norm() / n : 0.0;
}

// Below this sine two offsets are too close to parallel to fix a plane (rounded trace values).
constexpr double kMinSine = 0.01;

struct Correspondence {
  Vector3d pos, set;
};

bool rigid_pair(const Correspondence& p, const Correspondence& q, double tol) {
  return std::abs((p.pos - q.pos).norm() - (p.set - q.set).norm()) <= tol;
}

std::optional<PlaneAxes> plane_axes(const toolpath::Command& c, const std::string& name) {
  const toolpath::Value* v = c.find(name);
  if (!v) return std::nullopt;
  auto plane = toolpath::geometry::parse_plane(v->text);
  if (!plane) return std::nullopt;
  return toolpath::geometry::axes(*plane);
}

double angle_in(const Vector3d& offset, PlaneAxes a) {
  return toolpath::geometry::normalize_degrees(std::atan2(offset[a.second], offset[a.first]) * 180.0 / std::numbers::pi);
}

}  // namespace

// Runs on every parameter of every motion: the set prefixes are one or two letters, so most names
// are rejected by their length or first letter before any suffix is compared.
std::optional<SetCoordinate> classify_set_coordinate(std::string_view name) {
  if (name.size() < 5 || name.size() > 9) return std::nullopt;  // xhpos .. ztocenter
  const char first = toolpath::ascii_lower(name[0]);
  if (first < 'x' || first > 'z') return std::nullopt;
  for (int r = 0; r < 3; ++r) {
    const std::string_view role = kRoles[r];
    if (!ends_with_ci(name, role)) continue;
    const std::string_view middle = name.substr(1, name.size() - 1 - role.size());
    int set = -1;
    if (middle.size() == 1) {
      switch (toolpath::ascii_lower(middle[0])) {
        case 'h': set = 0; break;
        case 'm': set = 1; break;
        case 'o': set = 2; break;
        case 'l': set = 3; break;
        case 't': set = 4; break;
        default: break;
      }
    } else if (middle.size() == 2 && toolpath::iequals(middle, "to")) {
      set = 5;
    }
    if (set < 0) return std::nullopt;
    return SetCoordinate{set, static_cast<SetRole>(r), first - 'x'};
  }
  return std::nullopt;
}

namespace {

// Per key: 0 not a set coordinate, else 1 + set * 9 + role * 3 + axis. Filled once from the
// spelled names, so the table and classify_set_coordinate(string_view) cannot disagree.
const KeyTable<std::uint8_t> kSetCoordinates = [] {
  KeyTable<std::uint8_t> t{};
  for (std::size_t k = 1; k < t.size(); ++k) {
    const auto key = static_cast<toolpath::ParamKey>(k);
    if (auto c = classify_set_coordinate(toolpath::param_name(key)))
      t[k] = static_cast<std::uint8_t>(1 + c->set * 9 + static_cast<int>(c->role) * 3 + c->axis);
  }
  return t;
}();

// What SetHistory::observe records, per key: 0 nothing, 1..3 xpos ypos zpos, else 4 + set * 3 + axis
// for a set end point (x?pos).
const KeyTable<std::uint8_t> kObserved = [] {
  KeyTable<std::uint8_t> t{};
  at(t, toolpath::ParamKey::xpos) = 1;
  at(t, toolpath::ParamKey::ypos) = 2;
  at(t, toolpath::ParamKey::zpos) = 3;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const int code = kSetCoordinates[k];
    if (code != 0 && (code - 1) / 3 % 3 == static_cast<int>(SetRole::End))
      t[k] = static_cast<std::uint8_t>(4 + (code - 1) / 9 * 3 + (code - 1) % 3);
  }
  return t;
}();

}  // namespace

std::optional<SetCoordinate> classify_set_coordinate(toolpath::ParamKey key) {
  const int code = at(kSetCoordinates, key);
  if (code == 0) return std::nullopt;
  return SetCoordinate{(code - 1) / 9, static_cast<SetRole>((code - 1) / 3 % 3), (code - 1) % 3};
}

void SetHistory::clear() {
  for (auto& p : pairs_) p.clear();
}

void SetHistory::add(int set, const Vector3d& pos, const Vector3d& in_set) {
  auto& list = pairs_[static_cast<std::size_t>(set)];
  if (list.size() >= 6) list.erase(list.begin());
  list.push_back({pos, in_set});
}

void SetHistory::observe(const toolpath::Command& c) { observe(c, command_kind(c)); }

void SetHistory::observe(const toolpath::Command& c, CommandKind kind) {
  using K = CommandKind;
  if (!c.is_stream_command()) return;
  if (!has(kMovesTool, kind)) {
    constexpr KindSet keeps = bit(K::compensation) | bit(K::message) | bit(K::feed_spin) | bit(K::delay) |
                              bit(K::tool_path_info) | bit(K::absolute_mode) | bit(K::line_on);
    if (!has(keeps, kind)) clear();
    return;
  }
  std::array<std::array<double, 3>, kSetCount> end{};
  std::array<int, kSetCount> seen{};
  std::array<double, 3> pos{};
  int pos_seen = 0;
  bool any_set = false;
  for (const auto& p : c.parameters) {
    const int code = at(kObserved, p.key);
    if (code == 0 || !is_number(p.value)) continue;
    if (code <= 3) {
      pos[static_cast<std::size_t>(code - 1)] = number_of(p.value);
      pos_seen |= 1 << (code - 1);
      continue;
    }
    const int set = (code - 4) / 3, axis = (code - 4) % 3;
    end[static_cast<std::size_t>(set)][static_cast<std::size_t>(axis)] = number_of(p.value);
    seen[static_cast<std::size_t>(set)] |= 1 << axis;
    any_set = true;
  }
  if (!any_set) return;  // nothing to record (set histories change only through add())
  if (pos_seen != 7) return;
  for (int s = 0; s < kSetCount; ++s) {
    const auto& e = end[static_cast<std::size_t>(s)];
    if (seen[static_cast<std::size_t>(s)] == 7) add(s, Vector3d(pos[0], pos[1], pos[2]), Vector3d(e[0], e[1], e[2]));
  }
}

void ArcSets::prepare(const toolpath::Command& arc, const toolpath::geometry::Arc& geometry, SetHistory& history) {
  maps_.clear();
  // One pass over the parameters: which set coordinates the arc carries.
  std::array<std::array<Vector3d, 3>, kSetCount> points;
  std::array<int, kSetCount> seen{};
  for (const auto& p : arc.parameters) {
    auto k = classify_set_coordinate(p.key);
    if (!k) continue;
    points[static_cast<std::size_t>(k->set)][static_cast<std::size_t>(k->role)][k->axis] = p.value.as_number();
    seen[static_cast<std::size_t>(k->set)] |= 1 << (3 * static_cast<int>(k->role) + k->axis);
  }
  const Vector3d S = geometry.start, C = geometry.centre, E = geometry.end;
  const double scale = std::max({S.cwiseAbs().maxCoeff(), E.cwiseAbs().maxCoeff(), C.cwiseAbs().maxCoeff()});
  for (int s = 0; s < kSetCount; ++s) {
    const auto set = static_cast<std::size_t>(s);
    if (seen[set] == 0) continue;
    const SetNames& n = names()[set];
    if (seen[set] != 0777)
      throw StreamError(arc, fmt::format("the arc carries only part of the {} coordinate set (it needs {}.., {}.. and "
                                         "{}..): the pieces' {} values cannot be derived",
                                         kSetPrefixes[set], n.point[0][0], n.point[1][0], n.point[2][0], kSetPrefixes[set]));
    Map m;
    m.set = s;
    m.centre = C;
    m.end_set = points[set][0];
    m.centre_set = points[set][1];
    m.start_set = points[set][2];
    const double tol = tolerance(scale + m.centre_set.cwiseAbs().maxCoeff());
    const Correspondence cs{C, m.centre_set}, ss{S, m.start_set}, es{E, m.end_set};
    if (!rigid_pair(cs, ss, tol) || !rigid_pair(cs, es, tol) || !rigid_pair(ss, es, tol))
      throw StreamError(arc, fmt::format("the arc's {} coordinates are not a rigid image of its working-plane ones "
                                         "(start to centre {:.6g} against {:.6g}, start to end {:.6g} against {:.6g}): "
                                         "the pieces' {} values cannot be derived",
                                         kSetPrefixes[set], (m.start_set - m.centre_set).norm(), (S - C).norm(),
                                         (m.end_set - m.start_set).norm(), (E - S).norm(), kSetPrefixes[set]));

    // Two offsets from the centre that span a plane: the arc's own start and end, or a recent point.
    const Vector3d a = S - C, a_set = m.start_set - m.centre_set;
    std::vector<Correspondence> others{es};
    for (const auto& h : history.pairs(s)) others.push_back({h.pos, h.set});
    std::optional<Correspondence> b;
    for (auto it = others.begin(); it != others.end(); ++it) {
      if (sine_between(a, it->pos - C) >= kMinSine && rigid_pair(*it, cs, tol) && rigid_pair(*it, ss, tol)) {
        b = *it;
        others.erase(it);
        break;
      }
    }
    if (a.norm() <= tol) {
      m.linear.setIdentity();  // a point-sized arc: only the shift matters
    } else if (b) {
      const Vector3d bp = b->pos - C, b_set = b->set - m.centre_set;
      Eigen::Matrix3d from, to;
      from << a, bp, a.cross(bp);
      to << a_set, b_set, a_set.cross(b_set);
      // A further point off the plane of a and b tells a mirrored set from a rotated one.
      double handedness = 1.0;
      for (const auto& o : others) {
        const Vector3d q = o.pos - C;
        if (!rigid_pair(o, cs, tol) || !rigid_pair(o, ss, tol) || !rigid_pair(o, *b, tol)) continue;
        const Vector3d coeff = from.fullPivLu().solve(q);
        if (std::abs(coeff[2]) * a.cross(bp).norm() < 10 * tol) continue;  // in the plane: says nothing
        const Vector3d proper = a_set * coeff[0] + b_set * coeff[1] + a_set.cross(b_set) * coeff[2];
        const Vector3d mirrored = a_set * coeff[0] + b_set * coeff[1] - a_set.cross(b_set) * coeff[2];
        const Vector3d target = o.set - m.centre_set;
        handedness = (mirrored - target).norm() < (proper - target).norm() ? -1.0 : 1.0;
        break;
      }
      to.col(2) *= handedness;
      m.linear = to * from.inverse();
    } else if ((a_set - a).norm() <= tol && ((m.end_set - m.centre_set) - (E - C)).norm() <= tol) {
      m.linear.setIdentity();  // offsets equal pos offsets: the set is pos shifted
    } else {
      throw StreamError(arc, fmt::format("the arc's {0} points lie on one line (a half or full circle) and no recent "
                                         "{0} point fixes the orientation of its plane: the pieces' {0} values cannot "
                                         "be derived",
                                         kSetPrefixes[set]));
    }
    m.has_rel = arc.find(n.rel[0]) || arc.find(n.rel[1]);
    m.has_angles = arc.find(n.start_angle) || arc.find(n.end_angle);
    m.angle_axes = plane_axes(arc, n.plane);
    m.rel_axes = m.angle_axes.value_or(toolpath::geometry::axes(geometry.plane));
    maps_.push_back(m);
  }
  // The arc's own points stay available for the next arc of the same set.
  for (const Map& m : maps_) {
    history.add(m.set, S, m.start_set);
    history.add(m.set, C, m.centre_set);
  }
}

void ArcSets::write_piece(toolpath::Command& out, const toolpath::geometry::Arc& piece, bool first, bool last) const {
  for (const Map& m : maps_) {
    const SetNames& n = names()[static_cast<std::size_t>(m.set)];
    const Vector3d start = first ? m.start_set : m.apply(piece.start);
    const Vector3d end = last ? m.end_set : m.apply(piece.end);
    const Vector3d centre = m.apply(piece.centre);  // at the piece's start height, as the pos centre
    for (int a = 0; a < 3; ++a) {
      set_number(out, n.point[0][a], end[a]);
      set_number(out, n.point[1][a], centre[a]);
      set_number(out, n.point[2][a], start[a]);
    }
    if (m.has_rel) {
      set_number(out, n.rel[0], centre[m.rel_axes.first] - start[m.rel_axes.first]);
      set_number(out, n.rel[1], centre[m.rel_axes.second] - start[m.rel_axes.second]);
    }
    if (m.has_angles && m.angle_axes) {
      set_number(out, n.start_angle, angle_in(start - centre, *m.angle_axes));
      set_number(out, n.end_angle, angle_in(end - centre, *m.angle_axes));
    }
  }
}

void ArcSets::write_vertex(toolpath::Command& out, const Vector3d& pos, bool last) const {
  for (const Map& m : maps_) {
    const SetNames& n = names()[static_cast<std::size_t>(m.set)];
    const Vector3d p = last ? m.end_set : m.apply(pos);
    for (int a = 0; a < 3; ++a) set_number(out, n.point[0][a], p[a]);
  }
}

}  // namespace prp
