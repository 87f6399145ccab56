#include "geometry/export/engine_probes.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

namespace {

constexpr double kSmallestFalloff = 1e-8;      // EEVEE_lightprobes_cube_data_from_object's clamp
constexpr double kSmallestScaleMeters = 0.01;  // a capture point on the range's face

// How far a box's farthest face is from a point along a unit direction.
double reachAlong(const BoxShape& box, glm::dvec3 from, glm::dvec3 direction) {
  double reach = glm::dot(box.centerMeters - from, direction);
  for (int axis = 0; axis < 3; ++axis) {
    glm::dvec3 boxAxis(0.0);
    boxAxis[axis] = 1.0;
    reach +=
        box.halfExtentsMeters[axis] * std::abs(glm::dot(box.worldFromBox * boxAxis, direction));
  }
  return reach;
}

}  // namespace

EeveeReflectionCubemap eeveeReflectionCubemap(const BoxShape& proxy, glm::dvec3 captureMeters,
                                              const InfluenceVolume& influence, bool inside) {
  // In plan, the nearer faces or the farther ones; in height always the farther: the floor
  // must be inside.
  const glm::dvec3 side(inside ? -1.0 : 1.0, inside ? -1.0 : 1.0, 1.0);
  EeveeReflectionCubemap probe;
  probe.location = captureMeters;
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    probe.rotation = box->worldFromBox;
    const glm::dvec3 offset =
        glm::conjugate(box->worldFromBox) * (captureMeters - box->centerMeters);
    probe.scale = glm::max(box->halfExtentsMeters + side * glm::abs(offset), kSmallestScaleMeters);
  } else {
    const auto& sphere = std::get<SphereInfluence>(influence);
    probe.sphere = true;
    probe.scale = glm::dvec3(
        std::max(sphere.radiusMeters + side.x * glm::distance(captureMeters, sphere.centerMeters),
                 kSmallestScaleMeters));
  }
  const glm::dvec3 h = probe.scale;
  probe.falloff = std::clamp(transitionDistanceMeters(influence) / std::min({h.x, h.y, h.z}),
                             kSmallestFalloff, 1.0);
  // parallax_distance k: least squares of k * scale against the capture point's mean distance
  // to the proxy's two faces along each of the probe's axes.
  double numerator = 0.0, denominator = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    glm::dvec3 unit(0.0);
    unit[axis] = 1.0;
    const glm::dvec3 direction = probe.rotation * unit;
    const double wanted = 0.5 * (reachAlong(proxy, captureMeters, direction) +
                                 reachAlong(proxy, captureMeters, -direction));
    numerator += h[axis] * wanted;
    denominator += h[axis] * h[axis];
  }
  probe.parallaxDistance = numerator / denominator;
  return probe;
}

EeveeReflectionCubemap eeveeReflectionCubemapAtBoxCentre(const BoxShape& box,
                                                         double transitionMeters) {
  const glm::dvec3 h = glm::max(box.halfExtentsMeters, kSmallestScaleMeters);
  const double shortest = std::min({h.x, h.y, h.z});
  // Grown by g = 1 + t / shortest, the influence's full-weight part (1 - falloff of it) is the
  // box when falloff = 1 - 1 / g; the parallax volume, 1 / g of the influence, is the box.
  const double grown = 1.0 + std::max(transitionMeters, 0.0) / shortest;
  EeveeReflectionCubemap probe;
  probe.location = box.centerMeters;
  probe.rotation = box.worldFromBox;
  probe.scale = grown * h;
  probe.falloff = std::clamp(1.0 - 1.0 / grown, kSmallestFalloff, 1.0);
  probe.parallaxDistance = 1.0 / grown;
  return probe;
}

}  // namespace probeproxy
