#include "geometry/raycast/open_space.h"

#include <limits>

namespace probeproxy {

std::vector<VerticalView> lookUpAndDown(const LevelRayCaster& level,
                                        std::span<const glm::dvec3> pointsMeters) {
  std::vector<Ray> rays(2 * pointsMeters.size());
  for (std::size_t i = 0; i < pointsMeters.size(); ++i) {
    rays[2 * i] = {pointsMeters[i], {0, 0, -1}};
    rays[2 * i + 1] = {pointsMeters[i], {0, 0, 1}};
  }
  std::vector<RayHit> hits(rays.size());
  level.firstHits(rays, hits, true);
  std::vector<VerticalView> views(pointsMeters.size());
  for (std::size_t i = 0; i < views.size(); ++i) {
    const RayHit& down = hits[2 * i];
    const RayHit& up = hits[2 * i + 1];
    VerticalView& v = views[i];
    v.insideSolid =
        (up.hit() && up.geometricNormal.z > 0.5f) || (down.hit() && down.geometricNormal.z < -0.5f);
    const bool floorBelow = down.hit() && down.geometricNormal.z > 0.5f && !v.insideSolid;
    v.floorBelowMeters = floorBelow ? down.t : std::numeric_limits<float>::infinity();
  }
  return views;
}

}  // namespace probeproxy
