// libFuzzer target: see fuzz::tool_table in entries.hpp.
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::tool_table({reinterpret_cast<const char*>(data), size});
  return 0;
}
