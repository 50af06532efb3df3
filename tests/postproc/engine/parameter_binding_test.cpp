// ParameterBinding's plans (assign_all) against its general path (assign_each): random commands
// whose parameters change order, spelling and value kind, into variables of every type (read or
// never read by the post, declared, implicit, an array, none), with T/F change flags. Both leave
// the same values, change and active flags, and throw the same errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gppl/gppl.hpp"
#include "postproc/engine/enumerations.hpp"
#include "postproc/engine/host_variables.hpp"
#include "postproc/engine/parameter_binding.hpp"
#include "prp/prp.hpp"
#include "toolpath/command.hpp"

namespace {

using toolpath::ChangeFlag;
using toolpath::Value;
using toolpath::ValueKind;

class NoOutput final : public gppl::OutputSink {
public:
  void write_line(std::string_view, const gppl::LineOrigin&) override {}
};

// Reads some catalogue names and leaves others unread (ParameterBinding skips values of their own
// type); extra_* are declared by the post, implicit_a is typed by what the host gives it.
const char* const kPost =
    "@init_post\n"
    "  global numeric extra_n\n  global string extra_s\n  global logical extra_l\n  global integer extra_i\n"
    "endp\n"
    "@line\n"
    "  {nl, xpos, ' ', ypos, ' ', feed, ' ', tool_number, ' ', job_name, ' ', arc_direction, ' ', compensation}\n"
    "  {nl, extra_n, ' ', extra_s, ' ', extra_l, ' ', extra_i, ' ', implicit_a, ' ', ang_prms<<1>>}\n"
    "endp\n";

// Catalogue names (read and unread), other names, array elements (one outside the array), and a
// name with no variable at all; several spellings of one name.
const std::vector<std::string> kNames = {
    "xpos",      "XPos",     "ypos",     "zpos",        "feed",        "tool_number", "job_name",
    "arc_direction", "arc_plane", "ycenter_rel", "message", "compensation", "absolute",  "extra_n",
    "Extra_S",   "extra_l",  "extra_i",  "implicit_a",  "nobody",      "ang_prms<<1>>", "ang_prms<<2,2>>",
    "ang_prms<<99>>"};

struct Bound {
  explicit Bound(std::shared_ptr<const gppl::Program> program)
      : interpreter(std::move(program), sink), binding(interpreter, enums, {"xpos"}) {
    binding.set_input_name("job.trace");
  }
  NoOutput sink;
  postproc::Enumerations enums;
  gppl::Interpreter interpreter;
  postproc::ParameterBinding binding;
};

Value random_value(std::mt19937& random, ValueKind kind) {
  static const std::array<const char*, 5> texts{"abc", "5", "", "1.5", "T"};
  static const std::array<const char*, 7> words{"CW", "ccw", "CCW", "XY", "Cw", "COMP_LEFT", "zz_new_word"};
  Value v;
  switch (kind) {
    case ValueKind::Integer: v = Value::make_integer(static_cast<std::int64_t>(random() % 4)); break;
    case ValueKind::Numeric: v = Value::make_numeric(static_cast<double>(random() % 4) / 2); break;
    case ValueKind::Logical: v = Value::make_logical(random() % 2 == 0); break;
    case ValueKind::String: v = Value::make_string(texts[random() % texts.size()]); break;
    case ValueKind::Enum: v = Value::make_enum(words[random() % words.size()]); break;
  }
  const unsigned flag = random() % 8;
  v.flag = flag == 0 ? ChangeFlag::Changed : flag == 1 ? ChangeFlag::Unchanged : ChangeFlag::None;
  return v;
}

// "ok", or what the assignment threw.
template <class Assign>
std::string outcome(Assign&& assign) {
  try {
    assign();
    return "ok";
  } catch (const std::exception& e) {
    return e.what();
  }
}

void expect_same_variables(const Bound& a, const Bound& b, const std::string& where) {
  for (const std::string& name : kNames) {
    const auto id = a.interpreter.find_variable(name.substr(0, name.find('<')));
    if (!id) continue;
    const gppl::Value& x = a.interpreter.value(*id);
    const gppl::Value& y = b.interpreter.value(*id);
    ASSERT_TRUE(x.type == y.type && x.integer == y.integer && x.numeric == y.numeric && x.logical == y.logical &&
                x.text == y.text)
        << name << " after " << where;
    ASSERT_EQ(a.interpreter.changed(*id), b.interpreter.changed(*id)) << name << " after " << where;
    ASSERT_EQ(a.interpreter.active(*id), b.interpreter.active(*id)) << name << " after " << where;
  }
}

TEST(ParameterBinding, PlansDoWhatTheGeneralPathDoes) {
  postproc::Enumerations enums;
  gppl::CompileOptions options;
  options.host_variables = postproc::host_variables(enums, prp::defaults(prp::Units::Metric));
  options.undeclared_from_job = true;
  const auto program = gppl::compile_source(kPost, "p.gpp", options);
  Bound planned(program), general(program);

  std::mt19937 random(14);
  constexpr std::size_t kCommandNames = 3;
  // Each command name has its usual parameters, in an order and with kinds of their own.
  std::vector<std::vector<std::pair<std::size_t, ValueKind>>> usual(kCommandNames);
  for (auto& parameters : usual)
    for (std::size_t i = 0, n = 3 + random() % 10; i < n; ++i)
      parameters.emplace_back(random() % kNames.size(), static_cast<ValueKind>(random() % 5));
  std::vector<postproc::ParameterBinding::Plan> plans(kCommandNames);
  std::vector<postproc::ParameterBinding::Positions> positions(kCommandNames);

  std::size_t errors = 0;
  for (std::size_t n = 0; n < 20000; ++n) {
    const std::size_t name = random() % kCommandNames;
    auto parameters = usual[name];
    switch (random() % 8) {  // mostly as usual
      case 0: std::shuffle(parameters.begin(), parameters.end(), random); break;
      case 1: parameters.erase(parameters.begin() + static_cast<std::ptrdiff_t>(random() % parameters.size())); break;
      case 2: parameters.emplace_back(random() % kNames.size(), static_cast<ValueKind>(random() % 5)); break;
      case 3: parameters[random() % parameters.size()].second = static_cast<ValueKind>(random() % 5); break;
      default: break;
    }
    toolpath::Command command;
    command.name = "@c" + std::to_string(name);
    command.index = n;
    command.line = static_cast<std::uint32_t>(n + 1);
    for (const auto& [parameter, kind] : parameters) {
      toolpath::Parameter p(kNames[parameter], random_value(random, kind));
      p.line = command.line;
      p.column = static_cast<std::uint32_t>(command.parameters.size() + 1);
      command.parameters.push_back(std::move(p));
    }
    const std::string where = "command " + std::to_string(n);
    const std::string a = outcome([&] { planned.binding.assign_all(command, plans[name]); });
    const std::string b = outcome([&] { general.binding.assign_each(command, positions[name]); });
    ASSERT_EQ(a, b) << where;
    errors += a != "ok";
    expect_same_variables(planned, general, where);
  }
  EXPECT_GT(errors, 100u);  // the errors were tested too
}

}  // namespace
