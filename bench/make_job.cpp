// make_job [--procedures] N FILE: writes a synthetic job of N motion commands (@line/@arc) as a
// SolidCAM-layout trace, for the engine benchmark and for trying posts on long jobs. The job is
// flat (as SolidCAM sends it for gen_procs = N) unless --procedures asks for the shape it sends for
// gen_procs = Y (the job in procedure 1, called from the main program).
#include <cstdlib>
#include <iostream>
#include <string_view>

#include "bench/synthetic_job.hpp"

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
  try {
    bench::write_job(path, motions, procedures ? bench::JobShape::procedures : bench::JobShape::flat);
  } catch (const std::exception& e) {
    std::cerr << "make_job: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
