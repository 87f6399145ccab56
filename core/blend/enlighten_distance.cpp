#include "core/blend/enlighten_distance.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace probeproxy {

double enlightenDistanceSq(const InfluenceVolume& influence, glm::dvec3 p) {
  glm::dvec3 local;
  glm::dvec3 halfExtents;
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    local = glm::conjugate(box->worldFromBox) * (p - box->centerMeters);
    halfExtents = box->halfExtentsMeters;
  } else {
    const auto& sphere = std::get<SphereInfluence>(influence);
    local = p - sphere.centerMeters;
    halfExtents = glm::dvec3(sphere.radiusMeters);
  }
  // The seed's CalcDistanceSqToClosestPointInHalfExtents.
  const glm::dvec3 d = glm::clamp(local, -halfExtents, halfExtents) - local;
  return glm::dot(d, d);
}

}  // namespace probeproxy
