#include "geometry/level/bsp/bsp_surface_flags.h"

namespace probeproxy {

BspSurfaceKind classifyBspShader(std::uint32_t surfaceFlags, std::uint32_t contentFlags) {
  // Sky first: a sky shader carries other flags too (noimpact, nomarks, nolightmap...), and
  // whatever else it is, a reflection that reaches it shows the sky.
  if (surfaceFlags & kSurfSky) return BspSurfaceKind::Sky;
  if (surfaceFlags & kSkippedSurfaceFlags) return BspSurfaceKind::Skipped;
  if (contentFlags & kSkippedContentFlags) return BspSurfaceKind::Skipped;
  return BspSurfaceKind::Solid;
}

}  // namespace probeproxy
