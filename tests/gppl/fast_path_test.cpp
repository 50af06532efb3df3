// The interpreter's fast paths give exactly what the general paths give: tests that read their
// operands in place (`if x gt 5`, `if flag`, `if change(x)`), assignments of a constant or a scalar,
// and the host's typed assignments (assign_numeric, ...) against assign() with a Value.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <string_view>

#include "support.hpp"

using namespace gppl_test;

namespace {

const char* const kRelations[] = {"eq", "ne", "lt", "le", "gt", "ge"};

struct OperandPair {
  gppl::Value a, b;
};

class FastRelation : public testing::TestWithParam<OperandPair> {};

// `if a OP b` (operands read in place) against `e = a OP b` (evaluated by the general path), for
// two variables and for a variable against a constant of the other's type.
TEST_P(FastRelation, AgreesWithEvaluatedRelation) {
  const OperandPair& p = GetParam();
  // e2: the left side made an expression (`a + 0`, `a + ''`), so no fast path can take it.
  const std::string evaluated_a = p.a.type == gppl::Type::String ? "(a + '')" : "(a + 0)";
  for (const char* op : kRelations) {
    std::string source = "@t\n  r = FALSE\n  if a " + std::string(op) + " b\n    r = TRUE\n  endif\n  e = a " + op +
                         " b\n  e2 = " + evaluated_a + " " + op + " b\nendp\n";
    Post post(source);
    post.set("a", p.a);
    post.set("b", p.b);
    post.call("@t");
    EXPECT_EQ(post.get("r"), post.get("e")) << source;
    EXPECT_EQ(post.get("r"), post.get("e2")) << source;
  }
}

// Expected truth of `a OP b` for the pairs below, written out: eq ne lt le gt ge.
struct ConstantCase {
  const char* test;
  gppl::Value a;
  bool truth[6];
};

class FastConstantRelation : public testing::TestWithParam<ConstantCase> {};

TEST_P(FastConstantRelation, ExactResults) {
  const ConstantCase& c = GetParam();
  for (int i = 0; i < 6; ++i) {
    std::string expression = c.test;
    expression.replace(expression.find("OP"), 2, kRelations[i]);
    Post post("@t\n  r = FALSE\n  if " + expression + "\n    r = TRUE\n  endif\nendp\n");
    post.set("a", c.a);
    post.call("@t");
    EXPECT_EQ(post.get("r"), logical(c.truth[i])) << expression;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Pairs, FastRelation,
    testing::Values(OperandPair{integer(3), integer(3)}, OperandPair{integer(3), integer(4)},
                    OperandPair{integer(4), integer(-3)}, OperandPair{integer(3), numeric(3.0)},
                    OperandPair{integer(3), numeric(3.5)}, OperandPair{numeric(2.5), integer(2)},
                    OperandPair{numeric(-0.0), numeric(0.0)}, OperandPair{numeric(1e-12), numeric(0.0)},
                    OperandPair{logical(true), integer(1)}, OperandPair{logical(false), numeric(0.0)},
                    OperandPair{logical(true), logical(false)}, OperandPair{numeric(0.5), logical(true)},
                    OperandPair{string("abc"), string("abd")}, OperandPair{string("b"), string("b")}));

INSTANTIATE_TEST_SUITE_P(
    Constants, FastConstantRelation,
    testing::Values(ConstantCase{"a OP 99990", integer(99990), {true, false, false, true, false, true}},
                    ConstantCase{"a OP 99990", integer(99991), {false, true, false, false, true, true}},
                    ConstantCase{"a OP 360", numeric(359.9999), {false, true, true, true, false, false}},
                    ConstantCase{"a OP 180.0", integer(180), {true, false, false, true, false, true}},
                    ConstantCase{"a OP TRUE", logical(true), {true, false, false, true, false, true}},
                    ConstantCase{"a OP TRUE", integer(0), {false, true, true, true, false, false}},
                    ConstantCase{"2.5 OP a", integer(2), {false, true, false, false, true, true}},
                    ConstantCase{"'x' OP a", string("y"), {false, true, true, true, false, false}}));

// The compiled comparisons (Program::relations) read locals from the running frame and declared
// globals from their cells: `if a OP b` against the evaluated `(a + 0) OP b`, a procedure called
// from another so that the frame does not start at the bottom of the stack.
TEST(FastCondition, LocalAndDeclaredOperands) {
  const std::vector<std::pair<const char*, const char*>> typed = {
      {"integer", "3"}, {"integer", "-2"}, {"numeric", "2.5"}, {"numeric", "3.0"}, {"logical", "TRUE"}};
  for (const auto& [type_a, value_a] : typed) {
    for (const auto& [type_b, value_b] : typed) {
      for (const char* op : kRelations) {
        for (const char* right : {"b", "g", "3", "2.5", "TRUE"}) {
          const std::string source = std::string("@init_post\n  global ") + type_b + " g\nendp\n@inner\n  local integer pad\n  local " +
                                     type_a + " a\n  local " + type_b + " b\n  pad = 7\n  a = " + value_a + "\n  b = " +
                                     value_b + "\n  g = " + value_b + "\n  r = FALSE\n  if a " + op + " " + right +
                                     "\n    r = TRUE\n  endif\n  e = (a + 0) " + op + " " + right + "\nendp\n"
                                     "@t\n  local numeric outer\n  outer = 1\n  call @inner\nendp\n";
          Post post(source);
          post.call("@init_post");
          post.call("@t");
          EXPECT_EQ(post.get("r"), post.get("e")) << source;
        }
      }
    }
  }
}

// and/or/not in a condition test their operands as conditions (no scratch value): the same truth
// and the same short-circuit as the evaluated expression, and the same error for a text operand.
TEST(FastCondition, AndOrNot) {
  const char* const values[] = {"TRUE", "FALSE", "0", "2", "0.5"};
  for (const char* form : {"a and b", "a or b", "not a", "not (a and b)", "a or not b and a", "(a or b) and not (a and b)"}) {
    for (const char* a : values) {
      for (const char* b : values) {
        const std::string source = std::string("@t\n  a = ") + a + "\n  b = " + b + "\n  r = FALSE\n  if " + form +
                                   "\n    r = TRUE\n  endif\n  e = " + form + "\nendp\n";
        Post post(source);
        post.call("@t");
        EXPECT_EQ(post.get("r"), post.get("e")) << source;
      }
    }
  }
  EXPECT_EQ(run_error("@t\n  global string s\n  if s or TRUE\n  endif\nendp\n"),
            run_error("@t\n  global string s\n  e = s or TRUE\nendp\n"));
  Post short_circuit("@t\n  global string s\n  r = 0\n  if TRUE or s\n    r = 1\n  endif\n  if FALSE and s\n    r = 2\n  endif\nendp\n");
  short_circuit.call("@t");
  EXPECT_EQ(short_circuit.get("r"), integer(1));
}

TEST(FastCondition, PlainLogicalVariable) {
  const std::string source = "@t\n  r = 0\n  if flag\n    r = 1\n  endif\nendp\n";
  for (const auto& [value, expected] :
       std::vector<std::pair<gppl::Value, std::int64_t>>{{logical(true), 1}, {logical(false), 0}, {integer(1), 1},
                                                        {integer(0), 0}, {numeric(1.0), 1}, {numeric(0.0), 0}}) {
    Post post(source);
    post.set("flag", value);
    post.call("@t");
    EXPECT_EQ(post.get("r"), integer(expected));
  }
  // Not 0 or 1: TRUE, as an evaluated condition says.
  for (const char* test : {"g", "(g + 0)"}) {
    Post post(std::string("@t\n  global integer g\n  g = 2\n  r = 0\n  if ") + test + "\n    r = 1\n  endif\nendp\n");
    post.set("r", integer(0));
    post.call("@t");
    EXPECT_EQ(post.get("r"), integer(1)) << test;
  }
  EXPECT_EQ(run_error("@t\n  global string s\n  if s\n  endif\nendp\n"),
            run_error("@t\n  global string s\n  if s + ''\n  endif\nendp\n"));
}

TEST(FastCondition, Attributes) {
  Post post(
      "@t\n  global integer g\n  g = 1\n  c1 = change(g)\n  if change(g)\n    r1 = 1\n  endif\n  g = 1\n"
      "  if change(g)\n    r2 = 1\n  endif\n  active(g) = FALSE\n  if active(g)\n    r3 = 1\n  endif\n"
      "  if not active(g)\n    r4 = 1\n  endif\nendp\n");
  post.set("r1", integer(0));
  post.set("r2", integer(0));
  post.set("r3", integer(0));
  post.set("r4", integer(0));
  post.call("@t");
  EXPECT_EQ(post.get("c1"), logical(true));
  EXPECT_EQ(post.get("r1"), integer(1));
  EXPECT_EQ(post.get("r2"), integer(0));
  EXPECT_EQ(post.get("r3"), integer(0));
  EXPECT_EQ(post.get("r4"), integer(1));
}

// Assigning a constant or a plain variable (no copy) follows the conversion table and the change rule.
TEST(FastAssign, ConstantsAndScalars) {
  Post post(
      "@t\n  global integer i\n  global numeric n\n  global logical l\n  global string s\n"
      "  i = 2.9999999999\n  n = 3\n  l = 1\n  s = 'ab'\n  s = s\n  ci = change(i)\n  cs = change(s)\n"
      "  n = i\n  cn = change(n)\n  n = i\n  cn2 = change(n)\n  i = l\n  t = s\nendp\n");
  post.call("@t");
  EXPECT_EQ(post.get("i"), integer(1));
  EXPECT_EQ(post.get("n"), numeric(3.0));
  EXPECT_EQ(post.get("l"), logical(true));
  EXPECT_EQ(post.get("s"), string("ab"));
  EXPECT_EQ(post.get("t"), string("ab"));
  EXPECT_EQ(post.get("ci"), logical(true));
  EXPECT_EQ(post.get("cs"), logical(false));  // s = s assigns the same text: no change
  EXPECT_EQ(post.get("cn"), logical(false));  // 3 into 3.0: same value
  EXPECT_EQ(post.get("cn2"), logical(false));
  EXPECT_EQ(run_error("@t\n  global integer i\n  global string s\n  i = s\nendp\n"),
            run_error("@t\n  global integer i\n  global string s\n  i = s + ''\nendp\n"));
  EXPECT_EQ(run_error("@t\n  global integer i\n  i = 1.0E10\nendp\n"),
            run_error("@t\n  global integer i\n  i = 1.0E10 + 0\nendp\n"));
  EXPECT_NE(run_error("@t\n  global integer i\n  i = 1.0E10\nendp\n").find("error 410"), std::string::npos);
}

// `change(x) = value` and `active(x) = value` with a constant or a plain variable (read in place)
// store what the evaluated form (`value + 0`) stores, and refuse what it refuses.
TEST(FastAttributeAssign, SameAsEvaluated) {
  const char* const values[] = {"TRUE", "FALSE", "1", "0", "1.0", "0.0", "one", "zero", "flag"};
  for (const char* attribute : {"change", "active"}) {
    for (const char* value : values) {
      const std::string evaluated = std::string(value) == "flag" ? "(flag and TRUE)" : std::string("(") + value + " + 0)";
      const std::string head = "@t\n  global integer g\n  global integer one\n  global numeric zero\n"
                               "  global logical flag\n  one = 1\n  zero = 0.0\n  flag = TRUE\n  g = 5\n  ";
      Post in_place(head + attribute + "(g) = " + value + "\n  r = " + attribute + "(g)\nendp\n");
      Post evaluated_post(head + attribute + "(g) = " + evaluated + "\n  r = " + attribute + "(g)\nendp\n");
      in_place.call("@t");
      evaluated_post.call("@t");
      EXPECT_EQ(in_place.get("r"), evaluated_post.get("r")) << attribute << " = " << value;
    }
    for (const char* refused : {"2", "0.5", "'TRUE'"}) {
      const std::string source = std::string("@t\n  global integer g\n  ") + attribute + "(g) = " + refused + "\nendp\n";
      const std::string evaluated =
          std::string("@t\n  global integer g\n  ") + attribute + "(g) = (" + refused + " + " +
          (refused[0] == '\'' ? "''" : "0") + ")\nendp\n";
      EXPECT_NE(run_error(source), "no error") << source;
      EXPECT_EQ(run_error(source).substr(run_error(source).find(':')), run_error(evaluated).substr(run_error(evaluated).find(':')))
          << source;
    }
  }
}

// The host's typed assignments (by id, and by HostSlot) against assign() with a Value: same value,
// change and active, and the same errors, whatever the variable's type (declared, implicit,
// untyped, added by the host).
struct HostStep {
  gppl::Value value;
  gppl::ChangeOverride change;
};

std::string describe(const gppl::Interpreter& run, gppl::VariableId id) {
  const gppl::Value& v = run.value(id);
  return std::to_string(int(v.type)) + "/" + std::to_string(v.integer) + "/" + std::to_string(v.numeric) + "/" +
         std::to_string(v.logical) + "/" + v.text + " changed=" + std::to_string(run.changed(id)) +
         " active=" + std::to_string(run.active(id));
}

// With `slot`, integers and numbers go through the variable's HostSlot.
void typed_assign(gppl::Interpreter& run, gppl::VariableId id, const gppl::Value& v, gppl::ChangeOverride change,
                  bool slot = false) {
  switch (v.type) {
    case gppl::Type::Integer:
      return slot ? run.assign_integer(run.host_slot(id), v.integer, change) : run.assign_integer(id, v.integer, change);
    case gppl::Type::Numeric:
      return slot ? run.assign_numeric(run.host_slot(id), v.numeric, change) : run.assign_numeric(id, v.numeric, change);
    case gppl::Type::Logical: return run.assign_logical(id, v.logical, change);
    case gppl::Type::String: return run.assign_string(id, v.text, change);
  }
}

TEST(FastHostAssign, SameAsValueAssignment) {
  const std::string source =
      "@init_post\n  global integer gi\n  global numeric gn\n  global logical gl\n  global string gs\nendp\n"
      "@t\n  x = implicit\nendp\n";
  const std::vector<HostStep> steps = {
      {numeric(1.5), gppl::ChangeOverride::Compute},        {numeric(1.5), gppl::ChangeOverride::Compute},
      {numeric(1.5), gppl::ChangeOverride::ForceChanged},   {numeric(2.5), gppl::ChangeOverride::ForceUnchanged},
      {integer(3), gppl::ChangeOverride::Compute},          {integer(3), gppl::ChangeOverride::Compute},
      {logical(true), gppl::ChangeOverride::Compute},       {logical(true), gppl::ChangeOverride::Compute},
      {integer(1), gppl::ChangeOverride::Compute},          {numeric(0.0), gppl::ChangeOverride::Compute},
      {string("CCW"), gppl::ChangeOverride::Compute},       {string("CCW"), gppl::ChangeOverride::Compute},
      {string("a longer text than fits in place"), gppl::ChangeOverride::Compute},
      {numeric(2.0), gppl::ChangeOverride::Compute},        {numeric(1e12), gppl::ChangeOverride::Compute},
      {integer(7), gppl::ChangeOverride::ForceChanged}};
  for (bool slot : {false, true}) {
    for (const char* variable : {"gi", "gn", "gl", "gs", "implicit", "added_by_host"}) {
      Post by_value(source), typed(source);
      by_value.run->start();
      typed.run->start();
      const gppl::VariableId a = by_value.run->add_variable(variable), b = typed.run->add_variable(variable);
      ASSERT_EQ(a, b);
      for (std::size_t i = 0; i < steps.size(); ++i) {
        std::string error_a, error_b;
        try {
          by_value.run->assign(a, steps[i].value, steps[i].change);
        } catch (const gppl::Error& e) {
          error_a = std::to_string(e.number()) + " " + e.text();
        }
        try {
          typed_assign(*typed.run, b, steps[i].value, steps[i].change, slot);
        } catch (const gppl::Error& e) {
          error_b = std::to_string(e.number()) + " " + e.text();
        }
        EXPECT_EQ(error_a, error_b) << variable << " step " << i << (slot ? " (slot)" : "");
        EXPECT_EQ(describe(*by_value.run, a), describe(*typed.run, b)) << variable << " step " << i << (slot ? " (slot)" : "");
      }
    }
  }
}

// assign_strings() (the engine's prev/current/next_command) against one assign_string() each: same
// texts, change and active attributes, across repeats, changes and a reset of the change memory.
TEST(FastHostAssign, StringsInOneCallAsOneByOne) {
  const std::string source =
      "@init_post\n  global string p\n  global string c\n  global string n\nendp\n"
      "@t\n  x = implicit\nendp\n";
  const std::vector<std::array<std::string, 3>> steps = {
      {"", "@start_of_file", "@line"}, {"@start_of_file", "@line", "@arc"}, {"@line", "@arc", "@line"},
      {"@arc", "@line", "@line"},      {"@line", "@line", "@line"},         {"@line", "@line", "@change_tool"},
      {"@line", "@change_tool", ""},   {"@change_tool", "", "a name longer than sixteen bytes"},
      {"", "a name longer than sixteen bytes", "a name longer than sixteen bytes"}};
  for (const char* last : {"n", "implicit", "added_by_host"}) {
    Post one_by_one(source), together(source);
    one_by_one.run->start();
    together.run->start();
    std::array<gppl::VariableId, 3> ids{};
    for (std::size_t k = 0; k < 3; ++k) {
      const char* name = k == 0 ? "p" : k == 1 ? "c" : last;
      ids[k] = one_by_one.run->add_variable(name);
      ASSERT_EQ(ids[k], together.run->add_variable(name));
    }
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (i == 4) {
        one_by_one.run->reset_change_memory();
        together.run->reset_change_memory();
      }
      const std::array<std::string_view, 3> texts{steps[i][0], steps[i][1], steps[i][2]};
      for (std::size_t k = 0; k < 3; ++k) one_by_one.run->assign_string(ids[k], texts[k]);
      together.run->assign_strings(ids, texts);
      for (std::size_t k = 0; k < 3; ++k)
        EXPECT_EQ(describe(*one_by_one.run, ids[k]), describe(*together.run, ids[k])) << last << " step " << i << " " << k;
    }
  }
}

}  // namespace
