// Value factories and error types of the public header, and the name folding both halves share.
#include <fmt/format.h>

#include "gppl/gppl.hpp"
#include "gppl/program.hpp"

namespace gppl {

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return r;
}

Value Value::of_integer(std::int64_t v) {
  Value r;
  r.type = Type::Integer;
  r.integer = v;
  return r;
}

Value Value::of_numeric(double v) {
  Value r;
  r.type = Type::Numeric;
  r.numeric = v;
  return r;
}

Value Value::of_logical(bool v) {
  Value r;
  r.type = Type::Logical;
  r.logical = v;
  return r;
}

Value Value::of_string(std::string v) {
  Value r;
  r.type = Type::String;
  r.text = std::move(v);
  return r;
}

namespace {
// `file:line:col: error N: text`; an error no source line caused (a value the host assigned) says
// only what it can, never `:0:0:`.
std::string error_text(int number, const Position& where, const std::string& text) {
  if (where.line != 0) return fmt::format("{}:{}:{}: error {}: {}", where.file, where.line, where.column, number, text);
  if (!where.file.empty()) return fmt::format("{}: error {}: {}", where.file, number, text);
  return fmt::format("error {}: {}", number, text);
}
}  // namespace

Error::Error(int number, Position where, const std::string& text)
    : std::runtime_error(error_text(number, where, text)),
      number_(number),
      where_(std::move(where)),
      text_(text) {}

namespace {
std::string join(const std::vector<Error>& all) {
  std::string s;
  for (const auto& e : all) {
    if (!s.empty()) s += '\n';
    s += e.what();
  }
  return s;
}
}  // namespace

Errors::Errors(std::vector<Error> all) : std::runtime_error(join(all)), all_(std::move(all)) {}

}  // namespace gppl
