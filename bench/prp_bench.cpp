// prp_bench [MOTIONS]: a synthetic arc-heavy job (half of its motions are quarter arcs) through
// prp::build_filter_chain with a typical PRP (the manual's fanuc.prp: quadrant splitting, arcs
// over 180 degrees halved, zero snapping, precision rounding, structure checks) and with one that
// linearises every arc. Prints commands per second and the peak resident memory after a short and
// a long run: equal peaks show that memory does not grow with the job.
#include <sys/resource.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>

#include <fmt/format.h>

#include "bench/synthetic_job.hpp"
#include "prp/prp.hpp"

namespace {

const char* kTypical = R"(@pre_processor
gen_procs = N
drill_proc = N
loop_exist = Y
abs_coord = N
comp_exist = Y
comp_by_zero_tool = N
arc_exist = Y
arc_3d = Y
arc_quadrants = Y
arc_gt_180 = N
arc_max_chord = 30.0000, 1.1811
arc_max_angle = 10.0000
arc_max_radius = 2000.0000, 78.7402
arc_min_length = 0.0000, 0.0000
arc_zx_yz = N
eps_angle = 0.0020, 0.0001
eps_line = 0.0010, 0.0000
zero_value = 0.0010, 0.0000
movement_precision = 0.0010, 0.0000
min_delt_arc_rad = 0.0100, 0.0004
endp
)";

const char* kLinearise = R"(@pre_processor
arc_exist = N
arc_max_chord = 0.5
arc_max_angle = 10
movement_precision = 0.001
endp
)";

long peak_kib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

void run(const char* label, const char* prp, std::size_t motions) {
  auto params = prp::load_source(prp, "bench.prp", prp::Units::Metric);
  bench::SyntheticJob job(motions);
  std::size_t warnings = 0;
  auto chain = prp::build_filter_chain(params, job, [&](const toolpath::Command&, const std::string&) { ++warnings; });
  toolpath::Command c;
  std::size_t out = 0;
  const auto start = std::chrono::steady_clock::now();
  while (chain->next(c)) ++out;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double in = static_cast<double>(motions + 9);
  std::cout << fmt::format("{:<22} {:>10} in {:>10} out {:8.3f} s {:>7.2f} M in/s {:>7.2f} M out/s  peak {:>7} KiB\n", label,
                           motions + 9, out, seconds, in / seconds / 1e6, static_cast<double>(out) / seconds / 1e6,
                           peak_kib());
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t motions = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 2'000'000;
  run("typical (short)", kTypical, motions / 10);
  run("typical", kTypical, motions);
  run("linearise (short)", kLinearise, motions / 10);
  run("linearise", kLinearise, motions);
  return 0;
}
