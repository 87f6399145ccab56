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
  // Shrunk by the blend distance on every side but the bottom, which stays where the measured
  // box's is: a floor lying on it keeps the probe's full weight (Unity fades outside the box),
  // and the box Unity projects on reaches the blend distance below it, where a mirror floor's
  // reflections never go.
  const double b = probe.blendDistance;
  glm::dvec3 center = aabb.centerMeters, half = glm::max(h - b, 0.0);
  center.z -= 0.5 * b;
  half.z = std::max(h.z - 0.5 * b, 0.0);
  probe.position = filePointFromWorld(unity, captureMeters);
  probe.center = filePointFromWorld(unity, center - captureMeters);
  probe.size = 2.0 * fileHalfExtentsFromWorld(unity, half);
  return probe;
}

}  // namespace probeproxy
