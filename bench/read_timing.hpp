// What the controller-reader benchmarks share: peak memory from /proc, and one timed pass of a
// reader over its program (commands counted, a checksum so the work cannot be optimised away).
#pragma once

#include <chrono>
#include <fstream>
#include <string>

#include "toolpath/command.hpp"

namespace bench {

inline long peak_rss_kb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  long value = 0;
  while (status >> key) {
    if (key == "VmHWM:") {
      status >> value;
      return value;
    }
    status.ignore(256, '\n');
  }
  return 0;
}

struct ReadTiming {
  long commands = 0;
  double seconds = 0;
  double checksum = 0;
};

template <class Reader>
ReadTiming time_reading(Reader& reader) {
  ReadTiming t;
  const auto t0 = std::chrono::steady_clock::now();
  toolpath::Command c;
  while (reader.next(c)) {
    ++t.commands;
    if (!c.parameters.empty()) t.checksum += c.parameters.front().value.as_number();
  }
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return t;
}

}  // namespace bench
