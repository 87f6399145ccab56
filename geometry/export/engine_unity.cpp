#include "geometry/export/engine_probes.h"

#include <glm/common.hpp>

namespace probeproxy {

namespace {
// Unity: left-handed, Y up, metres. glTF's Y-up axes (x, z, -y) with x negated.
glm::dvec3 unityFromWorld(glm::dvec3 p) { return {-p.x, p.z, -p.y}; }
}  // namespace

UnityReflectionProbe unityReflectionProbe(const BoxShape& aabb, glm::dvec3 captureMeters) {
  UnityReflectionProbe probe;
  probe.position = unityFromWorld(captureMeters);
  probe.center = unityFromWorld(aabb.centerMeters - captureMeters);
  probe.size = 2.0 * glm::abs(unityFromWorld(aabb.halfExtentsMeters));
  return probe;
}

}  // namespace probeproxy
