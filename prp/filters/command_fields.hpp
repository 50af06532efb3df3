// The parameters the geometric filters read, found in one pass over a command's parameters (the
// first of each name, as Command::find finds it). The arc filter finds them on every command it
// hands out and passes them on with it (KindSource::fields()), so the precision filter after it
// reads them instead of walking the parameters a second time.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

#include "prp/filters/kinematic_sets.hpp"
#include "prp/filters/motion.hpp"

namespace prp {

struct CommandFields {
  // The precision filter's parameters first, in its order (lengths, the first three the tool
  // position, then the feed and the spindle speed), then the others the arc filter reads.
  enum Field : std::uint8_t {
    xpos, ypos, zpos, xcenter, ycenter, xcenter_rel, ycenter_rel, radius, zstart, drill_upper_z, drill_lower_z,
    drill_clearance_z, drill_depth, down_step, feed, spin,
    apos, bpos, arc_size, arc_plane, arc_direction, arc_plane_m,
    count
  };
  // Per key: its Field, set_end_point for a set end point (kSetEndPoints), other for the rest.
  static constexpr std::uint8_t set_end_point = count, other = count + 1;
  static_assert(other < 32, "present holds a bit per code");

  CommandFields() = default;
  explicit CommandFields(toolpath::Command& c) { find(c); }

  // From the last parameter to the first, each stored under its code without a test: the first of
  // each name is stored last, and any other parameter lands in a slot nobody reads. Slots are not
  // cleared: `present` tells which hold this command's.
  void find(toolpath::Command& c) {
    std::uint32_t seen = 0;
    toolpath::Parameter* p = c.parameters.data() + c.parameters.size();
    while (p != c.parameters.data()) {
      --p;
      const std::uint8_t code = at(codes(), p->key);
      slots[code] = &p->value;
      seen |= std::uint32_t{1} << code;
    }
    present = seen;
  }
  bool has(std::uint8_t code) const { return (present >> code) & 1; }
  // The parameter, or null when the command has none of that name.
  toolpath::Value* operator[](std::uint8_t code) const { return has(code) ? slots[code] : nullptr; }
  // As prp::number().
  std::optional<double> number(Field f) const {
    const toolpath::Value* v = (*this)[f];
    if (!v || !is_number(*v)) return std::nullopt;
    return number_of(*v);
  }
  bool names_set_end_point() const { return has(set_end_point); }

  toolpath::Value* slots[other + 1];  // per Field, then set_end_point and other; valid where present
  std::uint32_t present = 0;          // bit f: slots[f] holds the command's first of that name

  static constexpr toolpath::ParamKey key_of[count] = {
      toolpath::ParamKey::xpos,          toolpath::ParamKey::ypos,          toolpath::ParamKey::zpos,
      toolpath::ParamKey::xcenter,       toolpath::ParamKey::ycenter,       toolpath::ParamKey::xcenter_rel,
      toolpath::ParamKey::ycenter_rel,   toolpath::ParamKey::radius,        toolpath::ParamKey::zstart,
      toolpath::ParamKey::drill_upper_z, toolpath::ParamKey::drill_lower_z, toolpath::ParamKey::drill_clearance_z,
      toolpath::ParamKey::drill_depth,   toolpath::ParamKey::down_step,     toolpath::ParamKey::feed,
      toolpath::ParamKey::spin,          toolpath::ParamKey::apos,          toolpath::ParamKey::bpos,
      toolpath::ParamKey::arc_size,      toolpath::ParamKey::arc_plane,     toolpath::ParamKey::arc_direction,
      toolpath::ParamKey::arc_plane_m};

private:
  static const KeyTable<std::uint8_t>& codes() {
    static constexpr KeyTable<std::uint8_t> table = [] {
      KeyTable<std::uint8_t> t{};
      t.fill(other);
      for (std::uint8_t f = 0; f < count; ++f) at(t, key_of[f]) = f;
      for (toolpath::ParamKey key : kSetEndPoints) at(t, key) = set_end_point;
      return t;
    }();
    return table;
  }
};

}  // namespace prp
