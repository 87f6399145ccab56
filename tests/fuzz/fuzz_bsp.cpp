// Quake 3 BSP files (geometry/level/bsp/bsp_level.h), parsed from memory, then held to what the
// rest of probeproxy relies on: every point a level hands on (vertices, spawn points, lights)
// finite and within the scene limit. A parse that passes a spawn point at 1e20 m on is a
// finding here, not an Embree abort in `layout`.
#include "core/scene/scene_limits.h"
#include "fuzz_input.h"
#include "geometry/level/bsp/bsp_level.h"
#include "geometry/level/load_level.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <span>

namespace {

void requireWithinLimit(glm::dvec3 p, const char* what) {
  using probeproxy::kMaxSceneMeters;
  if (std::abs(p.x) <= kMaxSceneMeters && std::abs(p.y) <= kMaxSceneMeters &&
      std::abs(p.z) <= kMaxSceneMeters)
    return;
  std::fprintf(stderr, "%s at (%g, %g, %g) passed the reader\n", what, p.x, p.y, p.z);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace probeproxy;
  return fuzz::refusedOrRead([&] {
    const BspLevel bsp =
        parseBspLevel(std::span(reinterpret_cast<const std::byte*>(data), size), "fuzz.bsp");
    requireLevelWithinLimits("fuzz.bsp", bsp.mesh);  // as loadLevelMeshRef does next
    for (const BspSpawnPoint& s : bsp.spawnPoints)
      requireWithinLimit(s.originMeters, "a spawn point");
    for (const BspLight& l : bsp.lights) requireWithinLimit(l.originMeters, "a light");
  });
}
