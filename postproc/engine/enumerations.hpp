// Enumeration constants (`CW`, `COMP_LEFT`, `Peck`, ...): GPPL sees them as read-only integers, and the
// engine turns enumeration words of the command stream into the same integers, so that
// `if side eq COMP_LEFT` compares codes. See docs/engine.md for how the codes are chosen.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace postproc {

class Enumerations {
public:
  struct Constant {
    std::string name;  // as the spec spells it
    std::int64_t code;
  };

  // The constants of gpptool-commands.md section 4, with `drill_type` names from the PRP's
  // `drill_type = <name> <internal type> ...` lines (the internal type names when the PRP has none).
  explicit Enumerations(const std::vector<std::string>& drill_type_names = {});

  // The code of a word (case-insensitive). A word no table lists gets a code of its own, the same
  // for every later use, so that change detection still works on it.
  std::int64_t code(std::string_view word);
  // The declared constants, in declaration order (each name once).
  const std::vector<Constant>& constants() const { return constants_; }

private:
  void declare_group(std::initializer_list<std::string_view> words, std::int64_t first_code, bool constants = true);
  std::vector<Constant> constants_;
  // Keyed by the lower-case word; hashed and compared without case, so that code() looks a
  // stream's word up as it is, without building a lower-case copy (it runs for every command).
  struct NoCaseHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const;
  };
  struct NoCaseEqual {
    using is_transparent = void;
    bool operator()(std::string_view a, std::string_view b) const;
  };
  std::unordered_map<std::string, std::int64_t, NoCaseHash, NoCaseEqual> by_lower_name_;
  std::int64_t next_unknown_code_ = 1000;
};

}  // namespace postproc
