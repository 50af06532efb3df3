// `input` and `print` at run time, and the answers that stand in for the user (runs are never
// interactive). Both write to the run log, never into the NC output.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>

#include "gppl/builtins/functions.hpp"
#include "gppl/run/machine.hpp"

namespace gppl {

namespace {

// A number written as tonum() reads it; nullopt when it is not one.
std::optional<double> parse_number(const std::string& text) {
  static const FunctionSignature* tonum = find_function("tonum");
  try {
    const Value v = call_function(*tonum, std::span<const Value>(std::array<Value, 1>{Value::of_string(text)}));
    return v.numeric;
  } catch (const Error&) {
    return std::nullopt;
  }
}

// The answer's text as a value of the input's type, or the error that says why it is not one.
Value convert(const InputStatement& input, const Answer& answer, const Program& program) {
  auto fail = [&](ErrorCode code, std::string_view expected) -> Value {
    throw make_error(code, program.position(input.pos), {},
                     fmt::format("{}: {} needs {}, not '{}'", answer.source, input.name, expected, answer.value));
  };
  const std::string& text = answer.value;
  if (!input.type) {  // an implicit host variable: a number when it reads as one, else a string
    if (auto x = parse_number(text)) return Value::of_numeric(*x);
    return Value::of_string(text);
  }
  switch (*input.type) {
    case Type::String: return Value::of_string(text);
    case Type::Numeric:
      if (auto x = parse_number(text)) return Value::of_numeric(*x);
      return fail(ErrorCode::NotNumeric, "a number");
    case Type::Integer: {
      const auto x = parse_number(text);
      const double whole = x ? std::round(*x) : 0.0;
      if (!x || std::fabs(*x - whole) > 1e-9) return fail(ErrorCode::NotNumeric, "an integer");
      if (std::fabs(whole) > double(max_integer)) return fail(ErrorCode::ValueRange, "an integer within ±999999999");
      return Value::of_integer(std::int64_t(whole));
    }
    case Type::Logical: {
      const std::string word = lower(text);
      if (word == "1" || word == "true") return Value::of_logical(true);
      if (word == "0" || word == "false") return Value::of_logical(false);
      return fail(ErrorCode::NotLogical, "a logical (0, 1, TRUE or FALSE)");
    }
  }
  return Value();
}

// The answer for each input statement (by index); warnings for answers nobody reads.
std::vector<std::string> prepare(const Program& program, std::span<const Answer> answers,
                                 std::vector<std::optional<PreparedAnswer>>* out) {
  std::map<std::string, const Answer*> by_name;  // the last answer of a name wins
  for (const Answer& a : answers) by_name[lower(a.name)] = &a;
  std::map<std::string, bool> read;
  for (const InputStatement& input : program.inputs) read[lower(input.name)] = true;
  std::vector<std::string> warnings;
  for (const Answer& a : answers)
    if (!read.count(lower(a.name)) && by_name[lower(a.name)] == &a)
      warnings.push_back(fmt::format("{}: warning: no input statement reads '{}'", a.source, a.name));
  std::vector<Error> errors;
  if (out) out->assign(program.inputs.size(), std::nullopt);
  for (std::size_t i = 0; i < program.inputs.size(); ++i) {
    const InputStatement& input = program.inputs[i];
    const auto it = by_name.find(lower(input.name));
    if (it == by_name.end()) continue;
    try {
      Value v = convert(input, *it->second, program);
      if (out) (*out)[i] = PreparedAnswer{std::move(v), it->second->source};
    } catch (const Error& e) {
      errors.push_back(e);
    }
  }
  if (!errors.empty()) throw Errors(std::move(errors));
  return warnings;
}

std::string shown(const Value& v) {
  switch (v.type) {
    case Type::Integer: return fmt::format("{}", v.integer);
    case Type::Numeric: return fmt::format("{}", v.numeric);
    case Type::Logical: return v.logical ? "TRUE" : "FALSE";
    case Type::String: break;
  }
  return fmt::format("'{}'", v.text);
}

std::string where(const Program& program, SourcePos pos) {
  const Position p = program.position(pos);
  return fmt::format("{}:{}:{}", p.file, p.line, p.column);
}

}  // namespace

std::vector<std::string> check_answers(const Program& program, std::span<const Answer> answers) {
  return prepare(program, answers, nullptr);
}

void Interpreter::set_answers(std::span<const Answer> answers) { prepare(state_->program, answers, &state_->answers); }

void Interpreter::set_log_stream(std::ostream* log) { state_->log = log; }

void Interpreter::log_inputs(bool on) { state_->log_inputs = on; }

void Interpreter::State::input(std::uint32_t index) {
  const InputStatement& s = program.inputs[index];
  OutputLine prompt;
  render(program.items[s.prompt], prompt);
  const VarRef& ref = program.refs[s.target];
  Cell& target = element(ref);  // an index out of range is an error even without an answer
  const PreparedAnswer* answer = index < answers.size() && answers[index] ? &*answers[index] : nullptr;
  if (answer) assign(target, answer->value, ChangeOverride::Compute, &ref);
  if (log == nullptr || !log_inputs) return;
  *log << fmt::format("{}: input '{}': {} = {} ({})\n", where(program, s.pos), prompt.view(), s.name, shown(target.value),
                      answer ? "answer from " + answer->source : "no answer: value kept");
}

void Interpreter::State::print(std::uint32_t first, std::uint32_t count) {
  OutputLine text;
  for (std::uint32_t i = first; i < first + count; ++i) render(program.items[i], text);
  if (log != nullptr) *log << fmt::format("{}: print: {}\n", where(program, current->pos), text.view());
}

}  // namespace gppl
