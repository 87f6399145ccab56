#include "geometry/export/engine_probes.h"

#include <algorithm>

namespace probeproxy {

namespace {

constexpr double kCentimetersPerMeter = 100.0;

// Unreal: left-handed, Z up, centimetres; the world's Y flipped.
glm::dvec3 unrealFromWorld(glm::dvec3 p) {
  return glm::dvec3(p.x, -p.y, p.z) * kCentimetersPerMeter;
}

// Conjugating by the reflection diag(1, -1, 1) turns a rotation about axis a into one about
// -(a.x, -a.y, a.z) by the same angle: (w, x, y, z) -> (w, -x, y, -z). A box's own axes are
// reflected with the world's, so its half-extents keep their order.
glm::dquat unrealRotationFromWorld(const glm::dquat& q) {
  glm::dquat out;
  out.w = q.w;
  out.x = -q.x;
  out.y = q.y;
  out.z = -q.z;
  return out;
}

}  // namespace

double influenceFadeMeters(const InfluenceVolume& influence) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dvec3 fade = box->halfExtentsMeters - box->innerHalfExtentsMeters;
    return std::max(0.0, std::min({fade.x, fade.y, fade.z}));
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  return std::max(0.0, sphere.radiusMeters - sphere.innerRadiusMeters);
}

UnrealBoxReflectionCapture unrealBoxReflectionCapture(const BoxShape& box, glm::dvec3 captureMeters,
                                                      const InfluenceVolume& influence) {
  UnrealBoxReflectionCapture capture;
  capture.location = unrealFromWorld(box.centerMeters);
  capture.rotation = unrealRotationFromWorld(box.worldFromBox);
  capture.scale3D = box.halfExtentsMeters * kCentimetersPerMeter;
  capture.captureOffset = unrealFromWorld(captureMeters - box.centerMeters);
  capture.boxTransitionDistance = influenceFadeMeters(influence) * kCentimetersPerMeter;
  return capture;
}

UnrealSphereReflectionCapture unrealSphereReflectionCapture(const SphereShape& sphere,
                                                            glm::dvec3 captureMeters) {
  UnrealSphereReflectionCapture capture;
  capture.location = unrealFromWorld(sphere.centerMeters);
  capture.influenceRadius = sphere.radiiMeters.x * kCentimetersPerMeter;
  capture.captureOffset = unrealFromWorld(captureMeters - sphere.centerMeters);
  return capture;
}

}  // namespace probeproxy
