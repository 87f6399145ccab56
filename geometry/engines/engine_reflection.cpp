#include "geometry/engines/engine_reflection.h"

#include <glm/geometric.hpp>

namespace probeproxy {

EngineReflection engineReflection(const LevelRayCaster& level, const EngineModel& model,
                                  const ReflectionSample& sample) {
  const EngineBlend blend = model.blend(sample.xMeters, sample.eyeMeters);
  EngineReflection shown;
  shown.fallbackWeight = blend.fallbackWeight;
  glm::dvec3 weightedSum(0.0);
  for (const EngineWeight& w : blend.weights) {
    const EngineProbe& probe = model.probes[static_cast<std::size_t>(w.probe)];
    const std::optional<glm::dvec3> d = engineLookup(probe, sample.xMeters, sample.reflected);
    if (!d) continue;  // no lookup: the engine's shader gives nothing there either
    const glm::vec3 direction(glm::normalize(*d));
    const RayHit hit = level.firstHit({probe.captureMeters, direction});
    // The texel's point: t is in units of the (float) direction the ray took.
    const glm::dvec3 point = probe.captureMeters + double(hit.t) * glm::dvec3(direction);
    if (!hit.hit() || !capturedAt(probe, point)) {  // the sky, or the probe's clear colour
      shown.skyWeight += w.weight;
      continue;
    }
    weightedSum += w.weight * point;
    shown.texels.push_back({w.weight, point});
    shown.surfaceWeight += w.weight;
  }
  if (shown.surfaceWeight > 0.0) shown.shownMeters = weightedSum / shown.surfaceWeight;
  return shown;
}

}  // namespace probeproxy
