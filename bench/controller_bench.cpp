// Reads a long typical program of each registered controller (Controller::write_sample_program)
// back into stream commands, through the registry as `postproc read` does, and reports blocks and
// commands per second and peak memory. A controller added to the registry is benchmarked here
// without a line of its own.
// usage: controller_bench [BLOCKS=1000000] [NAME...]   (Release build; default: every controller)
#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/read_timing.hpp"
#include "machines/registry/registry.hpp"

int main(int argc, char** argv) {
  const std::size_t blocks = argc > 1 ? std::stoul(argv[1]) : 1'000'000;
  std::vector<const machines::Controller*> chosen;
  for (int i = 2; i < argc; ++i) {
    const machines::Controller* c = machines::find_controller(argv[i]);
    if (!c) {
      fmt::print(stderr, "unknown controller `{}` (known: {})\n", argv[i], machines::controller_names());
      return 2;
    }
    chosen.push_back(c);
  }
  if (chosen.empty())
    for (const machines::Controller* c : machines::controllers()) chosen.push_back(c);
  int status = 0;
  for (const machines::Controller* c : chosen) {
    const std::string name(c->names().front());
    const std::string path = fmt::format("/tmp/controller_bench.{}.nc", name);
    {
      std::ofstream out(path, std::ios::binary);
      if (!c->write_sample_program(out, blocks)) {
        fmt::print("{:<10} no sample program\n", name);
        continue;
      }
    }
    std::ostringstream warnings;
    try {
      auto reader = c->open(path, name, {}, warnings);
      const bench::ReadTiming t = bench::time_reading(*reader);
      fmt::print("{:<10} {} blocks, {} commands in {:.3f} s: {:.2f} M blocks/s, {:.2f} M commands/s; peak RSS {} kB; "
                 "checksum {:.3f}\n",
                 name, blocks, t.commands, t.seconds, static_cast<double>(blocks) / t.seconds / 1e6,
                 static_cast<double>(t.commands) / t.seconds / 1e6, bench::peak_rss_kb(), t.checksum);
    } catch (const std::exception& e) {
      fmt::print("{:<10} failed: {}\n", name, e.what());
      status = 1;
    }
    if (!warnings.str().empty()) fmt::print("{:<10} warnings:\n{}", "", warnings.str().substr(0, 2000));
    std::remove(path.c_str());
  }
  return status;
}
