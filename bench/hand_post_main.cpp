// hand_post JOB.trace OUT.nc: the hand-written Fanuc post (bench/hand_post.hpp) as a program of its
// own, which ceiling_bench starts beside `postproc run` so that both pay for starting a process.
#include <exception>
#include <iostream>

#include "bench/hand_post.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: hand_post JOB.trace OUT.nc\n";
    return 2;
  }
  try {
    bench::hand_post::post_file(argv[1], argv[2]);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
}
