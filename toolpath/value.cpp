#include "toolpath/value.hpp"

namespace toolpath {

std::string_view kind_name(ValueKind kind) {
  switch (kind) {
    case ValueKind::Integer: return "integer";
    case ValueKind::Numeric: return "numeric";
    case ValueKind::Logical: return "logical";
    case ValueKind::String: return "string";
    case ValueKind::Enum: return "enumeration";
  }
  return "?";
}

Value Value::make_integer(std::int64_t v, ChangeFlag f) {
  Value r;
  r.kind = ValueKind::Integer;
  r.integer = v;
  r.flag = f;
  return r;
}

Value Value::make_numeric(double v, ChangeFlag f) {
  Value r;
  r.kind = ValueKind::Numeric;
  r.numeric = v;
  r.flag = f;
  return r;
}

Value Value::make_logical(bool v) {
  Value r;
  r.kind = ValueKind::Logical;
  r.logical = v;
  return r;
}

Value Value::make_string(std::string v) {
  Value r;
  r.kind = ValueKind::String;
  r.text = std::move(v);
  return r;
}

Value Value::make_enum(std::string word) {
  Value r;
  r.kind = ValueKind::Enum;
  r.text = std::move(word);
  return r;
}

double Value::as_number() const {
  if (kind == ValueKind::Integer) return static_cast<double>(integer);
  if (kind == ValueKind::Numeric) return numeric;
  return 0.0;
}

bool operator==(const Value& a, const Value& b) {
  if (a.kind != b.kind || a.flag != b.flag) return false;
  switch (a.kind) {
    case ValueKind::Integer: return a.integer == b.integer;
    case ValueKind::Numeric: return a.numeric == b.numeric;
    case ValueKind::Logical: return a.logical == b.logical;
    case ValueKind::String: return a.text == b.text;
    case ValueKind::Enum: return iequals(a.text, b.text);
  }
  return false;
}

}  // namespace toolpath
