// One case per class of malformed PRP input: the exact message and position, and that every error
// of a file is reported at once. Then the warnings, which never stop loading.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "prp/prp.hpp"

namespace {

std::string load_error(const std::string& body) {
  try {
    prp::load_source(body, "t.prp", prp::Units::Metric);
  } catch (const prp::LoadError& e) {
    return e.what();
  }
  return "no error";
}

struct ErrorCase {
  const char* name;
  std::string text;
  std::string expected;
};

class LoadErrors : public testing::TestWithParam<ErrorCase> {};

TEST_P(LoadErrors, ExactMessageAndPosition) {
  EXPECT_EQ(load_error(GetParam().text), GetParam().expected);
}

const ErrorCase kErrorCases[] = {
    {"Logical", "@pre_processor\narc_exist = maybe\nendp\n", "t.prp:2:13: error: expected Y or N, found `maybe`"},
    {"NumberWithUnit", "@pre_processor\narc_max_chord = 30 mm\nendp\n",
     "t.prp:2:20: error: expected a number, or number ',' number, found `mm`"},
    {"NumberThreeHalves", "@pre_processor\nsafety_dist = 2, 0.0787, 1\nendp\n",
     "t.prp:2:24: error: expected a number, or number ',' number"},
    {"PointTooShort", "@pre_processor\ndflt_start = 1 2\nendp\n",
     "t.prp:2:17: error: expected 3 numbers, optionally ',' and 3 more"},
    {"PointHalvesDiffer", "@pre_processor\ndflt_start = 1 2 3, 4 5\nendp\n",
     "t.prp:2:24: error: expected 3 numbers, optionally ',' and 3 more"},
    {"PointDecimalComma", "@pre_processor\ndflt_end = 1,5 2 3\nendp\n",
     "t.prp:2:13: error: expected 3 numbers, optionally ',' and 3 more"},
    {"Integer", "@pre_processor\nprog_num_min = 12.5\nendp\n", "t.prp:2:16: error: expected an integer, found `12.5`"},
    {"IntegerRange", "@pre_processor\nprog_num_max = 1000000000\nendp\n",
     "t.prp:2:16: error: integer out of range (-999999999 .. 999999999)"},
    {"NumberRange", "@pre_processor\nrapid_feed = 1e301\nendp\n",
     "t.prp:2:14: error: number out of range (-1E300 .. 1E300)"},
    {"Enumeration", "@pre_processor\nmachine_plane = XZ\nendp\n",
     "t.prp:2:17: error: expected XY, YZ, ZX or ZC, found `XZ`"},
    // A wrong file's megabyte token is quoted by its start.
    {"LongToken", "@pre_processor\nmachine_plane = " + std::string(100000, 'Q') + "\nendp\n",
     "t.prp:2:17: error: expected XY, YZ, ZX or ZC, found `" + std::string(40, 'Q') + "...`"},
    {"NoHeader", "; comment\narc_exist = Y\nendp\n", "t.prp:2:1: error: expected `@pre_processor` before the first statement"},
    {"EmptyFile", "", "t.prp:1:1: error: expected `@pre_processor`: the file has no parameter section"},
    {"NoEndp", "@pre_processor\narc_exist = Y",
     "t.prp:2:14: error: expected `endp` before the end of the file (is the file truncated?)"},
    {"NoEquals", "@pre_processor\n   T_angle m7_m8_3\nendp\n",
     "t.prp:2:4: error: expected `key = value` (a key starts with a letter or '_')"},
    {"KeyStartsWithDigit", "@pre_processor\n4th_axis = X\nendp\n",
     "t.prp:2:1: error: expected `key = value` (a key starts with a letter or '_')"},
    {"HeaderTwice", "@pre_processor\n@pre_processor\nendp\n", "t.prp:2:1: error: `@pre_processor` appears twice"},
    {"DrillBase", "@pre_processor\ndrill_type = G81 Drill Y\nendp\n",
     "t.prp:2:18: error: expected a drill base type (DRILLING, F_DRILL, PECK, TAPPING, BORING, R_BORING, F_BORING or "
     "None), found `Drill`"},
    {"DrillLegacyBase", "@pre_processor\ndrill_type = Spot Y\nendp\n",
     "t.prp:2:14: error: expected a drill base type (DRILLING, F_DRILL, PECK, TAPPING, BORING, R_BORING, F_BORING or "
     "None), found `Spot`"},
    {"RecordFlag", "@pre_processor\ndrill_type = G81 Drilling Maybe\nendp\n",
     "t.prp:2:27: error: expected Y or N, found `Maybe` (a record is `name base Y|N {param}`)"},
    {"RecordTooShort", "@pre_processor\nturn_type = T1\nendp\n",
     "t.prp:2:15: error: expected `name Y|N {param}` or `name TYPE`"},
    {"RecordIdentifier", "@pre_processor\njob_opt_type = OPT1 Y 2nd_feed\nendp\n",
     "t.prp:2:23: error: `2nd_feed` is not a valid name (a letter, then letters, digits or '_', at most 60 characters)"},
    {"RecordDuplicate", "@pre_processor\ndrill_type = Peck Peck Y\ndrill_type = peck Peck N\nendp\n",
     "t.prp:3:14: error: `drill_type` declares `peck` twice (first at line 2)"},
    {"OptionsShape", "@pre_processor\noptions = COLENT Y\nendp\n",
     "t.prp:2:18: error: expected `name TYPE` (TYPE: INTEGER, LOGICAL, NUMERIC or STRING)"},
    {"DrillTyped", "@pre_processor\ndrill_type = Delay NUMERIC\nendp\n",
     "t.prp:2:20: error: `drill_type` records declare cycles, not typed variables"},
    {"TypeConflict", "@pre_processor\noptions = Delay LOGICAL\ndrill_type = Peck Peck Y Delay\nendp\n",
     "t.prp:3:26: error: `Delay` is declared NUMERIC here but LOGICAL at line 2"},
    {"ProgramNumberRange", "@pre_processor\nprog_num_min = 5000\nprog_num_max = 8999\nprog_num_dflt = 100\nendp\n",
     "t.prp:4:17: error: prog_num_dflt 100 is below prog_num_min 5000"},
    {"ProcedureNumberRange", "@pre_processor\nproc_num_dflt = 9000\nproc_num_max = 8999\nendp\n",
     "t.prp:3:16: error: proc_num_dflt 9000 is above proc_num_max 8999"},
    {"ChordNotPositive", "@pre_processor\narc_max_chord = 30, 0\nendp\n",
     "t.prp:2:17: error: arc_max_chord must be greater than 0"},
    {"DeviationNotPositive", "@pre_processor\narc_max_deviation = 0.01, 0\nendp\n",
     "t.prp:2:21: error: arc_max_deviation must be greater than 0"},
    {"MaxAngle", "@pre_processor\narc_max_angle = 361\nendp\n", "t.prp:2:17: error: arc_max_angle must be in (0, 360] degrees"},
    {"NegativeEpsilon", "@pre_processor\neps_line = -0.1\nendp\n", "t.prp:2:12: error: eps_line must not be negative"},
    {"AllErrorsAtOnce", "@pre_processor\narc_exist = maybe\ngen_procs = X\narc_max_angle = 0\nendp\n",
     "t.prp:2:13: error: expected Y or N, found `maybe`\n"
     "t.prp:3:13: error: expected Y, N, C or D, found `X`\n"
     "t.prp:4:17: error: arc_max_angle must be in (0, 360] degrees"},
};

INSTANTIATE_TEST_SUITE_P(Classes, LoadErrors, testing::ValuesIn(kErrorCases),
                         [](const auto& info) { return std::string(info.param.name); });

struct WarningCase {
  const char* name;
  const char* text;
  std::vector<std::string> expected;
};

class LoadWarnings : public testing::TestWithParam<WarningCase> {};

TEST_P(LoadWarnings, LoadingGoesOn) {
  auto p = prp::load_source(GetParam().text, "w.prp", prp::Units::Metric);
  std::vector<std::string> got;
  for (const auto& w : p.warnings()) got.push_back(w.text());
  EXPECT_EQ(got, GetParam().expected);
}

const WarningCase kWarningCases[] = {
    {"UnknownKey", "@pre_processor\nnew_key = 3 4\nendp\n",
     {"w.prp:2:1: warning: unknown key `new_key`: kept as text for the post"}},
    {"Duplicate", "@pre_processor\narc_exist = Y\n  ARC_EXIST = N\nendp\n",
     {"w.prp:3:3: warning: `ARC_EXIST` is set again (first at line 2): the last value wins"}},
    {"HeaderText", "@pre_processor (translator's note)\nendp\n",
     {"w.prp:1:16: warning: text after `@pre_processor` is ignored"}},
    {"AfterEndp", "@pre_processor\nendp\n@init_post\n", {"w.prp:3:1: warning: text after `endp` is ignored"}},
    {"DecimalComma", "@pre_processor\narc_max_chord = 30,5\nendp\n",
     {"w.prp:2:17: warning: the inch value 5 is not the metric value 30 / 25.4 (a decimal comma written by "
      "mistake?)"}},
    {"ExtraTokens", "@pre_processor\nmax_g_name_length = 8 chars\nendp\n",
     {"w.prp:2:23: warning: extra text after the value is ignored"}},
    {"MachineType", "@pre_processor\nmachine_type = LASER\nendp\n",
     {"w.prp:2:16: warning: expected MILLING, TURNING or WIRE_CUT, found `LASER` (kept)"}},
};

INSTANTIATE_TEST_SUITE_P(Classes, LoadWarnings, testing::ValuesIn(kWarningCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(LoadWarnings, DuplicateKeepsTheLastValueAndUnknownKeysStayReadable) {
  auto p = prp::load_source("@pre_processor\narc_exist = Y\narc_exist = N\nnew_key = 3 4 ; why\nendp\n", "w.prp",
                            prp::Units::Metric);
  EXPECT_FALSE(p.logical("arc_exist"));
  ASSERT_NE(p.unknown("NEW_KEY"), nullptr);
  EXPECT_EQ(p.unknown("new_key")->raw, "3 4");
  EXPECT_EQ(p.unknown("new_key")->where.line, 4u);
  EXPECT_EQ(p.unknown("new_key")->where.column, 11u);
}

}  // namespace
