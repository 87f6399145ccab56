// Quake 3 BSP files (geometry/level/bsp/bsp_level.h), parsed from memory.
#include "fuzz_input.h"
#include "geometry/level/bsp/bsp_level.h"

#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace probeproxy;
  return fuzz::refusedOrRead([&] {
    parseBspLevel(std::span(reinterpret_cast<const std::byte*>(data), size), "fuzz.bsp");
  });
}
