// Microbenchmark of GPPL display formats and a few internal functions.
// Usage: format_bench [iterations]   (Release build; prints nanoseconds per operation)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "gppl/builtins/display_format.hpp"
#include "gppl/builtins/functions.hpp"

namespace {

using Clock = std::chrono::steady_clock;

template <typename Body>
void measure(const char* what, long iterations, Body body) {
  auto start = Clock::now();
  std::size_t sink = 0;
  for (long i = 0; i < iterations; ++i) sink += body(i);
  double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count() / static_cast<double>(iterations);
  std::printf("%-44s %8.1f ns/op   (checksum %zu)\n", what, ns, sink);
}

// Coordinates the way a toolpath produces them: varied magnitudes and fractions.
std::vector<gppl::Value> coordinates() {
  std::vector<gppl::Value> v;
  std::srand(42);
  for (int i = 0; i < 4096; ++i) v.push_back(gppl::Value::of_numeric((std::rand() % 2000000 - 1000000) / 1000.0 * 1.0001));
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  long n = argc > 1 ? std::atol(argv[1]) : 2'000'000;
  const auto values = coordinates();
  const std::size_t mask = values.size() - 1;
  std::string line;
  line.reserve(256);

  measure("parse_display_format('<X> 5.3(p)')", n, [](long) { return gppl::parse_display_format("<X> 5.3(p)").frac_digits; });

  struct Case {
    const char* label;
    const char* format;
  };
  const Case cases[] = {{"format numeric '5.3'", "5.3"},
                        {"format numeric '<X> 5.3(p)'", "<X> 5.3(p)"},
                        {"format numeric ' 5.3z'", " 5.3z"},
                        {"format numeric '+5.0(/2.54i)'", "+5.0(/2.54i)"},
                        {"format numeric '8/5.7/4'", "8/5.7/4"}};
  for (const auto& c : cases) {
    const gppl::DisplayFormat f = gppl::parse_display_format(c.format);
    measure(c.label, n, [&](long i) {
      line.clear();
      gppl::append_formatted(line, f, values[static_cast<std::size_t>(i) & mask]);
      return line.size();
    });
  }
  const gppl::DisplayFormat int_format = gppl::parse_display_format("5.0(p)");
  measure("format integer '5.0(p)'", n, [&](long i) {
    line.clear();
    gppl::append_formatted(line, int_format, gppl::Value::of_integer(i % 100000));
    return line.size();
  });

  const auto* sin = gppl::find_function("sin");
  const auto* round = gppl::find_function("round");
  const auto* tostr = gppl::find_function("tostr");
  measure("call sin(x)", n, [&](long i) {
    gppl::Value arg = values[static_cast<std::size_t>(i) & mask];
    return static_cast<std::size_t>(gppl::call_function(*sin, {&arg, 1}).numeric > 0);
  });
  measure("call round(x, 2)", n, [&](long i) {
    gppl::Value args[] = {values[static_cast<std::size_t>(i) & mask], gppl::Value::of_integer(2)};
    return static_cast<std::size_t>(gppl::call_function(*round, args).numeric > 0);
  });
  measure("call tostr(x : '5.3')", n, [&](long i) {
    gppl::Value args[] = {values[static_cast<std::size_t>(i) & mask], gppl::Value::of_string("5.3")};
    return gppl::call_function(*tostr, args).text.size();
  });
  return 0;
}
