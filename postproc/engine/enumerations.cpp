#include "postproc/engine/enumerations.hpp"

namespace postproc {
namespace {

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = lower(c);
  return r;
}

}  // namespace

std::size_t Enumerations::NoCaseHash::operator()(std::string_view s) const {
  std::size_t h = 14695981039346656037ull;  // FNV-1a over the lower-case bytes
  for (char c : s) h = (h ^ static_cast<unsigned char>(lower(c))) * 1099511628211ull;
  return h;
}

bool Enumerations::NoCaseEqual::operator()(std::string_view a, std::string_view b) const {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (lower(a[i]) != lower(b[i])) return false;
  return true;
}

Enumerations::Enumerations(const std::vector<std::string>& drill_type_names) {
  // Codes count from 1 inside each group, so that a variable never assigned (0) equals no constant.
  // The machine types count from 0: the Integrex post assigns 0 for milling and 1 for turning.
  declare_group({"milling", "turning", "wire_cut"}, 0);
  declare_group({"CW", "CCW"}, 1);
  declare_group({"XY", "YZ", "ZX", "ZC", "error"}, 1);
  declare_group({"COMP_LEFT", "COMP_RIGHT", "COMP_OFF"}, 1);
  declare_group({"MIRROR_OFF", "MIRROR_X", "MIRROR_Y", "MIRROR_XY"}, 1);
  declare_group({"D_Drilling", "D_F_Drill", "D_Peck", "D_Tapping", "D_Boring", "D_R_Boring", "D_F_Boring"}, 1);
  declare_group({"AXIS4_NONE", "AXIS4_FACE", "AXIS4_TOP", "AXIS4_RADIAL"}, 1);
  declare_group({"axis4_split", "axis4_polar", "axis4_cartesian"}, 1);
  declare_group({"tool_side_left", "tool_side_right", "tool_side_middle"}, 1);
  declare_group({"groove_rough", "groove_prof", "cut", "ang_groove"}, 1);
  declare_group({"ROUGH", "COPY", "PROFILE"}, 1);
  declare_group({"ONCE", "MULTIPLE"}, 1);
  declare_group({"LONG", "FACE"}, 1);
  declare_group({"INTERNAL", "EXTERNAL", "BACK", "FRONT"}, 1);
  declare_group({"DS_VALUE", "DS_LIST"}, 1);
  declare_group({"MM", "PITCH_INCH"}, 1);
  declare_group({"MM_MIN", "MM_REV"}, 1);
  declare_group({"RPM", "CSS"}, 1);
  declare_group({"T_TANGENT", "T_CENTER", "T_DEFINE"}, 1);
  declare_group({"EXT_ROUGH", "TURN_DRILLING", "EXT_THREAD", "EXT_GROOVE", "EXT_CONTOUR", "INT_FACE_BACK",
                 "INT_THREAD", "INT_GROOVE", "INT_CONTOUR", "INT_ROUGH"},
                1);
  declare_group({"none", "hatch", "contour", "plunging", "linear", "offset_cutting", "spiral", "circular_pocket",
                 "constant_z", "pencil"},
                1);
  declare_group({"INTEGER", "NUMERIC", "STRING"}, 1);
  declare_group({"positive", "negative"}, 1);  // the taper of a wire pass (p_angle)
  // Switch words of a real trace: SolidCAM's posts test `flood_coolant eq 1` for `on` and
  // `eq 0 or eq 2` for the rest (docs/engine.md, "Enumeration words"). Codes only: names as
  // common as `on` or `no` are not made constants a post could collide with.
  declare_group({"off", "on", "no_action"}, 0, false);
  declare_group({"no", "yes"}, 0, false);
  // Drill cycles: the PRP's own names first, then the internal types (a PRP normally names its cycles
  // after them, as the FANUC one does: `drill_type = Peck Peck Y Delay`).
  std::int64_t drill_code = 0;  // SolidCAM numbers the machine's cycles from 0: `drill_type:0` is the first
  for (const auto& name : drill_type_names)
    if (!by_lower_name_.count(lower(name))) {
      by_lower_name_.emplace(lower(name), drill_code);
      constants_.push_back({name, drill_code++});
    }
  for (std::string_view internal : {"Drilling", "F_Drill", "Peck", "Tapping", "Boring", "R_Boring", "F_Boring"})
    if (!by_lower_name_.count(lower(internal))) {
      by_lower_name_.emplace(lower(internal), drill_code);
      constants_.push_back({std::string(internal), drill_code++});
    }
}

void Enumerations::declare_group(std::initializer_list<std::string_view> words, std::int64_t first_code,
                                 bool constants) {
  std::int64_t code = first_code;
  for (std::string_view w : words) {
    // A word listed by two groups keeps its first code (`XY` is the same in every plane group).
    if (by_lower_name_.emplace(lower(w), code).second && constants) constants_.push_back({std::string(w), code});
    ++code;
  }
}

std::int64_t Enumerations::code(std::string_view word) {
  if (auto it = by_lower_name_.find(word); it != by_lower_name_.end()) return it->second;
  std::int64_t c = next_unknown_code_++;
  by_lower_name_.emplace(lower(word), c);
  return c;
}

}  // namespace postproc
