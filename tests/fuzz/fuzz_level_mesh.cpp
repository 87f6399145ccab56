// Level mesh files through the project's loader (geometry/level/load_level.h): one target per
// format, named by PROBEPROXY_FUZZ_EXTENSION (".gltf", ".glb", ".obj", ".ply", ".off"), since
// the loader picks its reader by the file's extension.
#include "fuzz_input.h"
#include "geometry/level/load_level.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace probeproxy;
  const auto file = fuzz::writeScratch(std::string("level") + PROBEPROXY_FUZZ_EXTENSION,
                                       fuzz::asText(data, size));
  return fuzz::refusedOrRead([&] { loadLevelMeshFile(file, UpAxis::Y, 1.0); });
}
