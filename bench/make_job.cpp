// make_job [--procedures] N FILE: writes a synthetic job of N motion commands (@line/@arc) as a
// SolidCAM-layout trace, for the engine benchmark and for trying posts on long jobs. The job is
// flat (as SolidCAM sends it for gen_procs = N) unless --procedures asks for the shape it sends for
// gen_procs = Y (the job in procedure 1, called from the main program).
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string_view>

#include "bench/synthetic_job.hpp"
#include "toolpath/trace_writer.hpp"

int main(int argc, char** argv) {
  const bool procedures = argc == 4 && std::string_view(argv[1]) == "--procedures";
  if (argc != 3 && !procedures) {
    std::cerr << "usage: make_job [--procedures] MOTIONS FILE\n";
    return 2;
  }
  const char* count = argv[argc - 2];
  const char* path = argv[argc - 1];
  char* end = nullptr;
  unsigned long long motions = std::strtoull(count, &end, 10);
  if (*end != '\0' || end == count) {
    std::cerr << "make_job: MOTIONS must be a number\n";
    return 2;
  }
  std::ofstream out(path, std::ios::binary);
  if (!out) {
    std::cerr << "make_job: cannot write " << path << '\n';
    return 1;
  }
  bench::SyntheticJob job(motions, procedures ? bench::JobShape::procedures : bench::JobShape::flat);
  toolpath::TraceWriter writer(out);
  toolpath::Command c;
  while (job.next(c)) writer.write(c);
  writer.flush();
  return out ? 0 : 1;
}
