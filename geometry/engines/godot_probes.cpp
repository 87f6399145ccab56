#include "geometry/engines/godot_probes.h"

#include <glm/common.hpp>
#include <glm/gtc/quaternion.hpp>

namespace probeproxy {

GodotProbes godotProbes(const RuntimeExport& presets, bool godot4) {
  GodotProbes out;
  for (std::size_t i = 0; i < presets.probes.size(); ++i) {
    const RuntimeEngines& engines = presets.probes[i].engines;
    const auto& preset = godot4 ? engines.godot4 : engines.godot;
    if (!preset) continue;
    const PresetBox held = godotPresetBox(*preset);
    EngineProbe p;
    p.sceneProbe = static_cast<int>(i);
    p.captureMeters = held.captureMeters;
    p.lookupOriginMeters = held.captureMeters;
    p.projection = preset->boxProjection ? ProxyShape(held.box) : ProxyShape(InfiniteShape{});
    const glm::dvec3 offset =
        glm::conjugate(held.box.worldFromBox) * (held.captureMeters - held.box.centerMeters);
    const glm::dvec3 far(preset->maxDistance);
    p.depth =
        CaptureDepth{held.box.worldFromBox, glm::max(far, held.box.halfExtentsMeters - offset),
                     glm::max(far, held.box.halfExtentsMeters + offset)};
    out.probes.push_back(std::move(p));
    out.boxes.push_back(held);
  }
  return out;
}

std::optional<glm::dvec3> godotLocalPosition(const BoxShape& box, glm::dvec3 x) {
  const glm::dvec3 local = glm::conjugate(box.worldFromBox) * (x - box.centerMeters);
  if (glm::any(glm::greaterThan(glm::abs(local), box.halfExtentsMeters))) return std::nullopt;
  return local;
}

}  // namespace probeproxy
