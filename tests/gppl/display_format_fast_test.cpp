// The fast display-format printer against the exact one (library digits, the reference): a large
// deterministic table of tricky values (halves at every decimal count, neighbours of powers of
// ten, negative zero, 1e15 and beyond, tiny values, random doubles with a fixed seed) for every
// format shape. Any difference, even one byte, fails.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "gppl/builtins/display_format.hpp"
#include "gppl/builtins/display_format_internal.hpp"

namespace {

using gppl::Value;

double decimal(const std::string& text) {
  double v = 0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}

void add_with_neighbours(std::vector<double>& out, double v) {
  out.push_back(v);
  out.push_back(std::nextafter(v, 0.0));
  out.push_back(std::nextafter(v, std::numeric_limits<double>::infinity()));
}

// Non-negative magnitudes; the tables below also use their negatives.
std::vector<double> tricky_magnitudes() {
  std::vector<double> v = {0.0, 1e15, 1e15 + 1, 999999999999999.0, 1e16, 4503599627370496.0,
                           9007199254740992.0, 9007199254740993.0, 1e20, 1e22, 1e50, 1e100,
                           1e-300, 5e-324, 2.2250738585072014e-308, 1e-16, 1e-9, 4.9999999999999996e-4,
                           0.1 + 0.2, 1.0005, 2.675, 1.005, 1.015, 1.025, 8.345, 1234.5675, 0.45,
                           0.049999999999999996, 123456789.123456789, 0.3, 0.7, 9.9995, 99.9995};
  // Halves at every decimal count: k.5 * 10^-d and digit strings ending in 5, and their neighbours.
  for (int d = 0; d <= 17; ++d) {
    for (const char* mantissa : {"5", "15", "25", "35", "45", "125", "675", "2675", "9995", "99995", "12345",
                                 "123455", "1000005", "44444445", "999999995", "123456789012345"}) {
      add_with_neighbours(v, decimal(std::string(mantissa) + "e-" + std::to_string(d + 1)));
    }
  }
  // Powers of ten, just below them and the values that round up into them.
  for (int k = -12; k <= 17; ++k) {
    double p = decimal("1e" + std::to_string(k));
    add_with_neighbours(v, p);
    for (int d = 0; d <= 8; ++d) {
      add_with_neighbours(v, p - decimal("5e-" + std::to_string(d + 1)));
      add_with_neighbours(v, p - decimal("4e-" + std::to_string(d + 1)));
    }
  }
  // Double rounding: 16+ digits that the 15-digit step turns into an exact half one to six places
  // above the 15th digit ("...4 9 5" -> "...5 0"), so rounding the raw value and rounding its 15
  // digits differ. These sit right at the fast path's safety margin.
  for (const char* lead : {"1", "3", "9"}) {
    for (int k = 1; k <= 6; ++k) {
      std::string digits = std::string(lead) + std::string(static_cast<std::size_t>(14 - k), '0') + "4" +
                           std::string(static_cast<std::size_t>(k - 1), '9') + "51";
      for (int e = -10; e <= 16; ++e) add_with_neighbours(v, decimal(digits + "e" + std::to_string(e - 16)));
    }
  }
  return v;
}

// `scale` times as many random values as the base set: CAM-like decimals, arithmetic noise,
// random magnitudes and random bit patterns (fixed seed, so every run checks the same values).
std::vector<double> random_magnitudes(int scale) {
  std::vector<double> v;
  std::mt19937_64 rng(20240617);
  // Coordinates the way a CAM system writes them: up to 8 decimals, magnitudes up to 1e6.
  for (int i = 0; i < 300 * scale; ++i) {
    std::int64_t digits = static_cast<std::int64_t>(rng() % 100'000'000'000'000);
    int scale = static_cast<int>(rng() % 9);
    v.push_back(decimal(std::to_string(digits) + "e-" + std::to_string(scale)) * (i % 2 == 0 ? 1.0 : 1e-3));
  }
  // Arithmetic noise around short decimals (sums, products, unit conversion).
  for (int i = 0; i < 200 * scale; ++i) {
    double a = static_cast<double>(rng() % 2'000'000) / 1000.0;
    v.push_back(a * 1.0001);
    v.push_back(a / 25.4);
    v.push_back(a + 0.1);
  }
  // Random magnitudes over the whole printable range, and random bit patterns.
  std::uniform_real_distribution<double> exponent(-20.0, 20.0);
  for (int i = 0; i < 200 * scale; ++i) v.push_back(std::pow(10.0, exponent(rng)));
  for (int i = 0; i < 100 * scale; ++i) {
    std::uint64_t bits = rng();
    double x = 0;
    std::memcpy(&x, &bits, sizeof x);
    x = std::fabs(x);
    if (x <= 1e100) v.push_back(x);
  }
  return v;
}

std::vector<double> magnitudes(int random_scale) {
  std::vector<double> v = tricky_magnitudes();
  for (double m : random_magnitudes(random_scale)) v.push_back(m);
  for (double& m : v) m = std::fabs(m);  // "power minus a half" goes negative for small powers
  return v;
}

std::string shortest(double v) {
  char buf[40];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

std::string without_leading_zeros(const std::string& s) {
  std::size_t first = s.find_first_not_of('0');
  return first == std::string::npos ? "0" : s.substr(first);
}

// The decision itself: whenever the fast rounding answers, its integer equals the reference's
// digits (printed with no point and every decimal), for every N it handles.
TEST(FastRounding, AgreesWithTheExactDigitsAtEveryDecimalCount) {
  const std::vector<double> all = magnitudes(10);
  long decided = 0, total = 0;
  for (int n = 0; n <= gppl::fast::max_fraction; ++n) {
    const gppl::DisplayFormat digits_only = gppl::parse_display_format("0/0." + std::to_string(n) + "z(n)");
    for (double m : all) {
      std::uint64_t units = 0;
      ++total;
      if (!gppl::fast::round_to_units(m, n, units)) continue;
      ++decided;
      std::string expected;
      gppl::exact::format_reference(expected, digits_only, Value::of_numeric(m));
      ASSERT_EQ(std::to_string(units), without_leading_zeros(expected)) << shortest(m) << " at " << n << " decimals";
    }
  }
  EXPECT_GT(decided, total / 2);  // the fast path does decide most values
}

// One format of every shape the grammar allows, and the shipped posts' formats.
std::vector<std::string> format_shapes() {
  std::vector<std::string> shapes = {
      "5.3", "<X> 5.3", "5.3(p)", "<X> 5.3(p)", "<X>5.3<;>", "4.3(p)", "5.0(p)", "2.0(p)", "5.1(p)", "5.3/1",
      " 5.3z", " 5.3z(n)", "+5.0(/2.54i)", "+5.0(*100)", "8/5.7/4", "<X> 5.2 (p)", "5.3 ", "5.2/3", "+ 4.1",
      " +4.1", "z5.3", "Z4.0(p)", "5/0.3", "5/0.3(p)", "5/0.3 ", "5/0.0", "5/0.0(p)", "5.3(d)", "<X>5.0(d)<;>",
      "5.3(*1000p)", "5.1(*-1.5)", "5.3(/4*2)", "5.3(*.5)", "2/2.0(p)", "z2.0(n)", "5.3(n)", "5.3z(p)",
      "5.3(pi)", "+5.3(i)", " 3.0(p)", "1.4(/25.4)", "5.4(*25.4)", "+z9/3.4/2z", "99.3", "5/99.2", "5.99z",
      "5.3(*2*2*2*2*2/4)"};
  for (int n : {0, 1, 2, 3, 4, 6, 9, 13, 14, 15, 16, 18}) {
    const std::string N = std::to_string(n);
    for (const char* shape : {"5.N", "5.Nz", "5.N(p)", "0/0.N(p)", "5.N ", "+ 9/2.N/1", "z5.Nz(n)", "1.N(d)"}) {
      std::string s = shape;
      s.replace(s.find('N'), 1, N);
      shapes.push_back(s);
    }
  }
  return shapes;
}

std::string describe(const Value& v) {
  return v.type == gppl::Type::Numeric ? shortest(v.numeric) : std::to_string(v.type == gppl::Type::Logical ? v.logical : v.integer);
}

// The printed text (or the error number) through a printer.
template <typename Printer>
std::string printed(Printer print, const gppl::DisplayFormat& f, const Value& v) {
  std::string out = "[";
  try {
    print(out, f, v);
  } catch (const gppl::Error& e) {
    out += "error " + std::to_string(e.number());
  }
  return out;
}

TEST(FastPrinter, MatchesTheExactPrinterForEveryShape) {
  std::vector<Value> values;
  for (double m : magnitudes(1)) {
    values.push_back(Value::of_numeric(m));
    values.push_back(Value::of_numeric(-m));
  }
  std::mt19937_64 rng(7);
  for (std::int64_t i : {std::int64_t{0}, std::int64_t{1}, std::int64_t{-1}, std::int64_t{999'999'999},
                         std::int64_t{-999'999'999}, std::int64_t{1'000'000'000'000'000}, INT64_MAX, INT64_MIN})
    values.push_back(Value::of_integer(i));
  for (int i = 0; i < 500; ++i) values.push_back(Value::of_integer(static_cast<std::int64_t>(rng()) >> (rng() % 64)));
  values.push_back(Value::of_logical(true));
  values.push_back(Value::of_logical(false));

  for (const std::string& shape : format_shapes()) {
    const gppl::DisplayFormat f = gppl::parse_display_format(shape);
    for (const Value& v : values) {
      const std::string expected = printed(gppl::exact::format_reference, f, v);
      const std::string actual = printed(gppl::append_formatted, f, v);
      ASSERT_EQ(actual, expected) << "format '" << shape << "', value " << describe(v);
    }
  }
}


// The quick path (DisplayFormat::quick) on its own: every value it takes must print exactly as
// the reference does, and it must take the values it is there for (short decimals, integers
// below 10^6 under the shipped posts' formats).
std::vector<Value> quick_candidates() {
  std::vector<Value> values;
  for (std::int64_t i = -2000; i <= 2000; ++i) values.push_back(Value::of_integer(i));
  for (std::int64_t edge : {std::int64_t{999}, std::int64_t{1000}, std::int64_t{1001}, std::int64_t{9999},
                            std::int64_t{10000}, std::int64_t{99999}, std::int64_t{100000}, std::int64_t{999999},
                            std::int64_t{1000000}, std::int64_t{1000001}, INT64_MAX}) {
    values.push_back(Value::of_integer(edge));
    values.push_back(Value::of_integer(-edge));
  }
  values.push_back(Value::of_integer(INT64_MIN));
  std::mt19937_64 rng(14);
  for (int i = 0; i < 20000; ++i) values.push_back(Value::of_integer(static_cast<std::int64_t>(rng() % 2'400'000) - 1'200'000));
  // Decimals as a CAM system writes them (up to four places, so that N = 3 rounds some), their
  // halves and neighbours, and the values that round up to the next thousand or million.
  for (int i = 0; i < 40000; ++i) {
    const std::int64_t digits = static_cast<std::int64_t>(rng() % 20'000'000'000) - 10'000'000'000;
    const double x = decimal(std::to_string(digits) + "e-4");
    values.push_back(Value::of_numeric(x));
    values.push_back(Value::of_numeric(std::nextafter(x, 0.0)));
  }
  for (double m : {0.0, 0.0005, 0.05, 0.5, 0.4999999999, 999.9995, 999.9994, 999999.9995, 999999.9994, 999999.4,
                   999999.5, 1e6, 99999.99951, 1.0005, 2.675, 1234.5675, 0.001, 0.0004999}) {
    for (double x : {m, -m, std::nextafter(m, 0.0), std::nextafter(m, 1e9)}) {
      values.push_back(Value::of_numeric(x));
      values.push_back(Value::of_numeric(-x));
    }
  }
  values.push_back(Value::of_numeric(-0.0));
  values.push_back(Value::of_numeric(std::numeric_limits<double>::quiet_NaN()));
  values.push_back(Value::of_numeric(std::numeric_limits<double>::infinity()));
  values.push_back(Value::of_logical(true));
  return values;
}

TEST(QuickPrinter, MatchesTheExactPrinterWhereverItAnswers) {
  const std::vector<Value> values = quick_candidates();
  long quick_formats = 0;
  for (const std::string& shape : format_shapes()) {
    const gppl::DisplayFormat f = gppl::parse_display_format(shape);
    if (!f.quick) continue;
    ++quick_formats;
    long answered = 0;
    for (const Value& v : values) {
      char buf[gppl::formatted_room];
      const char* end = gppl::fast::write_quick(buf, f, v);
      if (end == nullptr) continue;
      ++answered;
      std::string expected;
      gppl::exact::format_reference(expected, f, v);
      ASSERT_EQ(std::string(buf, static_cast<std::size_t>(end - buf)), expected) << "format '" << shape << "', value " << describe(v);
    }
    // Halves at the last place (a tenth of the four-place decimals under N = 3) go to the exact path.
    EXPECT_GT(answered, static_cast<long>(values.size()) * 8 / 10) << "format '" << shape << "'";
  }
  EXPECT_GE(quick_formats, 10);
}

TEST(QuickPrinter, TakesOnlyThePlainShapesWithoutScalesAndAtMostThreeDecimals) {
  for (const char* shape : {"5.3", "5.0(p)", "2.0(p)", "5.1(p)", "<X>5.3<;>", "<X> 5.3(p)", "4.3(p)", "5.2", "5/1.3"})
    EXPECT_TRUE(gppl::parse_display_format(shape).quick) << shape;
  for (const char* shape : {"5.4", "5.3(i)", "5.3(*2)", "5.3/1", "+5.3", " 5.3z", "z5.3", "5.3(n)", "5.3(d)", "5/0.3", "2/2.0(p)"})
    EXPECT_FALSE(gppl::parse_display_format(shape).quick) << shape;
}

// write_formatted() for a bare integer (block numbers) against the Value overload's reference,
// through the quick path and the general one.
TEST(QuickPrinter, TheIntegerOverloadMatchesTheReference) {
  std::vector<std::int64_t> integers;
  for (const Value& v : quick_candidates())
    if (v.type == gppl::Type::Integer) integers.push_back(v.integer);
  for (const std::string& shape : format_shapes()) {
    const gppl::DisplayFormat f = gppl::parse_display_format(shape);
    for (std::int64_t i : integers) {
      const Value v = Value::of_integer(i);
      const std::string expected = printed(gppl::exact::format_reference, f, v);
      const std::string actual = printed([i](std::string& out, const gppl::DisplayFormat& fmt, const Value&) {
        char buf[gppl::formatted_room];
        const char* end = gppl::write_formatted(buf, fmt, i);
        out.append(buf, static_cast<std::size_t>(end - buf));
      }, f, v);
      ASSERT_EQ(actual, expected) << "format '" << shape << "', value " << i;
    }
  }
}

}  // namespace
