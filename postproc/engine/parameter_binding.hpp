// How the engine hands a command's parameters to the post's variables (docs/engine.md, steps 2-3):
// each parameter goes to the variable of its name, converted to the variable's type, with the
// change attribute computed or forced by the parameter's `T`/`F` flag. Internal to postproc/.
//
// This runs for every parameter of every command, so the binding of a name to its variable is
// looked up once: by the parameter's interned key (toolpath::ParamKey, one array index), or for a
// name outside the catalogue by its position in the command (the same command name brings its
// parameters in the same order, so one comparison usually replaces a name lookup).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "gppl/gppl.hpp"
#include "postproc/engine/enumerations.hpp"
#include "toolpath/command.hpp"

namespace postproc {

class ParameterBinding {
public:
  // The post variable of one parameter name, and how an enumeration word goes into it.
  struct Slot {
    std::optional<gppl::VariableId> id;
    bool is_string = false;  // the variable is a string: an enumeration word goes in as its text
    // A value of this kind is left out: the post never reads the variable, which holds exactly
    // that type (gppl::Interpreter::unread_type), so the assignment could neither fail nor show.
    // kNoSkip for the rest: other kinds convert, and a conversion may be an error of the job.
    std::uint8_t skipped_kind = kNoSkip;
  };
  static constexpr std::uint8_t kNoSkip = 0xff;
  // One binding with the last enumeration word it converted (a word repeats command after command).
  struct Bound {
    std::string name;  // positional bindings only: the name seen at that position
    Slot slot;
    bool resolved = false;
    // An array element (`call_prms<<2>>`): slot.id stays empty, so the common path skips it.
    std::optional<gppl::VariableId> array;
    std::array<int, 2> index{};
    std::uint8_t index_count = 0;
    std::string enum_word;
    std::int64_t enum_code = 0;
  };
  // The positional bindings of one command name (names outside the catalogue).
  using Positions = std::vector<Bound>;

  // `host_reads`: the variables the host itself reads back (by name), which are always assigned.
  ParameterBinding(gppl::Interpreter& interpreter, Enumerations& enums, std::vector<std::string> host_reads = {});

  // Assigns every parameter of `command` to its variable; `positions` belongs to the command's name.
  // A value the variable cannot take is an error at the parameter's position in the input.
  void assign_all(const toolpath::Command& command, Positions& positions) {
    const std::size_t count = command.parameters.size();
    std::size_t i = 0;
    try {
      for (; i < count; ++i) {
        const toolpath::Parameter& p = command.parameters[i];
        Bound& b = p.key != toolpath::ParamKey::none ? keyed(p) : at_position(positions, i, p.name);
        if (b.slot.id) assign(b, p.value);
        else if (b.array) assign_element(b, p.value);
      }
    } catch (const gppl::Error& e) {
      fail(command, command.parameters[i], e);
    }
  }

  // The input's name for those errors.
  void set_input_name(std::string name) { input_name_ = std::move(name); }

  // The variable of a parameter name (looked up once per name).
  const Slot& slot(std::string_view name);

  // A PRP value as a post value (start-up only; commands go through assign_all()).
  gppl::Value convert(const toolpath::Value& v, bool to_string);

private:
  [[noreturn]] void fail(const toolpath::Command& command, const toolpath::Parameter& p, const gppl::Error& e) const;
  Bound& keyed(const toolpath::Parameter& p) {
    Bound& b = by_key_[static_cast<std::size_t>(p.key)];
    if (!b.resolved) resolve(b, p.name);
    return b;
  }
  Bound& at_position(Positions& positions, std::size_t position, std::string_view name);
  void resolve(Bound& b, std::string_view name);

  // The two enumerations number their cases alike, so the flag converts without a switch.
  static gppl::ChangeOverride change_override(toolpath::ChangeFlag flag) {
    static_assert(int(toolpath::ChangeFlag::None) == int(gppl::ChangeOverride::Compute) &&
                  int(toolpath::ChangeFlag::Changed) == int(gppl::ChangeOverride::ForceChanged) &&
                  int(toolpath::ChangeFlag::Unchanged) == int(gppl::ChangeOverride::ForceUnchanged));
    return static_cast<gppl::ChangeOverride>(flag);
  }

  // A parameter into its post variable, converted as convert() would, without building a Value.
  void assign(Bound& b, const toolpath::Value& v) {
    if (static_cast<std::uint8_t>(v.kind) == b.slot.skipped_kind) return;
    const gppl::VariableId id = *b.slot.id;
    const gppl::ChangeOverride change = change_override(v.flag);
    if (v.kind == toolpath::ValueKind::Numeric) return interpreter_.assign_numeric(id, v.numeric, change);  // most are
    switch (v.kind) {
      case toolpath::ValueKind::Integer: return interpreter_.assign_integer(id, v.integer, change);
      case toolpath::ValueKind::Numeric: return interpreter_.assign_numeric(id, v.numeric, change);
      case toolpath::ValueKind::Logical: return interpreter_.assign_logical(id, v.logical, change);
      case toolpath::ValueKind::String: return interpreter_.assign_string(id, v.text, change);
      case toolpath::ValueKind::Enum: return assign_enum(b, v, change);
    }
  }
  void assign_enum(Bound& b, const toolpath::Value& v, gppl::ChangeOverride change);
  void assign_element(const Bound& b, const toolpath::Value& v);

  struct TransparentHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };

  gppl::Interpreter& interpreter_;
  Enumerations& enums_;
  std::string input_name_;
  std::vector<std::string> host_reads_;
  std::vector<Bound> by_key_;  // indexed by ParamKey
  std::unordered_map<std::string, Slot, TransparentHash, std::equal_to<>> slots_;
};

}  // namespace postproc
