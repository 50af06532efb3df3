// The number grammar of 2XAxisCNC programs, as a table.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "machines/2xaxiscnc/numbers.hpp"

namespace {

using Status = twoaxis::Number::Status;

struct Case {
  const char* text;
  Status status;
  double value;
};

const Case kCases[] = {
    {"5,5", Status::Ok, 5.5},           {"-3", Status::Ok, -3},
    {"0,7", Status::Ok, 0.7},           {"-0,2455", Status::Ok, -0.2455},
    {"105", Status::Ok, 105},           {"+2", Status::Ok, 2},
    {"-0", Status::Ok, 0},              {"007,50", Status::Ok, 7.5},
    {"1.5", Status::NonPortable, 1.5},  {"1e2", Status::NonPortable, 100},
    {"2,5E-1", Status::NonPortable, 0.25},
    {"", Status::Malformed, 0},         {"-", Status::Malformed, 0},
    {",5", Status::Malformed, 0},       {"5,", Status::Malformed, 0},
    {"5,5,", Status::Malformed, 0},     {"1 2", Status::Malformed, 0},
    {"(Hello", Status::Malformed, 0},   {"1e", Status::Malformed, 0},
    {"--1", Status::Malformed, 0},      {"1,2,3", Status::Malformed, 0},
    {"0x10", Status::Malformed, 0},     {"inf", Status::Malformed, 0},
    {"1e39", Status::OutOfRange, 0},    {"-1e100", Status::OutOfRange, 0},
    {"3,40282357e38", Status::OutOfRange, 0},
    {"3,4028235e38", Status::NonPortable, 3.4028235e38},
};

TEST(TwoAxisNumbers, ParseTable) {
  for (const Case& c : kCases) {
    const auto n = twoaxis::parse_number(c.text);
    EXPECT_EQ(n.status, c.status) << '`' << c.text << '`';
    if (n.status == Status::Ok || n.status == Status::NonPortable) {
      EXPECT_DOUBLE_EQ(n.value, c.value) << c.text;
      EXPECT_FALSE(std::signbit(n.value) && n.value == 0) << c.text << ": -0";
    }
  }
}

TEST(TwoAxisNumbers, OverlongTextIsMalformed) {
  EXPECT_EQ(twoaxis::parse_number(std::string(65, '1')).status, Status::Malformed);
  EXPECT_EQ(twoaxis::parse_number(std::string(64, '1')).status, Status::OutOfRange);
}

TEST(TwoAxisNumbers, SinglePrecisionKeepsFourDecimalsBelow1024) {
  EXPECT_NEAR(twoaxis::as_single(1023.1234), 1023.1234, 0.00005);
  EXPECT_NEAR(twoaxis::as_single(100000.1234), 100000.125, 1e-9);  // beyond: the 4th decimal is lost
  EXPECT_EQ(twoaxis::tidy(twoaxis::as_single(0.7)), 0.7);
  EXPECT_EQ(twoaxis::tidy(-1e-7), 0.0);
  EXPECT_FALSE(std::signbit(twoaxis::tidy(-1e-7)));
}

}  // namespace
