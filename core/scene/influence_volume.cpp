#include "core/scene/influence_volume.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include <limits>

namespace probeproxy {

bool insideInfluence(const InfluenceVolume& influence, glm::dvec3 p) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dvec3 local = glm::conjugate(box->worldFromBox) * (p - box->centerMeters);
    return glm::all(glm::lessThanEqual(glm::abs(local), box->halfExtentsMeters));
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  return glm::distance(p, sphere.centerMeters) <= sphere.radiusMeters;
}

bool insideInnerRange(const InfluenceVolume& influence, glm::dvec3 p) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dvec3 local = glm::conjugate(box->worldFromBox) * (p - box->centerMeters);
    return glm::all(glm::lessThan(glm::abs(local), box->innerHalfExtentsMeters));
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  return glm::distance(p, sphere.centerMeters) < sphere.innerRadiusMeters;
}

void influenceBounds(const InfluenceVolume& influence, glm::dvec3& lo, glm::dvec3& hi) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dmat3 axes = glm::mat3_cast(box->worldFromBox);
    // Half-size of the rotated box along each world axis.
    const glm::dvec3 reach = glm::abs(axes[0]) * box->halfExtentsMeters.x +
                             glm::abs(axes[1]) * box->halfExtentsMeters.y +
                             glm::abs(axes[2]) * box->halfExtentsMeters.z;
    lo = box->centerMeters - reach;
    hi = box->centerMeters + reach;
    return;
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  lo = sphere.centerMeters - glm::dvec3(sphere.radiusMeters);
  hi = sphere.centerMeters + glm::dvec3(sphere.radiusMeters);
}

double influenceCubicMeters(const InfluenceVolume& influence) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dvec3& h = box->halfExtentsMeters;
    return 8.0 * h.x * h.y * h.z;
  }
  const double r = std::get<SphereInfluence>(influence).radiusMeters;
  return 4.0 / 3.0 * glm::pi<double>() * r * r * r;
}

void influenceBounds(std::span<const InfluenceVolume> volumes, glm::dvec3& lo, glm::dvec3& hi) {
  lo = glm::dvec3(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (const InfluenceVolume& v : volumes) {
    glm::dvec3 vLo, vHi;
    influenceBounds(v, vLo, vHi);
    lo = glm::min(lo, vLo);
    hi = glm::max(hi, vHi);
  }
}

}  // namespace probeproxy
