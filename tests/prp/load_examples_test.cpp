// Loading real PRP files: the spec's two example files and the shared FANUC example, in both unit
// systems, and the round trip of every value kind through the canonical writer.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "prp/prp.hpp"

using prp::Units;

namespace {

std::vector<std::string> names(const std::vector<const prp::Record*>& records) {
  std::vector<std::string> out;
  for (const auto* r : records) out.push_back(r->name + "/" + r->base + "/" + (r->flag ? (*r->flag ? "Y" : "N") : "-"));
  return out;
}

std::vector<std::string> texts(const std::vector<prp::Diagnostic>& diagnostics) {
  std::vector<std::string> out;
  for (const auto& d : diagnostics) out.push_back(d.text());
  return out;
}

TEST(LoadExamples, FanucMetric) {
  auto p = prp::load_file("prp/data/fanuc.prp", Units::Metric);
  EXPECT_EQ(p.text("post_processor"), "fanuc");
  EXPECT_EQ(p.text("gpp_file_ext"), "TAP");
  EXPECT_EQ(p.integer("max_g_name_length"), 0);
  EXPECT_EQ(p.text("default_lang"), "DEFAULT");
  EXPECT_FALSE(p.logical("abs_coord"));
  EXPECT_EQ(p.text("_4th_axes_around"), "X");
  EXPECT_EQ(p.integer("prog_num_min"), 5000);
  EXPECT_EQ(p.integer("prog_num_max"), 8999);
  EXPECT_EQ(p.text("gen_procs"), "N");
  EXPECT_EQ(p.point("dflt_start"), Eigen::Vector3d(0, 200, 100));
  EXPECT_EQ(p.point("dflt_end"), Eigen::Vector3d(0, 200, 0));
  EXPECT_EQ(p.integer("Delta_for_TOOL_H"), 50);  // written `delta_for_TOOL_H`
  EXPECT_TRUE(p.logical("arc_exist"));
  EXPECT_TRUE(p.logical("arc_quadrants"));
  EXPECT_FALSE(p.logical("arc_gt_180"));
  EXPECT_FALSE(p.logical("arc_zx_yz"));
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_chord"), 30.0);
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_angle"), 10.0);
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_radius"), 2000.0);
  EXPECT_DOUBLE_EQ(p.numeric("eps_angle"), 0.002);
  EXPECT_DOUBLE_EQ(p.numeric("zero_value"), 0.001);
  EXPECT_DOUBLE_EQ(p.numeric("rapid_feed"), 5000.0);
  EXPECT_DOUBLE_EQ(p.numeric("time_factor"), 1.0);
  EXPECT_DOUBLE_EQ(p.numeric("block_time"), 0.2);
  EXPECT_DOUBLE_EQ(p.numeric("interplat_angle_step"), 3.0);
  EXPECT_EQ(p.integer("center_rot_prp_num"), 20);
  // Engine defaults for keys the file does not set (spec 3.0).
  EXPECT_FALSE(p.has("arc_3d_4x"));
  EXPECT_TRUE(p.logical("arc_3d_4x"));
  EXPECT_DOUBLE_EQ(p.numeric("eps_line"), 0.0);
  EXPECT_DOUBLE_EQ(p.numeric("change_tool_time"), 0.0);
  EXPECT_THROW(p.numeric("arc_exist"), std::out_of_range);
  EXPECT_THROW(p.logical("no_such_key"), std::out_of_range);
  EXPECT_THROW(p.integer("num_homes"), std::out_of_range);  // no default

  EXPECT_EQ(names(p.records("drill_type")),
            (std::vector<std::string>{"Drilling/DRILLING/Y", "F_Drill/F_DRILL/Y", "Peck/PECK/Y", "Tapping/TAPPING/Y",
                                      "Boring/BORING/Y", "R_Boring/R_BORING/Y", "F_Boring/F_BORING/Y"}));
  EXPECT_EQ(p.drill_cycle("PECK")->params, std::vector<std::string>{"Delay"});
  EXPECT_EQ(names(p.records("job_opt_type")), std::vector<std::string>{"OPT1//Y"});

  std::vector<std::string> externals;
  for (const auto& v : p.external_variables())
    externals.push_back(v.name + ":" + std::string(prp::type_name(v.type)) + ":" + v.declared_by + ":" +
                        (v.initial ? "0" : "inactive"));
  EXPECT_EQ(externals, (std::vector<std::string>{"COLENT:INTEGER:options:0", "DELY:NUMERIC:job_opt_type:inactive",
                                                 "FEAD:NUMERIC:job_opt_type:inactive",
                                                 "Delay:NUMERIC:drill_type:inactive"}));
  EXPECT_TRUE(p.unknown_keys().empty());
  EXPECT_EQ(texts(p.warnings()),
            std::vector<std::string>{"prp/data/fanuc.prp:13:16: warning: expected CHINESE, CZECH, DANISH, ENGLISH, "
                                     "FRENCH, GERMAN, HEBREW, HUNGARIAN, ITALIAN, JAPANESE, KOREAN, POLISH, "
                                     "PORTUGUESE, RUSSIAN, SPANISH or TURKISH, found `DEFAULT` (kept)"});
}

TEST(LoadExamples, FanucInchUsesTheInchHalvesAsWritten) {
  auto p = prp::load_file("prp/data/fanuc.prp", Units::Inch);
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_chord"), 1.1811);
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_radius"), 78.7402);
  EXPECT_DOUBLE_EQ(p.numeric("zero_value"), 0.0);  // rounded independently, never recomputed
  EXPECT_DOUBLE_EQ(p.numeric("rapid_feed"), 196.8503);
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_angle"), 10.0);  // a single value applies to both systems
  EXPECT_EQ(p.point("dflt_start"), Eigen::Vector3d(0, 7.874, 3.937));
  EXPECT_DOUBLE_EQ(p.numeric("interplat_distance"), 0.1969);
}

void check_integrex(const prp::MachineParameters& p) {
  EXPECT_EQ(p.text("gpp_file_ext"), "EIA");
  EXPECT_EQ(p.text("_5th_axes_around"), "Z");
  EXPECT_EQ(p.integer("prog_num_min"), 1);  // written 0001
  EXPECT_EQ(p.text("gen_procs"), "Y");
  EXPECT_TRUE(p.logical("seq_sub_number"));  // written `y`
  EXPECT_EQ(p.point("dflt_start"), Eigen::Vector3d(200, 0, 200));
  EXPECT_TRUE(p.logical("comp_exist"));
  EXPECT_EQ(p.find("comp_exist")->extra, std::vector<std::string>{"Y"});
  EXPECT_EQ(p.find("turning_cycle")->extra, std::vector<std::string>{"N"});
  EXPECT_FALSE(p.logical("arc_quadrants"));
  EXPECT_TRUE(p.logical("arc_gt_180"));
  EXPECT_DOUBLE_EQ(p.numeric("arc_max_chord"), 30.0);  // the commented-out 10.0 is ignored
  EXPECT_EQ(p.text("offset_group_name"), "");
  EXPECT_TRUE(p.has("offset_group_name"));
  EXPECT_EQ(names(p.records("options")), (std::vector<std::string>{"BACK_SPIN//-", "GREAPER//-", "COLENT//-",
                                                                   "number_of_parts//-"}));
  EXPECT_EQ(p.records("options")[3]->type, prp::VarType::Integer);
  EXPECT_EQ(names(p.records("drill_type")),
            (std::vector<std::string>{"Peck/PECK/Y", "Tapping/TAPPING/Y", "G84_2/TAPPING/Y", "F_Boring/F_BORING/Y",
                                      "G87/PECK/Y", "G88/TAPPING/Y", "G88_2/TAPPING/Y", "G89/F_BORING/Y"}));
  EXPECT_TRUE(p.drill_cycle("g84_2")->params.empty());
  EXPECT_EQ(p.records("thread_type")[0]->params,
            (std::vector<std::string>{"phase", "no_last_cut", "last_cut", "min_down_step", "spin_dir1", "T_angle",
                                      "m7_m8_3"}));
  std::vector<std::string> externals;
  for (const auto& v : p.external_variables()) externals.push_back(v.name);
  EXPECT_EQ(externals, (std::vector<std::string>{"BACK_SPIN", "GREAPER", "COLENT", "number_of_parts", "G107",
                                                 "use_feed", "m7_m8", "Delay", "m7_m8_1", "phase", "no_last_cut",
                                                 "last_cut", "min_down_step", "spin_dir1", "T_angle", "m7_m8_3",
                                                 "m7_m8_4"}));
  EXPECT_TRUE(p.warnings().empty());
}

TEST(LoadExamples, Integrex) { check_integrex(prp::load_file("prp/data/integrex-e-410h.prp", Units::Metric)); }

TEST(LoadExamples, IntegrexWithNoBreakSpacesAndCrLf) {
  check_integrex(prp::load_file("prp/data/integrex-nbsp.prp", Units::Metric));
}

TEST(LoadExamples, UnreadableFile) {
  EXPECT_THROW(prp::load_file("prp/data/no-such-file.prp", Units::Metric), toolpath::InputError);
}

// Every value kind, written back canonically and read again, gives the same parameters.
TEST(RoundTrip, EveryValueKind) {
  const std::string text =
      "@pre_processor\n"
      "prog_num_min = -0042\n"
      "arc_max_angle = 12.5\n"
      "arc_max_chord = 30.0000, 1.1811\n"
      "dflt_start = 0 200 100\n"
      "dflt_end = 1.5 -2 .25, 0.0591 -0.0787 0.0098\n"
      "turning_cycle = y n\n"
      "machine_plane = zx\n"
      "gpp_file_ext = nc file\n"
      "dir_gcode =\n"
      "options = flag_a (Logical)\n"
      "job_opt_type_ger = Opt_B Y p1 p2\n"
      "drill_type = Peck Y Delay\n"
      "drill_type = G83 peck N Q_Peck P_Dwell\n"
      "wc_macro = P8000 None Y XX YY\n"
      "wc_pos_type = POS1 AA BB\n"
      "brand_new_key = 1 2 3 ;comment\n"
      "endp\n";
  auto first = prp::load_source(text, "a.prp", Units::Metric);
  const std::string written = prp::write_source(first);
  auto second = prp::load_source(written, "b.prp", Units::Metric);
  ASSERT_EQ(first.parameters().size(), 9u);
  ASSERT_EQ(second.parameters().size(), first.parameters().size());
  for (std::size_t i = 0; i < first.parameters().size(); ++i) {
    const auto& a = first.parameters()[i];
    const auto& b = second.parameters()[i];
    EXPECT_EQ(a.key, b.key);
    EXPECT_EQ(a.kind, b.kind) << a.key;
    EXPECT_EQ(a.integer, b.integer) << a.key;
    EXPECT_EQ(a.logical, b.logical) << a.key;
    EXPECT_EQ(a.text, b.text) << a.key;
    EXPECT_EQ(a.metric, b.metric) << a.key;
    EXPECT_EQ(a.inch, b.inch) << a.key;
    EXPECT_EQ(a.has_inch_half, b.has_inch_half) << a.key;
    EXPECT_EQ(a.extra, b.extra) << a.key;
  }
  ASSERT_EQ(second.all_records().size(), first.all_records().size());
  for (std::size_t i = 0; i < first.all_records().size(); ++i)
    EXPECT_EQ(prp::format_record(first.all_records()[i]), prp::format_record(second.all_records()[i]));
  EXPECT_EQ(written,
            "@pre_processor\n"
            "prog_num_min = -42\n"
            "arc_max_angle = 12.5\n"
            "arc_max_chord = 30, 1.1811\n"
            "dflt_start = 0 200 100\n"
            "dflt_end = 1.5 -2 0.25, 0.0591 -0.0787 0.0098\n"
            "turning_cycle = Y n\n"
            "machine_plane = zx\n"
            "gpp_file_ext = nc file\n"
            "dir_gcode = \n"
            "options = flag_a LOGICAL\n"
            "job_opt_type_ger = Opt_B Y p1 p2\n"
            "drill_type = Peck PECK Y Delay\n"
            "drill_type = G83 PECK N Q_Peck P_Dwell\n"
            "wc_macro = P8000 None Y XX YY\n"
            "wc_pos_type = POS1 AA BB\n"
            "brand_new_key = 1 2 3\n"
            "endp\n");
  EXPECT_EQ(second.unknown("BRAND_NEW_KEY")->raw, "1 2 3");
  EXPECT_EQ(*first.find("gpp_file_ext")->value(Units::Metric), toolpath::Value::make_string("nc file"));
  EXPECT_EQ(*first.find("machine_plane")->value(Units::Metric), toolpath::Value::make_enum("ZX"));
  EXPECT_EQ(*first.find("arc_max_chord")->value(Units::Inch), toolpath::Value::make_numeric(1.1811));
}

}  // namespace
