#include <iostream>
#include <string>
#include <vector>

#include "postproc/cli/cli.hpp"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  std::vector<std::string> args(argv + 1, argv + argc);
  return postproc::cli::main(args, std::cout, std::cerr);
}
