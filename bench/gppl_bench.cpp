// Benchmark of the GPPL interpreter: commands/s for the FANUC post's motion procedures, and the
// number of heap allocations in the steady state (should be 0).
// Usage: gppl_bench [commands] [post.gpp]   (Release build; default tests/gppl/data/fanuc.gpp)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>

#include "gppl/gppl.hpp"

namespace {

std::size_t allocations = 0;

struct CountingSink : gppl::OutputSink {
  std::size_t bytes = 0;
  std::size_t lines = 0;
  void write_line(std::string_view line, const gppl::LineOrigin&) override {
    bytes += line.size();
    ++lines;
  }
};

}  // namespace

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

int main(int argc, char** argv) {
  const long commands = argc > 1 ? std::atol(argv[1]) : 2'000'000;
  const std::string path = argc > 2 ? argv[2] : "tests/gppl/data/fanuc.gpp";
  auto program = gppl::compile_file(path, {});
  CountingSink sink;
  gppl::Interpreter run(program, sink);
  run.start();
  const auto line = *run.find_procedure("@line");
  const auto rapid = *run.find_procedure("@rapid_move");
  const gppl::VariableId x = run.add_variable("xpos"), y = run.add_variable("ypos"), z = run.add_variable("zpos"),
                         feed = run.add_variable("feed");
  auto step = [&](long i) {
    // A contour: x and y change every command, z rarely, feed never; every 50th command a rapid.
    // The typed assignments are the ones the engine uses for a command's numeric parameters.
    run.assign_numeric(x, double(i % 1000) * 0.137 - 50.0);
    run.assign_numeric(y, double(i % 777) * 0.291 + 3.5);
    run.assign_numeric(z, i % 50 == 0 ? 10.0 : -2.5);
    run.assign_numeric(feed, 800.0);
    run.call(i % 50 == 0 ? rapid : line);
  };
  for (long i = 0; i < 1000; ++i) step(i);  // warm up: buffers reach their steady size
  const std::size_t before = allocations;
  const auto start = std::chrono::steady_clock::now();
  for (long i = 0; i < commands; ++i) step(i);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.finish();
  std::printf("%ld commands in %.3f s: %.2f M commands/s, %.0f ns/command\n", commands, seconds,
              double(commands) / seconds / 1e6, seconds * 1e9 / double(commands));
  std::printf("%zu lines, %zu bytes; heap allocations in the timed loop: %zu\n", sink.lines, sink.bytes,
              allocations - before);
  return 0;
}
