// Display formats: every vector of the language spec (section 7.5), the Fanuc sample output, and
// each invalid format with its GPPTool error number.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "gppl/builtins/display_format.hpp"

namespace {

using gppl::Value;

Value num(double v) { return Value::of_numeric(v); }
Value integer(std::int64_t v) { return Value::of_integer(v); }

struct Vector {
  const char* name;
  Value value;
  const char* format;
  const char* expected;
};

std::ostream& operator<<(std::ostream& os, const Vector& v) { return os << v.name; }

class FormatVectors : public testing::TestWithParam<Vector> {};

TEST_P(FormatVectors, PrintsExactly) {
  const Vector& v = GetParam();
  gppl::DisplayFormat f = gppl::parse_display_format(v.format);
  EXPECT_EQ(gppl::format_value(f, v.value), v.expected) << "format '" << v.format << "'";
}

// Section 7.5, in the spec's order (#1..#35).
const Vector spec_vectors[] = {
    {"v01", num(123.456), "5.2", "123.46"},
    {"v02", integer(123456), "5.2", "123456."},
    {"v03", integer(123456), "5.2(p)", "123456"},
    {"v04", num(-12.3), " 5.3z", "   -12.300"},
    {"v05", num(-12.3), " 5.3z(n)", "   -12300"},
    {"v06", num(1.234), "+5.0(*100)", "+123."},
    {"v07", integer(-1234), "+5.0(/2.54i)", "+486."},
    {"v08", num(12.345), "8/5.7/4", "00012.3450"},
    {"v09", num(12.5), "<X> 5.2 (p)", "X12.5"},
    {"v10", num(12.5), "5.2 (p) <abc>", "12.5abc"},
    {"v11", num(12.5), "<X> 5.2 <abc>", "X12.5abc"},
    {"v12", num(12.345), "<X> 5.3 < >", "X12.345 "},
    {"v13", num(0.), "5.3", "0."},
    {"v14", num(50.), "5.3", "50."},
    {"v15", num(-16.35), "5.3", "-16.35"},
    {"v16", num(10.), "5.3/1", "10.0"},
    {"v17", num(12.7), "5.3/1", "12.7"},
    {"v18", num(75.), "4.3(p)", "75"},
    {"v19", integer(5), "5.0(p)", "5"},
    {"v20", num(3000.), "5.0(p)", "3000"},
    {"v21", integer(276), "2.0(p)", "276"},
    {"v22", num(5.), "5.3", "5."},
    {"v23", num(5.), "5.3(p)", "5"},
    {"v24", num(5.1), "5.3(p)", "5.1"},
    {"v25", integer(1), "z2.0(n)", "01"},
    {"v26", integer(1), "2/2.0(p)", "01"},
    {"v27", num(10.), "5.3(*2)", "20."},
    {"v28", num(1.5), "2/2.0(P*10)", "15"},
    {"v29", num(0.012), "5.3(*1000p)", "12"},
    {"v30", num(0.), "5.3(d)", ""},
    {"v31", num(0.0004), "5.3(d)", ""},
    {"v32", num(-0.0004), "+5.3", "+0."},
    {"v33", num(0.5), "5.3", "0.5"},
    {"v34", num(0.5), "5/0.3", ".5"},
    {"v35", num(12.3), "5.3 ", "12.3  "},
};
INSTANTIATE_TEST_SUITE_P(Spec, FormatVectors, testing::ValuesIn(spec_vectors),
                         [](const auto& info) { return std::string(info.param.name); });

// The Fanuc example's output (shared example README, "Formats").
const Vector fanuc_vectors[] = {
    {"Z50", num(50.), "5.3", "50."},
    {"X0", num(0.), "5.3", "0."},
    {"R6_35", num(6.35), "5.3", "6.35"},
    {"S3000", num(3000.), "5.0(p)", "3000"},
    {"F75", num(75.), "4.3(p)", "75"},
    {"P51", integer(51), "5.0(p)", "51"},
    {"DIA12_7", num(12.7), "5.3/1", "12.7"},
    {"DIA10_0", num(10.), "5.3/1", "10.0"},
    {"DIA12_0", num(12.), "5.3/1", "12.0"},
    {"G1", integer(1), "2.0(p)", "1"},
    {"Xneg", num(-53.75), "5.3", "-53.75"},
};
INSTANTIATE_TEST_SUITE_P(Fanuc, FormatVectors, testing::ValuesIn(fanuc_vectors),
                         [](const auto& info) { return std::string(info.param.name); });

// Rounding, signs, padding and option corners that the spec's algorithm (7.3) implies.
const Vector algorithm_vectors[] = {
    {"half_up", num(12.5), "5.0", "13."},
    {"half_up_negative", num(-12.5), "5.0", "-13."},
    {"decimal_half", num(2.675), "5.2", "2.68"},
    {"decimal_half_negative", num(-2.675), "5.2", "-2.68"},
    {"noise_below_half", num(1.0005), "5.3", "1.001"},
    {"sum_noise", num(0.1 + 0.2), "5.3z", "0.300"},
    {"carry_into_new_digit", num(9.9996), "5.3", "10."},
    {"carry_from_nothing", num(0.0005), "5.3", "0.001"},
    {"below_half_unit", num(0.00049), "5.3", "0."},
    {"tiny", num(1e-30), "5.3", "0."},
    {"negative_zero", num(-0.0), "5.3", "0."},
    {"plus_zero", num(0.), "+5.3", "+0."},
    {"plus_positive", num(1.5), "+5.3", "+1.5"},
    {"minus_control_positive", num(1.5), "-5.3", "1.5"},
    {"minus_control_negative", num(-1.5), "-5.3", "-1.5"},
    {"lead_blank_positive", num(1.5), " 5.3", "    1.5"},
    {"lead_zero", num(-1.5), "z5.3", "-00001.5"},
    {"lead_zero_upper", num(12.), "Z4.0(p)", "0012"},
    {"lead_blank_plus", num(12.), "+ 4.1", "  +12."},
    {"lead_before_sign", num(12.), " +4.1", "  +12."},
    {"lead_not_truncating", num(123456.), " 3.0(p)", "123456"},
    {"min_int_two", num(0.25), "5/2.2", "00.25"},
    {"min_frac_kept", num(3.), "5.3/2", "3.00"},
    {"min_frac_more_than_N", num(3.), "5.2/3", "3.00"},
    {"trail_zero_upper", num(3.1), "5.3Z", "3.100"},
    {"trail_blank_all_zero", num(3.), "5.3 ", "3.   "},
    {"blank_before_options_separates", num(3.), "5.3 (p)", "3"},
    {"no_point_stripped", num(12.3), "5.3(n)", "123"},
    {"no_point_integer", integer(42), "5.0(n)", "42"},
    {"conditional_point_zero_trail", num(4.), "5.3z(p)", "4"},
    {"conditional_point_rounded", num(4.0004), "5.3(p)", "4"},
    {"invert_integer", integer(15), "5.0(pi)", "-15"},
    {"invert_zero", integer(0), "+5.0(pi)", "+0"},
    {"divide_then_multiply", num(10.), "5.3(/4*2)", "5."},
    {"negative_scale", num(2.), "5.1(*-1.5)", "-3."},
    {"fractional_scale", num(10.), "5.3(*.5)", "5."},
    {"integer_scaled", integer(3), "5.3(*0.5)", "1.5"},
    {"options_spaced", num(0.), "5.3( d )", ""},
    {"options_upper", num(5.), "5.3(P)", "5"},
    {"delete_integer_zero", integer(0), "<X>5.0(d)<;>", ""},
    {"delete_keeps_nonzero", integer(7), "<X>5.0(d)<;>", "X7.;"},
    {"prefix_lead_blank_separator", num(1.), "<X>  5.3", "X1."},
    {"empty_affixes", num(1.25), "<> 5.2 <>", "1.25"},
    {"affix_cut_at_31", num(1.), "<abcdefghijklmnopqrstuvwxyz0123456789>5.0(p)", "abcdefghijklmnopqrstuvwxyz012341"},
    {"blanks_before_prefix", num(1.), "  <Y>5.0(p)", "Y1"},
    {"m_zero_value_zero", num(0.), "5/0.3", "0."},
    {"m_zero_value_zero_p", num(0.), "5/0.3(p)", "0"},
    {"logical_true", Value::of_logical(true), "5.0(p)", "1"},
    {"logical_false", Value::of_logical(false), "5.3", "0."},
    {"large", num(1e20), "5.3", "100000000000000000000."},
    {"fifteen_digits", num(123456789.123456789), "5.9z", "123456789.123457000"},
    {"int64_exact", integer(999999999), "5.3", "999999999."},
    {"int64_min", integer(INT64_MIN), "5.0(p)", "-9223372036854775808"},
    {"many_fraction_digits", num(0.001234), "1.20z", "0.00123400000000000000"},
    {"string_verbatim", Value::of_string("ABC "), "<X>5.3", "ABC "},
};
INSTANTIATE_TEST_SUITE_P(Algorithm, FormatVectors, testing::ValuesIn(algorithm_vectors),
                         [](const auto& info) { return std::string(info.param.name); });

// What SolidCAM wrote with these formats (docs/gppl-formats.md, "M/m: never more than M"): the
// Siemens posts' gcode_f/mcode_f '1/2.0(p)' print G0, M3, G17, G710.
const Vector solidcam_vectors[] = {
    {"m_above_M_zero", integer(0), "1/2.0(p)", "0"},
    {"m_above_M_one_digit", integer(3), "1/2.0(p)", "3"},
    {"m_above_M_two_digits", integer(17), "1/2.0(p)", "17"},
    {"m_above_M_three_digits", integer(710), "1/2.0(p)", "710"},
    {"m_above_M_clipped_to_M", integer(5), "2/3.0(p)", "05"},
    {"m_below_M_zero_fills", num(1.5), "4/3.2", "001.5"},
};
INSTANTIATE_TEST_SUITE_P(SolidCAM, FormatVectors, testing::ValuesIn(solidcam_vectors),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(DisplayFormat, LargestPrintableValue) {
  gppl::DisplayFormat f = gppl::parse_display_format("5.0(p)");
  EXPECT_EQ(gppl::format_value(f, num(1e100)), "1" + std::string(100, '0'));
  EXPECT_EQ(gppl::format_value(f, num(-1e100)), "-1" + std::string(100, '0'));
}

TEST(DisplayFormat, AppendsToTheCallersBuffer) {
  gppl::DisplayFormat x = gppl::parse_display_format("<X>5.3");
  gppl::DisplayFormat y = gppl::parse_display_format("< Y>5.3<;>");
  std::string line = "G1 ";
  gppl::append_formatted(line, x, num(1.5));
  gppl::append_formatted(line, y, num(-2.));
  EXPECT_EQ(line, "G1 X1.5 Y-2.;");
}

TEST(DisplayFormat, ParsedComponents) {
  gppl::DisplayFormat f = gppl::parse_display_format("<N>+z8/5.7/4z(*2 /3 d n P I)<;>");
  EXPECT_EQ(f.prefix_text(), "N");
  EXPECT_EQ(f.postfix_text(), ";");
  EXPECT_EQ(f.sign, gppl::DisplayFormat::Sign::Always);
  EXPECT_EQ(f.lead, gppl::DisplayFormat::Pad::Zero);
  EXPECT_EQ(f.trail, gppl::DisplayFormat::Pad::Zero);
  EXPECT_EQ(f.int_digits, 8);
  EXPECT_EQ(f.min_int_digits, 5);
  EXPECT_EQ(f.frac_digits, 7);
  EXPECT_EQ(f.min_frac_digits, 4);
  ASSERT_EQ(f.scale_count, 2);
  EXPECT_EQ(f.scales[0].factor, 2.0);
  EXPECT_FALSE(f.scales[0].divide);
  EXPECT_EQ(f.scales[1].factor, 3.0);
  EXPECT_TRUE(f.scales[1].divide);
  EXPECT_TRUE(f.delete_if_zero && f.no_point && f.conditional_point && f.invert);
}

TEST(DisplayFormat, ScalesBeyondFourAreFolded) {
  gppl::DisplayFormat f = gppl::parse_display_format("5.3(*2*2*2*2*2/4)");
  EXPECT_EQ(f.scale_count, gppl::DisplayFormat::max_scales);
  EXPECT_EQ(gppl::format_value(f, num(1.)), "8.");
}

struct BadFormat {
  const char* format;
  int error;
};

class InvalidFormats : public testing::TestWithParam<BadFormat> {};

TEST_P(InvalidFormats, ThrowTheirNumber) {
  try {
    gppl::parse_display_format(GetParam().format);
    FAIL() << "'" << GetParam().format << "' was accepted";
  } catch (const gppl::Error& e) {
    EXPECT_EQ(e.number(), GetParam().error) << "'" << GetParam().format << "': " << e.what();
    EXPECT_TRUE(e.where().file.empty());
    EXPECT_NE(e.text().find(GetParam().format), std::string::npos) << e.text();
  }
}

INSTANTIATE_TEST_SUITE_P(Spec, InvalidFormats,
                         testing::Values(BadFormat{"5", 421}, BadFormat{"5.", 422}, BadFormat{".3", 408},
                                         BadFormat{"5.3(q)", 423}, BadFormat{"5.3(*)", 409}));

INSTANTIATE_TEST_SUITE_P(
    More, InvalidFormats,
    testing::Values(BadFormat{"", 408}, BadFormat{"   ", 408}, BadFormat{"+", 408}, BadFormat{"<X>", 408},
                    BadFormat{"<X>.5", 408}, BadFormat{"5/.3", 408}, BadFormat{"5(p)", 421}, BadFormat{"53", 421},
                    BadFormat{"5,3", 421}, BadFormat{"5.(p)", 422}, BadFormat{"5.3/", 422},
                    BadFormat{"5.3(/0)", 409}, BadFormat{"5.3(/0.0)", 409}, BadFormat{"5.3(*x)", 409},
                    BadFormat{"5.3(/-)", 409}, BadFormat{"5.3(*.)", 409}, BadFormat{"x5.3", 423},
                    BadFormat{"5.3(p", 423}, BadFormat{"5.3(p)(d)", 423}, BadFormat{"5.3 x", 423},
                    BadFormat{"5.3(p) <X", 423}, BadFormat{"<X 5.3", 423}, BadFormat{"5.3<X>(p)", 423},
                    BadFormat{"5.3<X>!", 423}, BadFormat{"++5.3", 423}, BadFormat{"z z5.3", 423},
                    BadFormat{"100.3", 423}, BadFormat{"5.100", 423}, BadFormat{"5.3(*2.5.1)", 423},
                    BadFormat{"5.3zz", 423}));

TEST(DisplayFormat, ValueOutOfRangeIs410) {
  gppl::DisplayFormat f = gppl::parse_display_format("5.3");
  for (double bad : {1e101, -1e101, std::numeric_limits<double>::infinity(), std::nan("")}) {
    try {
      gppl::format_value(f, num(bad));
      FAIL() << bad << " was printed";
    } catch (const gppl::Error& e) {
      EXPECT_EQ(e.number(), 410);
    }
  }
  gppl::DisplayFormat scaled = gppl::parse_display_format("5.3(*10)");
  EXPECT_THROW(gppl::format_value(scaled, num(1e100)), gppl::Error);
}

TEST(DisplayFormat, ScaledIntegerBeyondRangeIs410) {
  gppl::DisplayFormat f = gppl::parse_display_format("5.0(*10000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000)");
  EXPECT_THROW(gppl::format_value(f, integer(1000000000000)), gppl::Error);
}

struct Rounding {
  double value;
  int digits;
  double expected;
};

TEST(RoundHalfAway, DecimalRounding) {
  const Rounding cases[] = {
      {12.3456, 1, 12.3}, {12.3456, 3, 12.346}, {12.5, 0, 13.}, {-12.5, 0, -13.}, {123.4, -1, 120.},
      {126.4, -1, 130.},  {123, -3, 0.},        {2.675, 2, 2.68}, {-2.675, 2, -2.68}, {0.5, 0, 1.},
      {-0.4, 0, 0.},      {999.5, 0, 1000.},    {550., -2, 600.}, {1e300, 2, 1e300}, {0.0, 3, 0.},
      {1.23e-5, 400, 1.23e-5}, {5e-324, 400, 5e-324}, {5e-324, 300, 0.},
  };
  for (const auto& c : cases) EXPECT_EQ(gppl::round_half_away(c.value, c.digits), c.expected) << c.value << " @" << c.digits;
}

// Random format strings made of the format alphabet: parsing either succeeds or throws a
// numbered format error, and formatting a parsed format never crashes or overflows.
TEST(DisplayFormatFuzz, RandomStringsNeverCrash) {
  const std::string alphabet = "0123456789./+-zZ ()<>*dnpiDNPIq<>.,x";
  const Value values[] = {num(0.), num(-0.0004), num(123.456), num(-9.99e99), num(1e-300),
                          integer(0), integer(-7), integer(INT64_MAX), Value::of_logical(true)};
  std::mt19937 rng(20240601);
  int parsed = 0;
  for (int round = 0; round < 20000; ++round) {
    std::string spec;
    int length = static_cast<int>(rng() % 10);
    for (int i = 0; i < length; ++i) spec += alphabet[rng() % alphabet.size()];
    if (rng() % 2 == 0) spec = std::to_string(rng() % 120) + "." + std::to_string(rng() % 120) + spec;
    try {
      gppl::DisplayFormat f = gppl::parse_display_format(spec);
      ++parsed;
      for (const Value& v : values) {
        try {
          std::string out = gppl::format_value(f, v);
          EXPECT_LT(out.size(), 400u) << spec;
        } catch (const gppl::Error& e) {
          EXPECT_EQ(e.number(), 410) << spec;
        }
      }
    } catch (const gppl::Error& e) {
      int n = e.number();
      EXPECT_TRUE(n == 408 || n == 409 || n == 421 || n == 422 || n == 423) << spec << ": " << e.what();
    }
  }
  EXPECT_GT(parsed, 500);  // the generator reaches the formatter often enough
}

}  // namespace
