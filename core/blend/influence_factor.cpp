#include "core/blend/influence_factor.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

namespace {

// One axis (or the sphere's radius): where `reach` lies between the inner and outer range.
double rangeFraction(double reach, double inner, double outer) {
  if (reach >= outer) return 1.0;
  if (reach <= inner) return 0.0;
  return (reach - inner) / (outer - inner);  // outer > inner here
}

}  // namespace

double normalizedDistance(const InfluenceVolume& influence, glm::dvec3 p) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dvec3 local = glm::abs(glm::conjugate(box->worldFromBox) * (p - box->centerMeters));
    double factor = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      factor *= 1.0 - rangeFraction(local[axis], box->innerHalfExtentsMeters[axis],
                                    box->halfExtentsMeters[axis]);
    }
    return 1.0 - factor;
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  return rangeFraction(glm::distance(p, sphere.centerMeters), sphere.innerRadiusMeters,
                       sphere.radiusMeters);
}

double influenceFactor(const InfluenceVolume& influence, glm::dvec3 p) {
  return 1.0 - normalizedDistance(influence, p);
}

bool coversPoint(const InfluenceVolume& influence, glm::dvec3 p) {
  return normalizedDistance(influence, p) < 1.0;
}

}  // namespace probeproxy
