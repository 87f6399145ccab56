#include "core/scene/file_frame.h"
#include "geometry/export/engine_probes.h"

#include <glm/common.hpp>

#include <algorithm>

namespace probeproxy {

UnityReflectionProbe unityReflectionProbe(const BoxShape& aabb, glm::dvec3 captureMeters,
                                          const InfluenceVolume& influence) {
  const FileFrame unity = unityFrame();
  const glm::dvec3 h = aabb.halfExtentsMeters;
  const double shortest = std::min({h.x, h.y, h.z});
  UnityReflectionProbe probe;
  probe.blendDistance = std::clamp(transitionDistanceMeters(influence), kUnityMinBlendMeters,
                                   std::max(kUnityMinBlendMeters, 0.5 * shortest));
  probe.position = filePointFromWorld(unity, captureMeters);
  probe.center = filePointFromWorld(unity, aabb.centerMeters - captureMeters);
  probe.size = 2.0 * fileHalfExtentsFromWorld(unity, glm::max(h - probe.blendDistance, 0.0));
  return probe;
}

}  // namespace probeproxy
