// The trace writer's number text against the reference (fmt's shortest "{}" and the ".0" rule):
// values as the controller models round them (a nanometre), every decimal count up to seventeen,
// the edges of the fast path (1e-4, 1e6, fifteen digits), neighbours of all of them, zeros,
// infinities and random doubles with a fixed seed. Any difference, even one byte, fails.
#include <gtest/gtest.h>

#include <charconv>
#include <cstdio>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "toolpath/number_text.hpp"

namespace {

double decimal(const std::string& text) {
  double v = 0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}

void add_with_neighbours(std::vector<double>& out, double v) {
  for (double x : {v, std::nextafter(v, 0.0), std::nextafter(v, std::numeric_limits<double>::infinity()),
                   std::nextafter(v, -std::numeric_limits<double>::infinity())}) {
    out.push_back(x);
    out.push_back(-x);
  }
}

std::string hex(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%a", v);
  return b;
}

// The controller models' rounding (pikocnc::clean and the ISO models' own): to a nanometre.
double nanometre(double v) { return std::round(v * 1e9) / 1e9; }

std::vector<double> table() {
  std::vector<double> v;
  for (double x : {0.0, 1e-4, 1e-5, 9.9999e-5, 0.00010000000000000002, 1e6, 999999.999999999, 999999.9999999999,
                   1e15, 1e16, 1e20, 1e-9, 5e-324, 2.2250738585072014e-308, 1.7976931348623157e308, 0.1 + 0.2,
                   1.030946749, 101.458163501, 29.99856456, -45.4760057628, 0.5, 1.0, 800.0, 123456.789012345,
                   12345.6789012345, 99999.9999999995, 0.000123456789, 0.0001234567891})
    add_with_neighbours(v, x);
  // Every decimal count, and digit strings up to seventeen digits at every exponent of the range.
  for (int e = -12; e <= 8; ++e)
    for (const char* digits : {"1", "5", "9", "15", "99", "125", "999", "1234", "99995", "123456", "999999",
                               "1234567", "12345678", "123456789", "999999999", "1234567891", "123456789012",
                               "999999999999999", "123456789012345", "1234567890123456", "12345678901234567"})
      add_with_neighbours(v, decimal(std::string(digits) + "e" + std::to_string(e)));
  // Powers of ten and what lies just below them.
  for (int k = -10; k <= 17; ++k) {
    const double p = decimal("1e" + std::to_string(k));
    add_with_neighbours(v, p);
    for (int d = 1; d <= 12; ++d) add_with_neighbours(v, p - decimal("1e-" + std::to_string(d)));
  }
  std::mt19937_64 rng(20250125);
  // Model outputs: random coordinates rounded to a nanometre, at every magnitude of a machine.
  for (int i = 0; i < 400000; ++i) {
    const double scale = std::pow(10.0, static_cast<double>(static_cast<int>(rng() % 15)) - 6);
    const double x = (static_cast<double>(rng() >> 11) / 9007199254740992.0 - 0.5) * scale;
    v.push_back(nanometre(x));
    v.push_back(x);
  }
  // Decimals of 1 to 9 places with up to fifteen digits, as a program writes them.
  for (int i = 0; i < 200000; ++i) {
    const int places = 1 + static_cast<int>(rng() % 12);
    const std::uint64_t n = rng() % 1000000000000000ull;
    v.push_back(static_cast<double>(n) / std::pow(10.0, places));
    v.push_back(decimal(std::to_string(n) + "e-" + std::to_string(places)));
  }
  // Coordinates as a program writes them: up to four decimals, an integer part of up to six digits
  // (below 10 000, and around it, most often): the shortest of the fast path's forms.
  for (int i = 0; i < 200000; ++i) {
    const int places = static_cast<int>(rng() % 5);
    const std::uint64_t n = rng() % (rng() % 4 == 0 ? 10000000000ull : 100000000ull) / (rng() % 3 == 0 ? 1 : 10000);
    v.push_back(decimal(std::to_string(n) + "e-" + std::to_string(places)));
    v.push_back(decimal(std::to_string(n + 99990000) + "e-" + std::to_string(places)));
  }
  // Any bit pattern.
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    v.push_back(x);
  }
  v.push_back(std::numeric_limits<double>::infinity());
  v.push_back(-std::numeric_limits<double>::infinity());
  v.push_back(std::numeric_limits<double>::quiet_NaN());
  return v;
}

TEST(NumberText, SameBytesAsTheReference) {
  std::size_t failures = 0;
  for (const double x : table()) {
    char buffer[toolpath::kMaxNumberText + 8];
    char* end = toolpath::write_number_text(buffer, x);
    ASSERT_LE(static_cast<std::size_t>(end - buffer), toolpath::kMaxNumberText);
    const std::string fast(buffer, static_cast<std::size_t>(end - buffer));
    const std::string exact = toolpath::number_text_exact(x);
    if (fast != exact && ++failures <= 20)
      ADD_FAILURE() << "value " << hex(x) << ": fast `" << fast << "`, exact `" << exact << "`";
  }
  EXPECT_EQ(failures, 0u);
}

TEST(NumberText, Forms) {
  auto text = [](double x) {
    char buffer[toolpath::kMaxNumberText];
    return std::string(buffer, toolpath::write_number_text(buffer, x));
  };
  EXPECT_EQ(text(0.0), "0.0");
  EXPECT_EQ(text(-0.0), "-0.0");
  EXPECT_EQ(text(10.0), "10.0");
  EXPECT_EQ(text(-1.0), "-1.0");
  EXPECT_EQ(text(0.025), "0.025");
  EXPECT_EQ(text(1.030946749), "1.030946749");
  EXPECT_EQ(text(-45.4760057628), "-45.4760057628");
  EXPECT_EQ(text(0.0001), "0.0001");
  EXPECT_EQ(text(0.00001), "1e-05");
  EXPECT_EQ(text(1e20), "1e+20");
  EXPECT_EQ(text(1e15), "1000000000000000.0");
  EXPECT_EQ(text(0.1 + 0.2), "0.30000000000000004");
}

}  // namespace
