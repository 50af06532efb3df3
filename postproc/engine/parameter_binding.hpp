// How the engine hands a command's parameters to the post's variables (docs/engine.md, steps 2-3):
// each parameter goes to the variable of its name, converted to the variable's type, with the
// change attribute computed or forced by the parameter's `T`/`F` flag. Internal to postproc/.
//
// This runs for every parameter of every command, so the binding of a name to its variable is
// looked up once: by the parameter's interned key (toolpath::ParamKey, one array index), or for a
// name outside the catalogue by its position in the command (the same command name brings its
// parameters in the same order, so one comparison usually replaces a name lookup). A command name's
// Plan then keeps, position by position, what its parameter does (assign_all()).
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
    // An array element (`call_prms<<2>>`): slot.id stays empty.
    std::optional<gppl::VariableId> array;
    std::array<int, 2> index{};
    std::uint8_t index_count = 0;
    std::string enum_word;
    std::int64_t enum_code = 0;
  };
  // The positional bindings of one command name (names outside the catalogue).
  using Positions = std::vector<Bound>;

  // What a position of one command name does with its parameter, worked out once for the key it
  // had last time, for each value kind: a command name nearly always brings the same keys in the
  // same order, so a parameter costs one comparison and one table read. Positional: a name outside
  // the catalogue (no key), bound by assign_each()'s way.
  enum class Action : std::uint8_t { Skip, Integer, Numeric, Logical, String, Enum, Element, Positional };
  static constexpr std::size_t kKinds = 5;  // toolpath::ValueKind's
  static_assert(static_cast<std::size_t>(toolpath::ValueKind::Enum) + 1 == kKinds);
  struct Step {
    toolpath::ParamKey key = toolpath::ParamKey::none;
    std::array<Action, kKinds> actions{Action::Positional, Action::Positional, Action::Positional,
                                       Action::Positional, Action::Positional};  // by ValueKind
    gppl::Interpreter::HostSlot variable;  // for the assignments
    Bound* bound = nullptr;                // the key's binding (by_key_ never moves)
  };
  // The steps and positional bindings of one command name.
  struct Plan {
    std::vector<Step> steps;
    Positions positions;
  };

  // `host_reads`: the variables the host itself reads back (by name), which are always assigned.
  ParameterBinding(gppl::Interpreter& interpreter, Enumerations& enums, std::vector<std::string> host_reads = {});

  // Assigns every parameter of `command` to its variable; `plan` belongs to the command's name. A
  // step whose key differs from the parameter's is planned again: the result is always
  // assign_each()'s. A value the variable cannot take is an error at the parameter's position in the input.
  // Inlined into the engine's per-command step: its own call and frame cost more than a parameter.
  [[gnu::always_inline]] void assign_all(const toolpath::Command& command, Plan& plan) {
    const std::size_t count = command.parameters.size();
    if (plan.steps.size() < count) plan.steps.resize(count);  // new steps are Positional: planned below
    const toolpath::Parameter* const first = command.parameters.data();
    const toolpath::Parameter* const end = first + count;
    const toolpath::Parameter* p = first;
    Step* s = plan.steps.data();
    try {
      for (; p != end; ++p, ++s) {
        if (s->key != p->key) [[unlikely]] *s = step_for(*p);
        const toolpath::Value& v = p->value;
        const Action action = s->actions[static_cast<std::size_t>(v.kind)];
        if (action == Action::Numeric) interpreter_.assign_numeric(s->variable, v.numeric, change_override(v.flag));  // most are
        else if (action != Action::Skip) assign_step(*s, action, v, plan.positions, static_cast<std::size_t>(p - first), p->name);
      }
    } catch (const gppl::Error& e) {
      fail(command, *p, e);
    }
  }

  // assign_all() without a plan: each parameter's binding looked up by its key or position. The
  // reference the plans are tested against.
  void assign_each(const toolpath::Command& command, Positions& positions);

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

  // A parameter into its post variable, converted as convert() would, without building a Value
  // (assign_each()'s way; a step does the same for the kind it was planned for).
  void assign(Bound& b, const toolpath::Value& v);
  void assign_bound(Bound& b, const toolpath::Value& v) {
    if (b.slot.id) assign(b, v);
    else if (b.array) assign_element(b, v);
  }
  Step step_for(const toolpath::Parameter& p);
  Action action_for(const Bound& b, toolpath::ValueKind kind) const;
  void assign_step(const Step& s, Action action, const toolpath::Value& v, Positions& positions, std::size_t position,
                   std::string_view name) {
    const gppl::ChangeOverride change = change_override(v.flag);
    switch (action) {
      case Action::Skip: break;
      case Action::Integer: return interpreter_.assign_integer(s.variable, v.integer, change);
      case Action::Numeric: return interpreter_.assign_numeric(s.variable, v.numeric, change);
      case Action::Logical: return interpreter_.assign_logical(s.variable.id(), v.logical, change);
      case Action::String: return interpreter_.assign_string(s.variable.id(), v.text, change);
      case Action::Enum: return interpreter_.assign_integer(s.variable, enum_code(*s.bound, v.text), change);
      case Action::Element: return assign_element(*s.bound, v);
      case Action::Positional: return assign_bound(at_position(positions, position, name), v);
    }
  }
  // The code of an enumeration word; the last one is kept, and compared as written first (it
  // repeats, spelled the same); words are looked up without case.
  std::int64_t enum_code(Bound& b, std::string_view word) {
    if (!b.enum_word.empty() && toolpath::same_short_text(b.enum_word, word)) return b.enum_code;
    return other_word(b, word);
  }
  std::int64_t other_word(Bound& b, std::string_view word);
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
