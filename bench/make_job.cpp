// make_job N FILE: writes a synthetic job of N motion commands (@line/@arc) as a SolidCAM-layout
// trace, for the engine benchmark and for trying posts on long jobs.
#include <cstdlib>
#include <fstream>
#include <iostream>

#include "bench/synthetic_job.hpp"
#include "toolpath/trace_writer.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: make_job MOTIONS FILE\n";
    return 2;
  }
  char* end = nullptr;
  unsigned long long motions = std::strtoull(argv[1], &end, 10);
  if (*end != '\0') {
    std::cerr << "make_job: MOTIONS must be a number\n";
    return 2;
  }
  std::ofstream out(argv[2], std::ios::binary);
  if (!out) {
    std::cerr << "make_job: cannot write " << argv[2] << '\n';
    return 1;
  }
  bench::SyntheticJob job(motions);
  toolpath::TraceWriter writer(out);
  toolpath::Command c;
  while (job.next(c)) writer.write(c);
  writer.flush();
  return out ? 0 : 1;
}
