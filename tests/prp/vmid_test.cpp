// SolidCAM machine ID files (VMID) read into the PRP model: the mapping table, user parameters of
// every ValueType, drill cycles, precision and arc settings, skipped elements, and the positions of
// errors (malformed XML, a bad value).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "prp/params/catalogue.hpp"
#include "prp/prp.hpp"
#include "prp/params/vmid_map.hpp"

using prp::Units;

namespace {

std::string load_error(const std::string& text) {
  try {
    prp::load_source(text, "m.vmid", Units::Metric);
  } catch (const prp::LoadError& e) {
    return e.what();
  }
  return "no error";
}

std::vector<std::string> warnings(const prp::MachineParameters& p) {
  std::vector<std::string> out;
  for (const auto& w : p.warnings()) out.push_back(w.text());
  return out;
}

const prp::ExternalVariable* external(const prp::MachineParameters& p, std::string_view name) {
  for (const auto& v : p.external_variables())
    if (v.name == name) return &v;
  return nullptr;
}

TEST(VmidMap, EveryAttributeNamesADocumentedKeyOfItsKind) {
  for (const auto& m : prp::vmid_attributes()) {
    const prp::KeyInfo* info = prp::find_key(m.key);
    ASSERT_NE(info, nullptr) << m.element << "/" << m.attribute;
    EXPECT_EQ(info->kind, prp::vmid_kind(m.value)) << m.element << "/" << m.attribute;
  }
}

TEST(Vmid, ControllerSettingsBecomePrpParameters) {
  auto p = prp::load_file("prp/data/mill-4x.vmid", Units::Metric);
  EXPECT_TRUE(warnings(p).empty()) << warnings(p).front();
  EXPECT_EQ(p.text("post_processor"), "mill4x_fanuc");
  // <PrecisionDef>
  EXPECT_DOUBLE_EQ(p.numeric("movement_precision"), 4);
  EXPECT_EQ(p.integer("feed_precision"), 1);
  EXPECT_EQ(p.integer("spin_precision"), 0);
  // <ArcExecution>
  EXPECT_TRUE(p.logical("arc_exist"));
  EXPECT_FALSE(p.logical("arc_3d"));
  EXPECT_FALSE(p.logical("arc_3d_4x"));
  EXPECT_TRUE(p.logical("arc_quadrants"));
  EXPECT_FALSE(p.logical("arc_gt_180"));
  EXPECT_FALSE(p.logical("arc_zx_yz"));
  EXPECT_TRUE(p.logical("arc_in_main_planes"));
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_chord"), 3.81);
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_angle"), 5);
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_radius"), 2540);
  EXPECT_DOUBLE_EQ(p.numeric("arc_min_length"), 0.0254);
  EXPECT_DOUBLE_EQ(p.numeric("eps_angle"), 0.002);
  // the rest of the controller and the working style
  EXPECT_EQ(p.integer("prog_num_min"), 5000);  // not the 77 inside <Components>
  EXPECT_EQ(p.integer("prog_num_max"), 8999);
  EXPECT_EQ(p.integer("prog_num_dflt"), 5000);
  EXPECT_EQ(p.integer("proc_num_max"), 4999);
  EXPECT_TRUE(p.logical("comp_exist"));
  EXPECT_DOUBLE_EQ(p.numeric("min_delt_arc_rad"), 0.01);
  EXPECT_TRUE(p.logical("pos_to_machine"));
  EXPECT_EQ(p.text("doc_processor"), "DOCUMENT");
  EXPECT_EQ(p.integer("Delta_for_TOOL_H"), 50);
  EXPECT_TRUE(p.logical("home_data_at_start"));
  EXPECT_TRUE(p.logical("comp_by_zero_tool"));
  EXPECT_EQ(p.text("gpp_file_ext"), "ngc");
  EXPECT_EQ(p.integer("max_g_name_length"), 128);
  EXPECT_TRUE(p.logical("gcode_part_subfolder"));
  EXPECT_EQ(p.text("gen_procs"), "N");
  EXPECT_FALSE(p.logical("loop_exist"));
  EXPECT_DOUBLE_EQ(p.numeric("time_factor"), 1.2);
  EXPECT_DOUBLE_EQ(p.numeric("block_time"), 0.1);
  // a key the file leaves out keeps the engine default
  EXPECT_FALSE(p.has("arc_5x"));
  EXPECT_TRUE(p.logical("arc_5x"));
  // positions name the attribute's value
  ASSERT_NE(p.find("arc_max_chord"), nullptr);
  EXPECT_EQ(p.find("arc_max_chord")->where.line, 24u);
  EXPECT_EQ(p.find("arc_max_chord")->raw, "3.81");
}

TEST(Vmid, LengthsAreMillimetresAndGetAnInchHalf) {
  auto inch = prp::load_file("prp/data/mill-4x.vmid", Units::Inch);
  EXPECT_DOUBLE_EQ(inch.numeric("arc_max_chord"), 0.15);
  EXPECT_DOUBLE_EQ(inch.numeric("arc_max_radius"), 100);
  EXPECT_DOUBLE_EQ(inch.numeric("safety_dist"), 0.1);
  EXPECT_DOUBLE_EQ(inch.numeric("arc_max_angle"), 5);  // angles stay
  EXPECT_DOUBLE_EQ(inch.numeric("eps_angle"), 0.002);
}

TEST(Vmid, UserParametersOfEveryValueType) {
  auto p = prp::load_file("prp/data/mill-4x.vmid", Units::Metric);
  struct Row {
    const char* name;
    prp::VarType type;
    std::optional<toolpath::Value> initial;
    const char* declared_by;
  };
  using V = toolpath::Value;
  const Row rows[] = {
      {"bToolPreselect", prp::VarType::Logical, V::make_logical(true), "options"},             // ValueType 1
      {"sWorkpcDir", prp::VarType::String, V::make_string("C:\\parts"), "options"},            // 2
      {"trace_level", prp::VarType::Numeric, V::make_numeric(2.5), "options"},                 // 3
      {"iCounter", prp::VarType::Integer, V::make_integer(7), "options"},                      // 4, DefaultValue
      {"iNumber_of_Fixtures", prp::VarType::Integer, V::make_integer(3), "options"},           // 5
      {"nUnused", prp::VarType::Numeric, std::nullopt, "options"},                             // IsStateActive 0
      {"bStopM00", prp::VarType::Logical, V::make_logical(false), "job_opt_type"},             // a job list
  };
  for (const Row& row : rows) {
    const prp::ExternalVariable* v = external(p, row.name);
    ASSERT_NE(v, nullptr) << row.name;
    EXPECT_EQ(v->type, row.type) << row.name;
    EXPECT_EQ(v->declared_by, row.declared_by) << row.name;
    ASSERT_EQ(v->initial.has_value(), row.initial.has_value()) << row.name;
    if (row.initial) {
      EXPECT_TRUE(*v->initial == *row.initial) << row.name;
    }
  }
  // Declarations are records too, as `options = name TYPE` would be; bStopM00 once for both job lists.
  EXPECT_EQ(p.records("options").size(), 6u);
  ASSERT_EQ(p.records("job_opt_type").size(), 1u);
  EXPECT_EQ(p.records("job_opt_type")[0]->type, prp::VarType::Logical);
}

// What SolidCAM itself writes into VMIDs (the PoyaKar and Siemens 828D machines of catinrage/achar):
// whole circles allowed, and integer parameters whose whole values carry decimals.
TEST(Vmid, AsSolidCAMWritesThem) {
  auto p = prp::load_source(
      "<Machine><ArcExecutions><ArcExecution SupportArcs=\"1\" MaxArcAngle=\"360\"/></ArcExecutions>\n"
      "<UserDefParams><MachineParams><Param GppName=\"iM8_NumberOfIterations\" ValueType=\"4\" Value=\"\" "
      "DefaultValue=\"3.000000\" IsStateActive=\"1\"/></MachineParams></UserDefParams></Machine>",
      "s.vmid", Units::Metric);
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_angle"), 360);
  const prp::ExternalVariable* v = external(p, "iM8_NumberOfIterations");
  ASSERT_NE(v, nullptr);
  ASSERT_TRUE(v->initial.has_value());
  EXPECT_TRUE(*v->initial == toolpath::Value::make_integer(3));
  EXPECT_EQ(load_error("<Machine><UserDefParams><MachineParams>\n<Param GppName=\"iX\" ValueType=\"4\" "
                       "Value=\"3.500000\"/>\n</MachineParams></UserDefParams></Machine>"),
            "m.vmid:2:42: error: Value=\"3.500000\": expected an integer (ValueType 4)");
}

TEST(Vmid, DrillCyclesBecomeDrillTypeRecords) {
  auto p = prp::load_file("prp/data/mill-4x.vmid", Units::Metric);
  std::vector<std::string> got;
  for (const auto* r : p.records("drill_type")) {
    std::string s = r->name + " " + r->base + " " + (*r->flag ? "Y" : "N");
    for (const auto& param : r->params) s += " " + param;
    got.push_back(s);
  }
  EXPECT_EQ(got, (std::vector<std::string>{"G81 DRILLING Y", "G82 F_DRILL N dwell", "CYCLE83 PECK Y C83_VARI C83_FDEP",
                                           "G86 BORING Y"}));
  ASSERT_NE(p.drill_cycle("cycle83"), nullptr);
  // Cycle parameters wait for the toolpath, as in a PRP (the engine keeps every "drill_type"
  // variable inactive); until then they hold the VMID's Value. Their type follows ValueType.
  const prp::ExternalVariable* vari = external(p, "C83_VARI");
  ASSERT_NE(vari, nullptr);
  EXPECT_EQ(vari->type, prp::VarType::Integer);
  ASSERT_TRUE(vari->initial.has_value());
  EXPECT_EQ(vari->initial->as_number(), 0);
  EXPECT_EQ(vari->declared_by, "drill_type");
  EXPECT_EQ(external(p, "dwell")->type, prp::VarType::Numeric);
  // Probe cycles are not drill cycles: skipped.
  EXPECT_EQ(p.drill_cycle("Probe_Cycle_Int._Arc"), nullptr);
}

// A wire machine (the shape of Chmer.vmid, majeretft/Cam-posts): <Machine OperationType="6"> makes
// machine_type WIRE_CUT, each <WireEdmMacro> a wc_macro record whose parameters are variables, and
// the job parameters of <WireParamsJobs> (E1, D1, ...) job options.
TEST(Vmid, WireMachinesTheirMacrosAndJobParameters) {
  const std::string wire =
      "<Machine Name=\"W\" OperationType=\"6\"><Controller><WireEdmMacros>"
      "<WireEdmMacro GppName=\"P8000\" UseCycle=\"0\"><CycleParams>"
      "<Param GppName=\"XX\" ValueType=\"3\" Value=\"0\"/><Param GppName=\"EE\" ValueType=\"3\" Value=\"33\"/>"
      "</CycleParams></WireEdmMacro>"
      "<WireEdmMacro GppName=\"P8001\" UseCycle=\"1\"><CycleParams><Param GppName=\"XX\" ValueType=\"3\" Value=\"0\"/>"
      "</CycleParams></WireEdmMacro></WireEdmMacros>"
      "<UserDefParams><WireParamsJobs><ParamJobs GppName=\"E1\" ValueType=\"3\" Value=\"0\"/></WireParamsJobs>"
      "</UserDefParams></Controller></Machine>";
  auto p = prp::load_source(wire, "w.vmid", Units::Metric);
  EXPECT_EQ(p.text("machine_type"), "WIRE_CUT");
  std::vector<std::string> got;
  for (const auto* r : p.records("wc_macro")) {
    std::string line = r->name + " " + r->base + " " + (*r->flag ? "Y" : "N");
    for (const auto& param : r->params) line += " " + param;
    got.push_back(line);
  }
  EXPECT_EQ(got, (std::vector<std::string>{"P8000 None N XX EE", "P8001 None Y XX"}));
  ASSERT_NE(external(p, "EE"), nullptr);
  EXPECT_EQ(external(p, "EE")->declared_by, "wc_macro");
  ASSERT_NE(external(p, "E1"), nullptr);
  EXPECT_EQ(external(p, "E1")->declared_by, "job_opt_type");
  // A milling machine says 0: no machine_type.
  EXPECT_FALSE(prp::load_source("<Machine OperationType=\"0\"/>", "m.vmid", Units::Metric).has("machine_type"));
}

// The canonical PRP text of a VMID's model loads back to the same parameters, records and variable
// types: the VMID is a PRP in another notation. Two things have no PRP form: the VMID's initial
// values, and cycle parameters of a type other than numeric (a PRP declares them all numeric).
TEST(Vmid, WritesAsAnEquivalentPrp) {
  auto vmid = prp::load_file("prp/data/mill-4x.vmid", Units::Inch);
  auto prp = prp::load_source(prp::write_source(vmid), "w.prp", Units::Inch);
  EXPECT_TRUE(prp.warnings().empty());
  ASSERT_EQ(prp.parameters().size(), vmid.parameters().size());
  for (const auto& p : vmid.parameters()) {
    ASSERT_NE(prp.find(p.key), nullptr) << p.key;
    EXPECT_EQ(prp::format_value(*prp.find(p.key)), prp::format_value(p)) << p.key;
  }
  ASSERT_EQ(prp.all_records().size(), vmid.all_records().size());
  for (std::size_t i = 0; i < vmid.all_records().size(); ++i)
    EXPECT_EQ(prp::format_record(prp.all_records()[i]), prp::format_record(vmid.all_records()[i]));
  ASSERT_EQ(prp.external_variables().size(), vmid.external_variables().size());
  for (std::size_t i = 0; i < vmid.external_variables().size(); ++i) {
    const auto& v = vmid.external_variables()[i];
    EXPECT_EQ(prp.external_variables()[i].name, v.name);
    EXPECT_EQ(prp.external_variables()[i].type, v.declared_by == "drill_type" ? prp::VarType::Numeric : v.type) << v.name;
  }
}

TEST(Vmid, RecognisedByContentWhateverTheName) {
  const std::string body = "\xEF\xBB\xBF\n  <Machine><Controller><PrecisionDef FeedPrecision=\"2\"/></Controller></Machine>";
  auto p = prp::load_source(body, "machine.prp", Units::Metric);
  EXPECT_EQ(p.integer("feed_precision"), 2);
  auto q = prp::load_source("<!--xml version=\"1.0\"--><Machine/>", "m.txt", Units::Metric);
  EXPECT_TRUE(q.parameters().empty());
}

struct ErrorCase {
  const char* name;
  const char* text;
  const char* expected;
};

class VmidErrors : public testing::TestWithParam<ErrorCase> {};

TEST_P(VmidErrors, ExactMessageAndPosition) { EXPECT_EQ(load_error(GetParam().text), GetParam().expected); }

const ErrorCase kErrorCases[] = {
    {"UnclosedElement", "<Machine>\n  <Controller>\n</Machine>\n",
     "m.vmid:3:3: error: malformed XML: Start-end tags mismatch (expected a well-formed SolidCAM VMID file)"},
    {"TruncatedFile", "<Machine>\n  <Controller Ver=\"9",
     "m.vmid:2:20: error: malformed XML: Error parsing element attribute (expected a well-formed SolidCAM VMID file)"},
    {"OtherRoot", "<?xml version=\"1.0\"?>\n<Project/>\n",
     "m.vmid:2:1: error: expected the root element <Machine> of a SolidCAM VMID file, found <Project>"},
    {"BadFlag", "<Machine>\n <ArcExecution SupportArcs=\"yes\"/>\n</Machine>\n",
     "m.vmid:2:29: error: SupportArcs=\"yes\" (PRP arc_exist): expected 0 or 1"},
    {"BadNumber", "<Machine>\n <ArcExecution MaxChordLength=\"3,5\"/>\n</Machine>\n",
     "m.vmid:2:32: error: MaxChordLength=\"3,5\" (PRP arc_max_chord): expected a number"},
    {"BadInteger", "<Machine><ProgramNumbers MinProgramNumber=\"1.5\"/></Machine>",
     "m.vmid:1:44: error: MinProgramNumber=\"1.5\" (PRP prog_num_min): expected an integer (-999999999 .. 999999999)"},
    {"BadLogicalValue",
     "<Machine><UserDefParams><MachineParams>\n<Param GppName=\"bX\" ValueType=\"1\" Value=\"2\"/>\n"
     "</MachineParams></UserDefParams></Machine>",
     "m.vmid:2:42: error: Value=\"2\": expected 0 or 1, a yes/no option (ValueType 1)"},
    {"BadNumericValue",
     "<Machine><UserDefParams><MachineParams>\n<Param GppName=\"nX\" ValueType=\"3\" Value=\"abc\"/>\n"
     "</MachineParams></UserDefParams></Machine>",
     "m.vmid:2:42: error: Value=\"abc\": expected a number (ValueType 3)"},
    {"BadIntegerValue",
     "<Machine><UserDefParams><MachineParams>\n<Param GppName=\"iX\" ValueType=\"5\" Value=\"0.5\"/>\n"
     "</MachineParams></UserDefParams></Machine>",
     "m.vmid:2:42: error: Value=\"0.5\": expected an integer (ValueType 5)"},
    {"BadName",
     "<Machine><MillDrilCycles>\n<DrillCycle GppName=\"G84.2\" DrillType=\"3\"/>\n</MillDrilCycles></Machine>",
     "m.vmid:2:22: error: GppName=\"G84.2\": expected a name (a letter, then letters, digits or '_', at most 60 "
     "characters)"},
    {"TypeConflict",
     "<Machine><MillDrilCycles>\n<DrillCycle GppName=\"G82\" DrillType=\"1\"><CycleParams>"
     "<Param GppName=\"dwell\" ValueType=\"3\"/></CycleParams></DrillCycle>\n</MillDrilCycles>\n"
     "<UserDefParams><MachineParams><Param GppName=\"dwell\" ValueType=\"2\"/></MachineParams></UserDefParams>"
     "</Machine>",
     "m.vmid:4:47: error: `dwell` is declared STRING here but NUMERIC at line 2"},
    {"RangeCheckedAsInAPrp",
     "<Machine><ProgramNumbers MinProgramNumber=\"5000\"/>\n<ProgramNumbers DefaultProgramNumber=\"10\"/></Machine>",
     "m.vmid:2:39: error: prog_num_dflt 10 is below prog_num_min 5000"},
};

INSTANTIATE_TEST_SUITE_P(Classes, VmidErrors, testing::ValuesIn(kErrorCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(VmidWarnings, UnknownCodesAreKeptWithAWarning) {
  auto p = prp::load_source(
      "<Machine>\n<MillDrilCycles><DrillCycle GppName=\"CYCLE85\" DrillType=\"8\"/></MillDrilCycles>\n"
      "<UserDefParams><MachineParams><Param GppName=\"xNew\" ValueType=\"9\" Value=\"a b\"/></MachineParams>"
      "</UserDefParams>\n<ProceduresDef GenProc=\"3\"/>\n</Machine>",
      "w.vmid", Units::Metric);
  EXPECT_EQ(warnings(p), (std::vector<std::string>{
                             "w.vmid:2:58: warning: DrillType=\"8\" of `CYCLE85`: expected 0 to 6; the cycle has no "
                             "base type (None)",
                             "w.vmid:3:64: warning: ValueType=\"9\" of `xNew`: expected 1 to 5; kept as text",
                             "w.vmid:4:25: warning: GenProc=\"3\" is not a code we know (0: N, 1: Y): gen_procs keeps "
                             "its default",
                         }));
  EXPECT_EQ(p.drill_cycle("CYCLE85")->base, "NONE");
  EXPECT_EQ(external(p, "xNew")->initial->text, "a b");
  EXPECT_EQ(p.text("gen_procs"), "N");
}

// The travel of the rotary axes of the machine's components, for verify; linear axes (machine
// coordinates) and other rotary devices are left out, the first axis of a name counts.
TEST(Vmid, RotaryAxisLimits) {
  auto p = prp::load_source(
      "<Machine><Components><Component>\n"
      "<Axis Name=\"X\" Type=\"0\" MinLim=\"-550\" MaxLim=\"550\"/>\n"
      "<Axis Name=\"A\" Type=\"1\" MinLim=\"-120\" MaxLim=\"30\"/>\n"
      "<Axis Name=\"a\" Type=\"1\" MinLim=\"-1\" MaxLim=\"1\"/>\n"
      "<Axis Name=\"C\" Type=\"1\" MinLim=\"-100000\" MaxLim=\"100000\"/>\n"
      "<Axis Name=\"S1\" Type=\"1\" MinLim=\"0\" MaxLim=\"360\"/>\n"
      "<Axis Name=\"B\" Type=\"1\" MinLim=\"90\" MaxLim=\"-90\"/>\n"
      "</Component></Components></Machine>",
      "r.vmid", Units::Metric);
  std::vector<std::string> got;
  for (const auto& r : p.rotary_limits()) got.push_back(fmt::format("{} {:g} {:g} line {}", r.axis, r.min, r.max, r.where.line));
  EXPECT_EQ(got, (std::vector<std::string>{"A -120 30 line 3", "C -100000 100000 line 5"}));
  EXPECT_EQ(warnings(p), (std::vector<std::string>{"r.vmid:7:1: warning: rotary axis B: MinLim and MaxLim are no range of "
                                                   "degrees; its travel is not checked"}));
  EXPECT_TRUE(prp::defaults(Units::Metric).rotary_limits().empty());
}

}  // namespace
