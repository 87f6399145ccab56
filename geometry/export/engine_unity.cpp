#include "geometry/export/engine_probes.h"

#include "core/scene/file_frame.h"

#include <glm/common.hpp>

namespace probeproxy {

UnityReflectionProbe unityReflectionProbe(const BoxShape& aabb, glm::dvec3 captureMeters) {
  const FileFrame unity = unityFrame();
  UnityReflectionProbe probe;
  probe.position = filePointFromWorld(unity, captureMeters);
  probe.center = filePointFromWorld(unity, aabb.centerMeters - captureMeters);
  probe.size = 2.0 * fileHalfExtentsFromWorld(unity, aabb.halfExtentsMeters);
  return probe;
}

}  // namespace probeproxy
