#include "geometry/export/engine_probes.h"

#include "core/scene/file_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace probeproxy {

double transitionDistanceMeters(const InfluenceVolume& influence) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dvec3 fade = box->halfExtentsMeters - box->innerHalfExtentsMeters;
    double smallest = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      if (fade[axis] > 0.0) smallest = std::min(smallest, fade[axis]);
    }
    return std::isinf(smallest) ? 0.0 : smallest;
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  return std::max(0.0, sphere.radiusMeters - sphere.innerRadiusMeters);
}

UnrealBoxReflectionCapture unrealBoxReflectionCapture(const BoxShape& box, glm::dvec3 captureMeters,
                                                      const InfluenceVolume& influence) {
  const FileFrame unreal = unrealFrame();
  UnrealBoxReflectionCapture capture;
  capture.location = filePointFromWorld(unreal, box.centerMeters);
  capture.rotation = fileRotationFromWorld(unreal, box.worldFromBox);
  capture.scale3D = fileHalfExtentsFromWorld(unreal, box.halfExtentsMeters);
  capture.captureOffset = filePointFromWorld(unreal, captureMeters - box.centerMeters);
  capture.boxTransitionDistance = fileLengthFromWorld(unreal, transitionDistanceMeters(influence));
  return capture;
}

UnrealSphereReflectionCapture unrealSphereReflectionCapture(const SphereShape& sphere,
                                                            glm::dvec3 captureMeters) {
  const FileFrame unreal = unrealFrame();
  UnrealSphereReflectionCapture capture;
  capture.location = filePointFromWorld(unreal, sphere.centerMeters);
  capture.influenceRadius = fileLengthFromWorld(unreal, sphere.radiiMeters.x);
  capture.captureOffset = filePointFromWorld(unreal, captureMeters - sphere.centerMeters);
  return capture;
}

}  // namespace probeproxy
