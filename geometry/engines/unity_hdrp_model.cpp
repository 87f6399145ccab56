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
// The preset a studio makes from the export: the influence volume as the scene has it (blend
// distance on each face = outer - inner half-extent), the proxy volume the box the other box
// engines get (unreal_box_reflection_capture: the kept proxy when it is a box, else the best
// box candidate), the capture point the scene's.

#include "core/scene/influence_volume.h"
#include "geometry/engines/blend_composition.h"
#include "geometry/engines/engine_model.h"
#include "geometry/engines/preset_boxes.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <numeric>

namespace probeproxy {

namespace {

constexpr double kSmallestBlendMeters = 0.0001;  // the shaders' max(0.0001, blend distance)

double hdrpInfluenceWeight(const InfluenceVolume& influence, glm::dvec3 x) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dvec3 p = glm::conjugate(box->worldFromBox) * (x - box->centerMeters);
    const glm::dvec3 blend =
        glm::max(box->halfExtentsMeters - box->innerHalfExtentsMeters, kSmallestBlendMeters);
    const glm::dvec3 negative = (box->halfExtentsMeters + p) / blend;
    const glm::dvec3 positive = (box->halfExtentsMeters - p) / blend;
    const double falloff =
        std::min({negative.x, negative.y, negative.z, positive.x, positive.y, positive.z});
    return std::clamp(falloff, 0.0, 1.0);
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  const double blend =
      std::max(sphere.radiusMeters - sphere.innerRadiusMeters, kSmallestBlendMeters);
  const double beyond =
      std::max(glm::length(x - sphere.centerMeters) - (sphere.radiusMeters - blend), 0.0);
  return std::clamp(1.0 - beyond / blend, 0.0, 1.0);
}

}  // namespace

EngineModel unityHdrpModel(const RuntimeExport& presets) {
  EngineModel model;
  model.engine = Engine::UnityHdrp;
  std::vector<InfluenceVolume> influences;
  for (std::size_t i = 0; i < presets.probes.size(); ++i) {
    const RuntimeProbe& probe = presets.probes[i];
    if (!probe.engines.unrealBox) continue;
    const PresetBox proxy = unrealPresetBox(*probe.engines.unrealBox);
    EngineProbe p;
    p.sceneProbe = static_cast<int>(i);
    p.captureMeters = proxy.captureMeters;
    p.lookupOriginMeters = proxy.captureMeters;
    p.projection = proxy.box;
    model.probes.push_back(std::move(p));
    influences.push_back(probe.influence);
  }
  std::vector<int> order(influences.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return influenceCubicMeters(influences[static_cast<std::size_t>(a)]) <
           influenceCubicMeters(influences[static_cast<std::size_t>(b)]);
  });
  model.blend = [influences = std::move(influences), order = std::move(order)](glm::dvec3 x,
                                                                               glm::dvec3) {
    std::vector<ProbeFade> fades;
    for (const int i : order) {
      const double fade = hdrpInfluenceWeight(influences[static_cast<std::size_t>(i)], x);
      if (fade > 0.0) fades.push_back({i, fade});
    }
    return fillToOne(fades);
  };
  return model;
}

}  // namespace probeproxy
