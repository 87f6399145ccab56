// Scene files (geometry/scene/scene_file.h) as a user or another tool writes them.
#include "fuzz_input.h"
#include "geometry/scene/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace probeproxy;
  return fuzz::refusedOrRead([&] { parseSceneFile(fuzz::asText(data, size), "fuzz.scene.json"); });
}
