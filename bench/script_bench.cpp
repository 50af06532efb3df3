// PikoCNC scripts: a script that writes N G-code lines (default 1,000,000), timed end to end
// (parse + run + formatting; the output is counted, not stored). script_bench [LINES]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <streambuf>
#include <string>

#include "machines/pikocnc/script/script.hpp"

namespace {

struct CountingBuffer : std::streambuf {
  std::size_t bytes = 0;
  int overflow(int c) override {
    ++bytes;
    return c;
  }
  std::streamsize xsputn(const char*, std::streamsize n) override {
    bytes += std::size_t(n);
    return n;
  }
};

}  // namespace

int main(int argc, char** argv) {
  const long lines = argc > 1 ? std::atol(argv[1]) : 1'000'000;
  // A helix of small segments: trigonometry, arithmetic, a procedure call and four words a line.
  const std::string text = R"(var i: Integer; a: Extended;
procedure Point(a, z: Extended);
begin
  SetX(CirPointX(50, a)); SetY(CirPointY(50, a)); SetZ(z); Write;
end;
begin
  SetG(0); SetX(50); SetY(0); Write;
  SetG(1); SetF(1200); Write;
  for i := 1 to )" + std::to_string(lines - 3) + R"( do begin
    a := i * 0.36;
    Point(a, -1 - (i mod 100) * 0.01);
  end;
end.
)";
  CountingBuffer counter;
  std::ostream out(&counter), diag(nullptr);
  pikocnc::script::RunInputs inputs;
  inputs.max_steps = ~std::uint64_t(0);
  const auto start = std::chrono::steady_clock::now();
  const auto result = pikocnc::script::run_script_text(text, "bench.pas", inputs, out, diag);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("script_bench: %llu lines (%zu bytes, %llu statements) in %.2f s: %.2f M lines/s\n",
              static_cast<unsigned long long>(result.lines), counter.bytes,
              static_cast<unsigned long long>(result.steps), seconds, double(result.lines) / seconds / 1e6);
  return 0;
}
