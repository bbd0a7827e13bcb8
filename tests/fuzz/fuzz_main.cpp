// One libFuzzer target; GLOBE_FUZZ_ENTRY names the globe::fuzz entry it drives (set by CMake).
#include <cstddef>
#include <cstdint>

#include "fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  globe::fuzz::GLOBE_FUZZ_ENTRY(data, size);
  return 0;
}
