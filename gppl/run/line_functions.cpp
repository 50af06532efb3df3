// start_line / end_line at run time (gpptool-commands.md 2.8, 2.11): the item's display format is
// chosen and checked here, as for any integer item (6.4); the text itself comes from the host,
// which knows the program's structure and may write a placeholder it resolves later.
#include <fmt/format.h>

#include <stdexcept>

#include "gppl/run/machine.hpp"

namespace gppl {

namespace {

constexpr std::string_view kIntegerDefault = "5.0(p)";

}  // namespace

std::string_view name_of(LineFunction f) { return f == LineFunction::StartLine ? "start_line" : "end_line"; }

bool uses_line_functions(const Program& program) { return program.uses_line_functions; }

void OutputSink::line_function(LineFunction which, std::string_view format, const Position& item, std::string& out) {
  (void)format, (void)item, (void)out;
  throw std::runtime_error(fmt::format("this host does not supply {}", name_of(which)));
}

std::string format_integer(std::int64_t value, std::string_view format) {
  return format_value(parse_display_format(format), Value::of_integer(value));
}

void Interpreter::State::render_line_function(const GenItem& item, std::string& out) {
  const auto which = LineFunction(item.a);
  Value& spec_value = push_scratch();
  std::string_view spec;
  if (item.format_kind == FormatKind::Constant) {
    spec = program.format_specs[item.format];
  } else if (item.format_kind == FormatKind::Dynamic) {
    eval(item.format, spec_value);
    if (spec_value.type != Type::String) fail_at(item.pos, ErrorCode::NotString, {}, "a display format must be a string");
    spec = spec_value.text;
  }
  // Rule 3 of 6.4: a block number is an integer, so integer_def_f applies without a format of its own.
  if (spec.empty()) spec = globals[program.slots.integer_def_f].value.text;
  if (spec.empty()) spec = kIntegerDefault;
  (void)cached(format_sites[item.site], spec, item.pos);  // an invalid format is reported at the item
  try {
    sink.line_function(which, spec, program.position(item.pos), out);
  } catch (const Error&) {
    throw;
  } catch (const std::runtime_error& e) {
    fail_at(item.pos, ErrorCode::DoesNotExist, name_of(which), e.what());
  }
  pop_scratch();
}

}  // namespace gppl
