// libFuzzer target: see fuzz::pikocnc in entries.hpp.
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::pikocnc({reinterpret_cast<const char*>(data), size});
  return 0;
}
