// Unity's High Definition Render Pipeline: a Reflection Probe has an influence volume (box or
// sphere, with blend distances per face) apart from its proxy volume, the shape reflections
// are projected on (Manual "Reflection Probe", HDRP).
//
// Runtime/Lighting/VolumeProjection.hlsl, InfluenceBoxWeight(): in the influence's own frame,
// negativeFalloff = (extents + positionIS) / blendDistanceNegative, positiveFalloff = (extents -
// positionIS) / blendDistancePositive, alpha = saturate(min over the six faces): 1 deeper than
// the blend distance inside every face, linear to 0 on the face. InfluenceSphereWeight():
// alpha = saturate(1 - max(|p| - (radius - blend), 0) / blend). (The normal-facing and per-face
// cubemap fades are off by default and not modelled.)
// Runtime/Material/Material.hlsl, UpdateLightingHierarchyWeights(): the light loop visits the
// probes in order and each takes its alpha cut to what is left of 1; the sky takes the rest.
// LightLoop.cs sorts environment lights by the log of their influence volume, smallest first.
//
// The preset is the export's unity_hdrp_reflection_probe (engine_probes.h says how it is made).

#include "geometry/engines/blend_composition.h"
#include "geometry/engines/engine_model.h"
#include "geometry/engines/preset_boxes.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

namespace {

constexpr double kSmallestBlendMeters = 0.0001;  // the shaders' max(0.0001, blend distance)

double hdrpInfluenceWeight(const HdrpHeld& h, glm::dvec3 x) {
  if (h.sphere) {
    const double blend = std::max(h.sphereBlendMeters, kSmallestBlendMeters);
    const double beyond = std::max(
        glm::length(x - h.influenceBox.centerMeters) - (h.sphereRadiusMeters - blend), 0.0);
    return std::clamp(1.0 - beyond / blend, 0.0, 1.0);
  }
  const BoxShape& box = h.influenceBox;
  const glm::dvec3 p = glm::conjugate(box.worldFromBox) * (x - box.centerMeters);
  const glm::dvec3 negative =
      (box.halfExtentsMeters + p) / glm::max(h.blendNegative, kSmallestBlendMeters);
  const glm::dvec3 positive =
      (box.halfExtentsMeters - p) / glm::max(h.blendPositive, kSmallestBlendMeters);
  const double falloff =
      std::min({negative.x, negative.y, negative.z, positive.x, positive.y, positive.z});
  return std::clamp(falloff, 0.0, 1.0);
}

double influenceVolume(const HdrpHeld& h) {
  if (h.sphere) return 4.0 / 3.0 * M_PI * std::pow(h.sphereRadiusMeters, 3.0);
  const glm::dvec3 e = h.influenceBox.halfExtentsMeters;
  return 8.0 * e.x * e.y * e.z;
}

}  // namespace

EngineModel unityHdrpModel(const RuntimeExport& presets) {
  EngineModel model;
  model.engine = Engine::UnityHdrp;
  std::vector<HdrpHeld> held;
  for (std::size_t i = 0; i < presets.probes.size(); ++i) {
    const auto& preset = presets.probes[i].engines.unityHdrp;
    if (!preset) continue;
    const HdrpHeld h = unityHdrpHeld(*preset);
    EngineProbe p;
    p.sceneProbe = static_cast<int>(i);
    p.captureMeters = h.captureMeters;
    p.lookupOriginMeters = h.captureMeters;
    p.projection = h.proxy;
    model.probes.push_back(std::move(p));
    held.push_back(h);
  }
  std::vector<int> order = orderedBy(
      held.size(), [&](int i) { return influenceVolume(held[static_cast<std::size_t>(i)]); });
  setBlend(
      model,
      [held = std::move(held), order = std::move(order)](glm::dvec3 x, glm::dvec3) {
        return fadesInOrder(order, [&](std::size_t i) { return hdrpInfluenceWeight(held[i], x); });
      },
      [](std::span<const ProbeFade> ordered) { return fillToOne(ordered); }, 1.0);
  return model;
}

}  // namespace probeproxy
