#include "geometry/raycast/floor_below.h"

namespace probeproxy {

std::optional<double> floorHeightBelow(const LevelRayCaster& level, const glm::dvec3& pointMeters,
                                       float maxDropMeters) {
  Ray down;
  down.originMeters = pointMeters;
  down.direction = {0.0f, 0.0f, -1.0f};
  down.tMax = maxDropMeters;
  const RayHit hit = level.firstHit(down);
  if (!hit.hit()) return std::nullopt;
  return pointMeters.z - double(hit.t);
}

}  // namespace probeproxy
