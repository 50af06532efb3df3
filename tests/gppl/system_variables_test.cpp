// The system-variable table (gppl/compile/system_variables.inc): it covers SolidCAM's whole list, every
// name compiles where a post prints it, and docs/system-variables.md is the table rendered.
// POSTPROC_UPDATE_DOCS=1 rewrites the doc from the table instead of comparing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "gppl/gppl.hpp"
#include "gppl/compile/system_variables.hpp"
#include "tests/support/rendered_doc.hpp"

namespace {

std::string folded(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::vector<std::string> listed_names() {
  std::ifstream in("gppl/data/solidcam-system-variables.txt");
  std::vector<std::string> names;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') names.push_back(line);
  return names;
}

TEST(SystemVariables, CoverSolidCamsList) {
  const auto names = listed_names();
  ASSERT_EQ(names.size(), 1629u);
  for (const auto& n : names) EXPECT_NE(gppl::find_system_variable(n), nullptr) << n;
  std::set<std::string> seen;
  for (const auto& v : gppl::system_variables()) EXPECT_TRUE(seen.insert(folded(v.name)).second) << v.name;
  EXPECT_EQ(gppl::job_type_values().size(), 61u);
}

// A post that prints every listed name compiles with every name required to be declared (the
// strictness of `postproc check`). start_line/end_line are generate items, printed as such.
TEST(SystemVariables, EveryListedNamePrints) {
  std::string post = "@start_of_file\n";
  for (const auto& n : listed_names()) {
    const gppl::SystemVariable* v = gppl::find_system_variable(n);
    ASSERT_NE(v, nullptr) << n;
    std::string item = n;
    if (v->rows > 0) item += v->columns > 0 ? "<<1,1>>" : "<<1>>";
    post += "{nb, " + item + "}\n";
  }
  post += "endp\n";
  gppl::CompileOptions strict;
  strict.implicit_host_variables = false;
  try {
    auto program = gppl::compile_source(post, "every.gpp", strict);
    EXPECT_TRUE(gppl::warnings(*program).empty());
  } catch (const gppl::Errors& e) {
    ADD_FAILURE() << e.all().size() << " errors, first: " << e.all().front().what();
  }
}

TEST(SystemVariables, Defaults) {
  struct Case {
    const char* name;
    gppl::Value value;
  } cases[] = {
      {"blknum_letter", gppl::Value::of_string("N")},   {"blknum_max", gppl::Value::of_integer(32000)},
      {"skipline", gppl::Value::of_logical(true)},      {"xpos", gppl::Value::of_numeric(0)},
      {"part_name", gppl::Value::of_string("")},        {"pocket", gppl::Value::of_string("pocket")},
      {"line_labels", gppl::Value::of_logical(false)},  {"tool_user_type", gppl::Value::of_string("")},
  };
  for (const auto& c : cases) {
    const gppl::SystemVariable* v = gppl::find_system_variable(c.name);
    ASSERT_NE(v, nullptr) << c.name;
    EXPECT_EQ(gppl::default_value(*v), c.value) << c.name;
  }
  const auto* chng_cond = gppl::find_system_variable("CHNG_COND");
  ASSERT_NE(chng_cond, nullptr);
  EXPECT_EQ(chng_cond->type, gppl::Type::String);
  EXPECT_EQ(chng_cond->rows, 3);
}

std::string cell_text(std::string_view s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

// The reference page: the fixed text below, then one row per name, sorted without case.
std::string render_reference() {
  std::ostringstream md;
  md << "# System variables\n\n"
        "Every name SolidCAM predefines for a post (1,629 names, from the completion list of its GPPL\n"
        "editor), the command parameters of the GPPTool catalogue the list leaves out, and `PI`, `TRUE`,\n"
        "`FALSE`. A post uses any of them without declaring it. This page is generated from\n"
        "`gppl/compile/system_variables.inc` by `tests/gppl/system_variables_test.cpp` (run it with\n"
        "`POSTPROC_UPDATE_DOCS=1` after editing the table); the test fails when the two differ.\n\n"
        "Columns:\n\n"
        "* **type**: `integer`, `numeric`, `logical` or `string`; an array shows its sizes (`string<<3,100>>`).\n"
        "* **assign**: `yes` when a post may assign it; `no` is error 402.\n"
        "* **default**: the value before anything sets it (empty: `''`, `0` or `FALSE`).\n"
        "* **source**: `trace` (a command of the job sets it), `machine` (the PRP/VMID; SolidCAM writes\n"
        "  it into the trace), `post` (the post sets it, usually in `@init_post`), `run` (the engine fills\n"
        "  it: `part_name`, `pre_processor`, ...; a value in the trace still wins), `constant`.\n"
        "* **basis**: what the type rests on. `manual` and `catalogue` (gpptool-commands) are documented;\n"
        "  the others are **inferred**: `usage` (how public posts use it: compared with text, a number or\n"
        "  TRUE/FALSE), `observed` (its value in a real SolidCAM trace), `naming` (`msg_*`, `*_name`: text; `is_*`, `*_exist`, `use_*`, `module_*`:\n"
        "  logical; `*_number`, `*_id`, `num_*`: integer), `guess` (numeric, the common case). An inferred\n"
        "  type of a `trace` or `machine` scalar is only its default's: the job's first value types it\n"
        "  (a trace that sends text where the table guessed a number is right, and no error).\n\n"
        "Names that are job-type words in SolidCAM's list (`pocket`, `hsm_raster`, ...) are read-only\n"
        "strings holding their own name, so `job_type eq pocket` and `job_type eq 'pocket'` agree.\n"
        "Tool-type words (`end_mill`, `face_mill`, ...) arrive in the trace as words (`tool_type:face_mill`):\n"
        "they are read-only integers holding the code the engine gives that word, like the enumeration\n"
        "constants, so `tool_type eq face_mill` compares codes. `profile` stays the enumeration constant\n"
        "`PROFILE`.\n"
        "`start_line` and `end_line` are generate items, not variables (docs/gppl-language.md).\n\n"
        "| name | type | assign | default | source | basis | meaning |\n"
        "|---|---|---|---|---|---|---|\n";
  std::vector<const gppl::SystemVariable*> rows;
  for (const auto& v : gppl::system_variables()) rows.push_back(&v);
  std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return folded(a->name) < folded(b->name); });
  for (const auto* v : rows) {
    std::string type(gppl::name_of(v->type));
    if (v->rows > 0) type += "<<" + std::to_string(v->rows) + (v->columns > 0 ? "," + std::to_string(v->columns) : "") + ">>";
    md << "| `" << v->name << "` | " << type << " | " << (v->read_only ? "no" : "yes") << " | "
       << (v->default_text.empty() ? "" : (v->type == gppl::Type::String ? "'" + cell_text(v->default_text) + "'"
                                                                          : std::string(v->default_text)))
       << " | " << gppl::name_of(v->source) << " | " << gppl::name_of(v->basis) << " | " << cell_text(v->meaning)
       << " |\n";
  }
  md << "\n## Job-type values\n\n"
        "The values `job_type` takes that SolidCAM's list names (text, compared as `job_type eq '3-d drill'`):\n\n";
  bool first = true;
  for (auto value : gppl::job_type_values()) md << (first ? "" : ", ") << "`" << value << "`", first = false;
  md << ".\n";
  return md.str();
}

TEST(SystemVariables, ReferencePageIsTheTable) {
  test_support::expect_page_is_rendered("../docs/system-variables.md", render_reference(),
                                        "gppl/compile/system_variables.inc");
}

}  // namespace
