#include "core/scene/file_frame.h"
#include "geometry/export/engine_probes.h"

#include <glm/gtc/quaternion.hpp>

namespace probeproxy {

UnityHdrpReflectionProbe unityHdrpReflectionProbe(const BoxShape& proxy, glm::dvec3 captureMeters,
                                                  const InfluenceVolume& influence) {
  const FileFrame unity = unityFrame();
  UnityHdrpReflectionProbe probe;
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    probe.position = filePointFromWorld(unity, box->centerMeters);
    probe.rotation = fileRotationFromWorld(unity, box->worldFromBox);
    probe.boxSize = 2.0 * fileHalfExtentsFromWorld(unity, box->halfExtentsMeters);
    // The scene's fade is the same on both faces of an axis, so the swap of Unity's x faces
    // changes nothing.
    probe.blendDistancePositive =
        fileHalfExtentsFromWorld(unity, box->halfExtentsMeters - box->innerHalfExtentsMeters);
    probe.blendDistanceNegative = probe.blendDistancePositive;
  } else {
    const auto& sphere = std::get<SphereInfluence>(influence);
    probe.sphere = true;
    probe.position = filePointFromWorld(unity, sphere.centerMeters);
    probe.sphereRadius = fileLengthFromWorld(unity, sphere.radiusMeters);
    probe.blendDistancePositive = probe.blendDistanceNegative =
        glm::dvec3(fileLengthFromWorld(unity, sphere.radiusMeters - sphere.innerRadiusMeters));
  }
  probe.capturePosition = filePointFromWorld(unity, captureMeters);
  probe.proxyPosition = filePointFromWorld(unity, proxy.centerMeters);
  probe.proxyRotation = fileRotationFromWorld(unity, proxy.worldFromBox);
  probe.proxySize = 2.0 * fileHalfExtentsFromWorld(unity, proxy.halfExtentsMeters);
  return probe;
}

}  // namespace probeproxy
