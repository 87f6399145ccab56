// Unity's built-in render pipeline with deferred shading, where reflection probes are applied
// per pixel ("When using deferred shading, reflection probes are rendered per-pixel (instead of
// one or two probes affecting whole object)", ScriptReference ReflectionProbe.blendDistance).
// Forward rendering picks two probes per renderer for the whole object (Manual "Blend
// Reflection Probes in the Built-In Render Pipeline"): a floor mesh spanning many probes gets
// two of them everywhere, which no layout can serve; that path is not modelled.
//
// DefaultResourcesExtra/Internal-DeferredReflections.shader, frag():
//   - each probe is drawn as its box grown by blendDistance on every side, and box projection
//     intersects that grown box: boxMin = unity_SpecCube0_BoxMin - blendDistance, boxMax + ...;
//   - its alpha is falloff = saturate(1 - length(distanceFromAABB(worldPos, boxMin, boxMax)) /
//     blendDistance): 1 inside the box, fading to 0 blendDistance outside it;
//   - the probes are drawn over the skybox (a full-screen quad first), each blended over what is
//     there by its alpha. Unity's C++ side, which sorts them, is not public; we take the order
//     the documentation gives for overlapping probes (ScriptReference ReflectionProbe.importance:
//     "if object is inside both Important and Not Important probe, only Important probe will be
//     used, when object is leaving Important probe bounding box, it will gradually blend over
//     Not Important probe": the more important drawn later, on top) and, at equal importance,
//     the smaller box drawn later, on top.
// The export writes the measured box shrunk by blendDistance (engine_probes.h), so Unity
// projects on the measured box; an export without blend_distance leaves Unity's default, 1 m.

#include "geometry/engines/blend_composition.h"
#include "geometry/engines/engine_model.h"
#include "geometry/engines/preset_boxes.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <utility>

namespace probeproxy {

EngineModel unityModel(const RuntimeExport& presets) {
  EngineModel model;
  model.engine = Engine::Unity;
  std::vector<PresetBox> held;
  std::vector<int> importance;
  for (std::size_t i = 0; i < presets.probes.size(); ++i) {
    const auto& preset = presets.probes[i].engines.unity;
    if (!preset) continue;
    const PresetBox box = unityPresetBox(*preset);
    EngineProbe p;
    p.sceneProbe = static_cast<int>(i);
    p.captureMeters = box.captureMeters;
    p.lookupOriginMeters = box.captureMeters;
    if (preset->boxProjection) {
      BoxShape grown = box.box;
      grown.halfExtentsMeters += box.fadeMeters;
      p.projection = grown;
    } else {
      p.projection = InfiniteShape{};
    }
    model.probes.push_back(std::move(p));
    held.push_back(box);
    importance.push_back(preset->importance);
  }
  // Front to back: the more important first, then the smaller box (drawn last, on top); ties
  // in scene order.
  std::vector<int> order = orderedBy(held.size(), [&](int i) {
    const glm::dvec3 h = held[static_cast<std::size_t>(i)].box.halfExtentsMeters;
    return std::pair(-importance[static_cast<std::size_t>(i)], h.x * h.y * h.z);
  });
  setBlend(
      model,
      [held = std::move(held), order = std::move(order)](glm::dvec3 x, glm::dvec3) {
        return fadesInOrder(order, [&](std::size_t i) {
          const BoxShape& box = held[i].box;
          const glm::dvec3 low = box.centerMeters - box.halfExtentsMeters;
          const glm::dvec3 high = box.centerMeters + box.halfExtentsMeters;
          const glm::dvec3 outside = glm::max(glm::max(x - high, low - x), glm::dvec3(0.0));
          return std::clamp(1.0 - glm::length(outside) / held[i].fadeMeters, 0.0, 1.0);
        });
      },
      frontToBack, 1.0);
  return model;
}

}  // namespace probeproxy
