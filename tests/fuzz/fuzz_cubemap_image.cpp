// One-image cubemaps (core/cube/cubemap_io.h readCubemapImage): horizontal or vertical cross,
// or equirectangular, told by the aspect ratio. Radiance .hdr: a float format OpenImageIO
// reads without a large decoder in the way, so the runs reach the layout and size checks.
#include "core/cube/cubemap_io.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace probeproxy;
  const auto file = fuzz::writeScratch("cube.hdr", fuzz::asText(data, size));
  return fuzz::refusedOrRead([&] { readCubemapImage(file); });
}
