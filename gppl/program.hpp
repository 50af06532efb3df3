// The compiled form of a post: names resolved to slots, statements flattened to instructions with
// jump targets, expressions in one node arena. Built by the compiler, run by the interpreter.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "gppl/builtins/functions.hpp"
#include "gppl/gppl.hpp"

namespace gppl {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;
// VarRef::indices of a name the post uses but nothing declares (a run's implicit host variable):
// every use goes through the out-of-line element path, which refuses it until the host gives it a value.
constexpr std::uint32_t kUndeclared = 0xFFFFFFFEu;

// A compact source position; the file is an index into Program::files.
struct SourcePos {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
};

enum class Group : std::uint8_t { System, Host, Implicit, Global };

// A variable that lives for the whole run (system, host, implicit host, global).
struct GlobalVariable {
  std::string name;
  Type type = Type::Integer;
  Group group = Group::Global;
  bool read_only = false;
  bool typed = true;                    // false: implicit host variable, typed by its first assignment
  std::vector<int> dimensions;          // empty: scalar
  std::uint32_t first_cell = 0;
  std::uint32_t cell_count = 1;
  Value initial;                        // value at the start of a run
  bool initially_active = true;
  SourcePos declared;                   // globals: first declaration
};

// A local of one procedure (typed parameters come first).
struct LocalVariable {
  std::string name;
  Type type = Type::Integer;
  std::vector<int> dimensions;
  std::uint32_t offset = 0;  // first cell in the frame
  std::uint32_t cell_count = 1;
};

// Where a variable reference points: a global variable id, or a local of the running procedure.
struct VarRef {
  bool local = false;
  std::uint32_t id = 0;     // GlobalVariable index or LocalVariable index
  std::uint32_t cell = 0;   // first cell (global cell index or frame offset)
  std::uint32_t indices = kNone;  // first entry in Program::lists of the index expressions (arrays)
  std::uint32_t index_count = 0;
};

enum class NodeKind : std::uint8_t { Constant, Variable, Attribute, Negate, Not, Binary, And, Or, Call };
enum class BinaryOp : std::uint8_t { Add, Sub, Mul, Div, Pow, Eq, Ne, Lt, Le, Gt, Ge };

struct Node {
  NodeKind kind = NodeKind::Constant;
  BinaryOp op = BinaryOp::Add;
  bool active_attribute = false;  // Attribute: active (true) or change (false)
  // Constant, or Variable/Attribute of a scalar: read without evaluating. Binary: a comparison of
  // a scalar variable with a number constant or another scalar, `list` its Program::relations entry.
  bool simple = false;
  std::uint32_t a = 0;            // Constant: constant index; Variable/Attribute: ref index; unary/binary: child
  std::uint32_t b = 0;            // binary: right child
  std::uint32_t list = 0;         // Call: first argument in Program::lists; simple Binary: relation
  std::uint32_t count = 0;        // Call: number of arguments
  std::uint32_t format = kNone;   // Call (tostr): node of the `:format` of the first argument
  const FunctionSignature* function = nullptr;
  SourcePos pos;
};

// `variable op constant` or `variable op variable` of scalars (`if blknum gt 99990`, `if
// arc_plane eq XY`), the most common test of a post, resolved at compile time so that it costs
// the cell reads and a compare. A constant is a number or logical, kept in both forms the type
// rules of 4.5 compare with.
struct Relation {
  struct Cell {
    std::uint32_t index = 0;  // global cell, or frame offset when `local`
    bool local = false;
  };
  Cell left;
  Cell right;               // when right_is_variable
  bool right_is_variable = false;
  bool numeric = false;     // the constant is numeric: compare as numbers whatever the variable holds
  BinaryOp op = BinaryOp::Eq;
  std::int64_t integer = 0;
  double number = 0.0;
};

// Generate items (6.1). A group item is followed by its `count` member items.
// LineFunction: `start_line`/`end_line`, whose text the host supplies (a is the LineFunction).
enum class ItemKind : std::uint8_t { NewBlock, NewLine, Col, ColRel, Text, Value, Group, LineFunction };
enum class FormatKind : std::uint8_t { Default, Constant, Dynamic };

struct GenItem {
  ItemKind kind = ItemKind::Text;
  std::uint32_t a = 0;            // Text: constant index; Value/Col/ColRel: node; Group: member count
  std::uint32_t ref = kNone;      // Value: ref index when the operand is a plain variable or element
  FormatKind format_kind = FormatKind::Default;
  std::uint32_t format = kNone;   // Constant: format index; Dynamic: node
  std::uint32_t name_format = kNone;  // VarRef index of `name_f` for plain scalar variables
  std::uint32_t site = 0;         // format cache slot
  std::uint32_t required = 0;     // Group: first ref in Program::lists that make it required
  std::uint32_t required_count = 0;
  // Value: the global cell of `ref` when it is a scalar global; Group: that of its only required
  // variable. kNone otherwise. Saves the reference's indirections on every item of every line.
  std::uint32_t global_cell = kNone;
  bool has_gcode = false;         // Group: contains the variable gcode (gcode_space)
  bool text_value_pair = false;   // Group: exactly a Text then a Value, `[' X'xpos]`
  SourcePos pos;
};

enum class OpCode : std::uint8_t {
  Nop, Assign, SetChange, SetActive, JumpIfFalse, LoopIfFalse, Jump, Call, InlineLeaf, Generate, Trace, Abort, Exit,
  Return, Input, Print
};

struct Instruction {
  OpCode op = OpCode::Nop;
  std::uint32_t a = 0;  // Assign/Set*: target ref; Jump*: target instruction; Call/InlineLeaf: procedure;
                        // Generate/Print: first item; Trace: constant; Input: Program::inputs index
  std::uint32_t b = 0;  // Assign/Set*/JumpIfFalse/LoopIfFalse/Trace: expression node; Generate/Print: item count;
                        // Call: first arg; InlineLeaf: the instruction after the procedure's copied body,
                        // which follows it (compile/inline_calls.cpp)
  std::uint32_t c = 0;  // LoopIfFalse: exit target; Call: argument count
  SourcePos pos;
};

struct Procedure {
  std::string name;  // "@line", as written in the header
  SourcePos pos;
  std::uint32_t first = 0;  // instructions [first, end)
  std::uint32_t end = 0;
  std::uint32_t parameter_count = 0;
  std::vector<LocalVariable> locals;
  std::uint32_t frame_size = 0;
  bool defined = true;  // false: referenced by `call` only (error reported at load time)
  bool called = false;  // a `call` statement names it
};

// An `input` statement. Runs are not interactive: the host's answers are matched by the name of
// the target variable; without one the variable keeps its value.
struct InputStatement {
  std::uint32_t prompt = 0;    // GenItem that renders the prompt
  std::uint32_t target = 0;    // VarRef
  std::string name;            // the target variable as written
  std::optional<Type> type;    // nullopt: an implicit host variable, typed at run time
  SourcePos pos;
};

// Slots of the system variables the generator and the block numbering use directly.
struct SystemSlots {
  std::uint32_t skipline, blknum, blknum_delta, blknum_max, blknum_exist, blknum_gen, blknum_letter, blknum_f,
      integer_def_f, numeric_def_f, remove_blanks, end_block_text, gcode_space, clear_change_after_gen;
  std::uint32_t gcode;  // variable id (gcode_space pads groups that print it)
};

// GPPL names are case-insensitive: both halves compare them in lower case (ASCII only, the
// rest of an 8-bit name is kept as it is).
std::string lower(std::string_view s);

}  // namespace gppl

namespace gppl {

class Program {
public:
  std::vector<std::string> files;
  std::vector<GlobalVariable> globals;
  std::uint32_t global_cells = 0;
  std::vector<Procedure> procedures;
  std::vector<Instruction> code;
  std::vector<Node> nodes;
  std::vector<Relation> relations;
  std::vector<VarRef> refs;
  std::vector<std::uint32_t> lists;  // index/argument node lists, group requirement refs
  std::vector<GenItem> items;
  std::vector<Value> constants;
  std::vector<std::string> format_specs;  // constant display formats (parsed per interpreter)
  std::vector<InputStatement> inputs;
  std::uint32_t format_sites = 0;
  std::optional<std::uint32_t> init_post;
  std::vector<std::uint32_t> init_inc;  // one per file that defines it, in inclusion order
  SystemSlots slots{};
  bool uses_line_functions = false;  // start_line/end_line appear: the sink's structure hooks are called
  std::vector<std::string> warnings;
  std::vector<Error> warning_details;  // the same, with positions
  // Per ref with indices == kUndeclared: where the name stands and the error a use of it is
  // before the host has assigned it (383 read, 404 assigned), the diagnostic `check` gives.
  struct Undeclared {
    SourcePos pos;
    std::uint32_t error = 0;
  };
  std::unordered_map<std::uint32_t, Undeclared> undeclared;

  std::unordered_map<std::string, std::uint32_t> global_index;     // lower-case name -> globals
  std::unordered_map<std::string, std::uint32_t> procedure_index;  // lower-case "@name" -> procedures

  Position position(SourcePos p) const {
    return Position{p.file < files.size() ? files[p.file] : std::string(), int(p.line), int(p.column)};
  }
};

// ASCII case-insensitive comparison for names.
bool same_name(std::string_view a, std::string_view b);

}  // namespace gppl
