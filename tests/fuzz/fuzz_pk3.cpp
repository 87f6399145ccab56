// .pk3 archives (zip, read with libzip) holding the map maps/fuzz.bsp, as scenes name them.
#include "fuzz_input.h"
#include "geometry/level/bsp/bsp_level.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace probeproxy;
  const auto archive = fuzz::writeScratch("fuzz.pk3", fuzz::asText(data, size));
  return fuzz::refusedOrRead([&] { readBspLevel(archive, "maps/fuzz.bsp"); });
}
