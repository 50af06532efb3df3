// The command-parameter table and the enumeration constants.
#include <gtest/gtest.h>

#include <algorithm>

#include "gppl/compile/system_variables.hpp"
#include "postproc/engine/enumerations.hpp"
#include "postproc/engine/parameter_table.hpp"
#include "toolpath/value.hpp"

namespace {

using postproc::ParameterKind;

TEST(ParameterTable, TypesOfDocumentedParameters) {
  struct Case {
    const char* name;
    ParameterKind kind;
  } cases[] = {
      {"xpos", ParameterKind::Numeric},        {"XPOS", ParameterKind::Numeric},
      {"feed", ParameterKind::Numeric},        {"label", ParameterKind::Integer},
      {"message", ParameterKind::String},      {"first_drill", ParameterKind::Logical},
      {"arc_direction", ParameterKind::Enum},  {"side", ParameterKind::Enum},
      {"drill_type", ParameterKind::Integer},  {"safety", ParameterKind::Numeric},
      {"xtonext", ParameterKind::Numeric},     {"tmatrix_I_16", ParameterKind::Numeric},
      {"g_file_name", ParameterKind::String},  {"next_command", ParameterKind::String},
      {"semi_finish", ParameterKind::Logical}, {"drill_upper_zto", ParameterKind::Numeric},
  };
  for (const auto& c : cases) {
    const auto* p = postproc::find_parameter(c.name);
    ASSERT_NE(p, nullptr) << c.name;
    EXPECT_EQ(p->kind, c.kind) << c.name;
  }
  EXPECT_EQ(postproc::find_parameter("no_such_parameter"), nullptr);
  EXPECT_EQ(postproc::find_parameter("start_line"), nullptr) << "a function, not a variable";
}

// The system-variable table decides a name's type; the catalogue's kinds must agree with it (an
// enumeration parameter holds an integer code).
TEST(ParameterTable, AgreesWithTheSystemVariableTable) {
  for (const auto& p : postproc::parameter_table()) {
    const gppl::SystemVariable* v = gppl::find_system_variable(p.name);
    ASSERT_NE(v, nullptr) << p.name;
    const gppl::Type expected = p.kind == ParameterKind::Integer || p.kind == ParameterKind::Enum ? gppl::Type::Integer
                                : p.kind == ParameterKind::Numeric                               ? gppl::Type::Numeric
                                : p.kind == ParameterKind::Logical                               ? gppl::Type::Logical
                                                                                                  : gppl::Type::String;
    EXPECT_EQ(v->type, expected) << p.name;
  }
}

TEST(ParameterTable, IsSortedAndHasNoDuplicates) {
  auto table = postproc::parameter_table();
  EXPECT_GT(table.size(), 400u);
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(postproc::find_parameter(table[i].name), &table[i]) << table[i].name;
    if (i > 0) {
      EXPECT_FALSE(toolpath::iequals(table[i - 1].name, table[i].name)) << table[i].name;
    }
  }
}

TEST(Enumerations, CodesAreStableAndCaseInsensitive) {
  postproc::Enumerations e({"Drilling", "G84_2", "Peck"});
  EXPECT_EQ(e.code("CW"), 1);
  EXPECT_EQ(e.code("ccw"), 2);
  EXPECT_EQ(e.code("milling"), 0);
  EXPECT_EQ(e.code("turning"), 1);
  EXPECT_EQ(e.code("xy"), e.code("XY"));
  EXPECT_EQ(e.code("COMP_OFF"), 3);
  // The machine's cycles count from 0, as SolidCAM's traces do (`drill_type:0` is the first cycle).
  EXPECT_EQ(e.code("drilling"), 0);
  EXPECT_EQ(e.code("g84_2"), 1);
  EXPECT_EQ(e.code("peck"), 2);
  EXPECT_EQ(e.code("F_Drill"), 3) << "internal cycle types follow the PRP's own names";
  // Real SolidCAM traces: `flood_coolant:on` is 1 (posts test `eq 1`), `off` 0, `no_action` 2;
  // `msr_len:no` 0, `MCO_New_Line:yes` 1. Codes only, not constants a post could collide with.
  EXPECT_EQ(e.code("on"), 1);
  EXPECT_EQ(e.code("OFF"), 0);
  EXPECT_EQ(e.code("no_action"), 2);
  EXPECT_EQ(e.code("no"), 0);
  EXPECT_EQ(e.code("yes"), 1);
  auto unknown = e.code("salamat");
  EXPECT_GE(unknown, 1000);
  EXPECT_EQ(e.code("SALAMAT"), unknown);
  EXPECT_NE(e.code("other_word"), unknown);
  const auto& all = e.constants();
  EXPECT_TRUE(std::any_of(all.begin(), all.end(), [](const auto& c) { return c.name == "G84_2" && c.code == 1; }));
  EXPECT_EQ(std::count_if(all.begin(), all.end(), [](const auto& c) { return toolpath::iequals(c.name, "XY"); }), 1);
  EXPECT_TRUE(std::none_of(all.begin(), all.end(), [](const auto& c) { return toolpath::iequals(c.name, "on"); }));
}

}  // namespace

#include <sstream>

#include "postproc/engine/command_names.hpp"
#include "tests/support/rendered_doc.hpp"

namespace {

std::string_view kind_name(ParameterKind k) {
  switch (k) {
    case ParameterKind::Integer: return "integer";
    case ParameterKind::Numeric: return "numeric";
    case ParameterKind::Logical: return "logical";
    case ParameterKind::String: return "string";
    case ParameterKind::Enum: return "word";
  }
  return "?";
}

// docs/commands.md: every command a job may send, with the parameters the engine's table gives it.
std::string render_commands() {
  std::ostringstream md;
  md << "# Toolpath commands\n\n"
        "Every command a job may send to a post, with the parameters it carries and their types, as the\n"
        "engine knows them (`postproc/engine/command_names.cpp`, `postproc/engine/parameter_table*.cpp`;\n"
        "`tests/postproc/engine/tables_test.cpp` renders this page from them and fails when it differs:\n"
        "rerun it with `POSTPROC_UPDATE_DOCS=1`). A `word` parameter holds an enumeration word (`CW`,\n"
        "`COMP_LEFT`) that GPPL compares as an integer code ([engine.md](engine.md#enumeration-constants)).\n"
        "A post receives every parameter a command carries, listed here or not: a trace may carry more\n"
        "([system-variables.md](system-variables.md) lists every name SolidCAM defines).\n\n"
        "What happens when the post has no procedure for a command ([engine.md](engine.md#every-command)):\n"
        "**stop** (the run stops: moves would be lost), **quiet** (the command only informs), or a warning.\n\n"
        "| command | without a procedure | parameters |\n|---|---|---|\n";
  std::vector<std::string_view> names(postproc::stream_command_names().begin(), postproc::stream_command_names().end());
  std::sort(names.begin(), names.end());
  for (std::string_view command : names) {
    std::string params;
    for (const auto& p : postproc::parameter_table()) {
      std::istringstream carriers{std::string(p.commands)};
      for (std::string c; carriers >> c;)
        if (toolpath::iequals(c, command)) {
          params += (params.empty() ? "" : ", ") + std::string("`") + std::string(p.name) + "` " +
                    std::string(kind_name(p.kind));
          break;
        }
    }
    const char* missing = postproc::is_basic_motion(command)      ? "stop"
                          : postproc::is_informational(command) ? "quiet"
                                                                : "warning";
    md << "| `" << command << "` | " << missing << " | " << (params.empty() ? "(none listed)" : params) << " |\n";
  }
  return md.str();
}

TEST(CommandReference, PageIsTheTables) {
  test_support::expect_page_is_rendered("../docs/commands.md", render_commands(), "the engine's tables");
}

}  // namespace
