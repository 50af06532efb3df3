// libFuzzer target: see fuzz::pikocnc_script in entries.hpp.
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::pikocnc_script({reinterpret_cast<const char*>(data), size});
  return 0;
}
