#include "geometry/tune/snap_box_to_walls.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace probeproxy {

BoxShape snapBoxToWalls(const BoxShape& box, std::span<const ProxyPlane> walls,
                        double offsetToleranceMeters, double angleToleranceDeg) {
  const double cosTolerance = std::cos(angleToleranceDeg * M_PI / 180.0);
  const glm::dmat3 axes = glm::mat3_cast(box.worldFromBox);
  BoxShape snapped = box;
  for (int axis = 0; axis < 3; ++axis) {
    const glm::dvec3 u = axes[axis];
    const double centre = glm::dot(u, box.centerMeters);
    // Face offsets along u: the + face at centre + h, the - face (normal -u) at centre - h.
    const double fitHigh = centre + box.halfExtentsMeters[axis];
    const double fitLow = centre - box.halfExtentsMeters[axis];
    double high = fitHigh, low = fitLow;
    double bestHigh = offsetToleranceMeters, bestLow = offsetToleranceMeters;
    for (const ProxyPlane& wall : walls) {
      const double along = glm::dot(wall.normal, u);
      if (along >= cosTolerance && std::abs(wall.offsetMeters - fitHigh) < bestHigh) {
        bestHigh = std::abs(wall.offsetMeters - fitHigh);
        high = wall.offsetMeters;
      } else if (-along >= cosTolerance && std::abs(-wall.offsetMeters - fitLow) < bestLow) {
        bestLow = std::abs(-wall.offsetMeters - fitLow);
        low = -wall.offsetMeters;
      }
    }
    snapped.halfExtentsMeters[axis] = 0.5 * (high - low);
    snapped.centerMeters += (0.5 * (high + low) - centre) * u;
  }
  return snapped;
}

}  // namespace probeproxy
