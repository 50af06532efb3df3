// Kinematic coordinate sets (`xhpos`, `xmcenter`, `xostart`, `start_angle_h`, ... gpptool spec
// 3.2-3.3) on the pieces of a split or linearised arc.
//
// Within one 3-axis @arc every set is a rigid image of the working-plane ("pos") set: the part,
// machine and local systems differ from it by a rotation (or a mirror) and a shift. The arc's own
// start, centre and end in the set fix that map, and each piece's values follow from the pos
// piece. A planar arc of 180 or 360 degrees has its three points on one line, which leaves the
// set's plane orientation open; recent points of the same set (the lead-in move) then fix it, and
// failing those a set whose offsets equal the pos offsets is taken as shifted, not rotated.
// Whatever cannot be derived is an error naming the set, never a copied stale value.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "prp/filters/command_kind.hpp"
#include "toolpath/command.hpp"
#include "toolpath/geometry.hpp"

namespace prp {

// The six sets beside pos, by index: h, m, o, l, t, to.
inline constexpr std::array<std::string_view, 6> kSetPrefixes = {"h", "m", "o", "l", "t", "to"};
inline constexpr int kSetCount = static_cast<int>(kSetPrefixes.size());

enum class SetRole : std::uint8_t { End, Centre, Start };  // x?pos, x?center, x?start
struct SetCoordinate {
  int set;  // index into kSetPrefixes
  SetRole role;
  int axis;  // 0 x, 1 y, 2 z
};
// `xhpos` -> {h, End, x}; `ztocenter` -> {to, Centre, z}; anything else (xpos, xcenter_rel) -> none.
std::optional<SetCoordinate> classify_set_coordinate(std::string_view name);
// The same by interned key, one table load (every set coordinate is a catalogue name).
std::optional<SetCoordinate> classify_set_coordinate(toolpath::ParamKey key);

// The end points of the sets (x?pos, y?pos, z?pos): what SetHistory::observe records of a move.
inline constexpr toolpath::ParamKey kSetEndPoints[] = {
    toolpath::ParamKey::xhpos,  toolpath::ParamKey::yhpos,  toolpath::ParamKey::zhpos,  toolpath::ParamKey::xmpos,
    toolpath::ParamKey::ympos,  toolpath::ParamKey::zmpos,  toolpath::ParamKey::xopos,  toolpath::ParamKey::yopos,
    toolpath::ParamKey::zopos,  toolpath::ParamKey::xlpos,  toolpath::ParamKey::ylpos,  toolpath::ParamKey::zlpos,
    toolpath::ParamKey::xtpos,  toolpath::ParamKey::ytpos,  toolpath::ParamKey::ztpos,  toolpath::ParamKey::xtopos,
    toolpath::ParamKey::ytopos, toolpath::ParamKey::ztopos};

// Recent motion end points seen in pos and in each set, newest last (a few per set).
class SetHistory {
public:
  struct Pair {
    Eigen::Vector3d pos, set;
  };
  // Motion commands add their end points; commands that may move the frame (a tool change, a new
  // job, a plane rotation, a home) forget everything. A move that names no set end point
  // (kSetEndPoints) changes nothing.
  void observe(const toolpath::Command& c);
  void observe(const toolpath::Command& c, CommandKind kind);  // kind: command_kind(c), already known
  void add(int set, const Eigen::Vector3d& pos, const Eigen::Vector3d& in_set);
  void clear();
  const std::vector<Pair>& pairs(int set) const { return pairs_[static_cast<std::size_t>(set)]; }

private:
  std::array<std::vector<Pair>, kSetCount> pairs_;
};

class ArcSets {
public:
  // Works out, for every set the arc carries, how it maps from pos. Throws StreamError when a set
  // is incomplete, is not a rigid image of pos, or its orientation cannot be fixed.
  void prepare(const toolpath::Command& arc, const toolpath::geometry::Arc& pos, SetHistory& history);
  bool empty() const { return maps_.empty(); }
  // An @arc piece: end, start, centre, and (where the arc has them) relative centre and angles.
  void write_piece(toolpath::Command& out, const toolpath::geometry::Arc& piece, bool first, bool last) const;
  // A chord's end vertex: x?pos y?pos z?pos only.
  void write_vertex(toolpath::Command& out, const Eigen::Vector3d& pos, bool last) const;

private:
  struct Map {
    int set = 0;
    Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();  // p_set - centre_set = linear (p - centre)
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();      // pos centre (at the start's height)
    Eigen::Vector3d centre_set = Eigen::Vector3d::Zero();
    Eigen::Vector3d start_set = Eigen::Vector3d::Zero(), end_set = Eigen::Vector3d::Zero();
    toolpath::geometry::PlaneAxes rel_axes{0, 1, 2};  // axes of x?center_rel / y?center_rel
    std::optional<toolpath::geometry::PlaneAxes> angle_axes;  // plane of start_angle_? (h, m)
    bool has_rel = false, has_angles = false;
    Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return centre_set + linear * (p - centre); }
  };
  std::vector<Map> maps_;
};

}  // namespace prp
