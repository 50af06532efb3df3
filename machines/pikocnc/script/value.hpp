// Run-time values of the script language (spec 2.3) and the static types the compiler checks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pikocnc::script {

// Static types. Records and arrays carry a shape index into Program::shapes.
enum class Kind : std::uint8_t { Integer, Float, Boolean, String, Variant, Record, Array, Void };

struct Type {
  Kind kind = Kind::Void;
  std::uint8_t width = 0;   // Integer: 0 = Integer (32-bit), 1 = Byte, 2 = Cardinal
  std::int32_t shape = -1;  // Record/Array: index into Program::shapes
  bool operator==(const Type&) const = default;
};

// A record's fields or an array's element type and bounds.
struct Shape {
  std::string name;                  // "TPoint", or "array" for arrays
  std::vector<std::string> fields;   // folded (lower-case) field names
  std::vector<Type> field_types;
  Type element;                      // arrays
  std::int64_t low = 0, count = 0;   // arrays
};

// A value at run time: what it holds follows `kind` (Variant is never a run-time kind).
struct Value {
  Kind kind = Kind::Integer;
  bool b = false;
  std::int64_t i = 0;
  double f = 0;
  std::string s;
  std::vector<Value> items;  // record fields / array elements

  static Value integer(std::int64_t v) { Value x; x.kind = Kind::Integer; x.i = v; return x; }
  static Value real(double v) { Value x; x.kind = Kind::Float; x.f = v; return x; }
  static Value boolean(bool v) { Value x; x.kind = Kind::Boolean; x.b = v; return x; }
  static Value text(std::string v) { Value x; x.kind = Kind::String; x.s = std::move(v); return x; }
};

const char* kind_name(Kind kind);

}  // namespace pikocnc::script
