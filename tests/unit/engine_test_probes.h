#pragma once
// Hand-made export probes for the engine tests: each engine's preset as `build` exports it.

#include "geometry/export/runtime_export.h"

#include <string>
#include <utility>
#include <vector>

namespace probeproxy {

// A probe with every box engine's preset made from `box`, as `build` exports it.
inline RuntimeProbe probeWithPresets(const std::string& name, const BoxShape& box,
                                     glm::dvec3 capture, const InfluenceVolume& influence) {
  RuntimeProbe p;
  p.name = name;
  p.captureMeters = capture;
  p.method = Method::Aabb;
  p.box = box;
  p.influence = influence;
  p.engines.unity = unityReflectionProbe(box, capture, influence);
  p.engines.unityHdrp = unityHdrpReflectionProbe(box, capture, influence);
  p.engines.unrealBox = unrealBoxReflectionCapture(box, capture, influence);
  p.engines.godot = p.engines.godot4 = godotReflectionProbe(box, capture, influence);
  p.engines.bevy = bevyLightProbe(box, capture, influence);
  p.engines.eevee = eeveeReflectionCubemap(box, capture, influence);
  return p;
}

// A probe whose influence is its box, fading over the last `fadeMeters` inside it.
inline RuntimeProbe boxProbe(const std::string& name, const BoxShape& box, glm::dvec3 capture,
                             double fadeMeters) {
  BoxInfluence influence;
  influence.centerMeters = box.centerMeters;
  influence.halfExtentsMeters = box.halfExtentsMeters;
  influence.innerHalfExtentsMeters = box.halfExtentsMeters - fadeMeters;
  return probeWithPresets(name, box, capture, influence);
}

inline RuntimeExport exportOf(std::vector<RuntimeProbe> probes) {
  RuntimeExport e;
  e.probes = std::move(probes);
  return e;
}

}  // namespace probeproxy
