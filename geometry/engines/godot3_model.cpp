// Godot 3's GLES3 renderer (drivers/gles3/shaders/scene.glsl, reflection_process() and the
// USE_FORWARD_LIGHTING block of main()): every probe whose box holds the fragment contributes
//   inner_pos = abs(local_pos / box_extents); blend = max(inner_pos.x, .y, .z);
//   blend = mix(length(inner_pos), blend, blend); blend *= blend; blend = max(0, 1 - blend);
//   reflection_accum += vec4(radiance * blend, blend);
// and the result is reflection_accum.rgb / reflection_accum.a, or the environment's radiance
// where reflection_accum.a is 0. Godot 3 has no blend distance: the weight is that fixed curve,
// 1 at the box centre and 0 on its faces. Probes are listed per object (reflection_indices[],
// at most max_forward_lights_per_object, 8, per object, the first paired with it:
// rasterizer_scene_gles3.cpp, _setup_light): this model gives a point the first 8 boxes holding
// it, in the scene's order. It is the engine's exactly where no object meets more than 8 boxes;
// where more hold a point, which 8 the engine takes depends on how the level's meshes are cut
// and on the order Godot pairs them, which no export fixes (the layout keeps to 8).

#include "geometry/engines/blend_composition.h"
#include "geometry/engines/godot_probes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <span>

namespace probeproxy {

namespace {

constexpr std::size_t kGodot3ProbesPerObject = 8;  // max_forward_lights_per_object

}  // namespace

EngineModel godot3Model(const RuntimeExport& presets) {
  GodotProbes held = godotProbes(presets, /*godot4=*/false);
  EngineModel model;
  model.engine = Engine::Godot3;
  model.probes = std::move(held.probes);
  setBlend(
      model,
      [boxes = std::move(held.boxes)](glm::dvec3 x, glm::dvec3) {
        std::vector<ProbeFade> fades;
        for (std::size_t i = 0; i < boxes.size(); ++i) {
          const BoxShape& box = boxes[i].box;
          const std::optional<glm::dvec3> local = godotLocalPosition(box, x);
          if (!local) continue;
          const glm::dvec3 inner = glm::abs(*local / box.halfExtentsMeters);
          double blend = std::max({inner.x, inner.y, inner.z});
          blend = glm::length(inner) * (1.0 - blend) + blend * blend;  // mix(length, blend, blend)
          blend *= blend;
          blend = std::max(0.0, 1.0 - blend);
          if (blend > 0.0) fades.push_back({static_cast<int>(i), blend});
        }
        return fades;
      },
      [](std::span<const ProbeFade> ordered) {
        return normalizedFades(ordered.first(std::min(ordered.size(), kGodot3ProbesPerObject)));
      });
  model.averagesFades = true;
  model.mostProbes = kGodot3ProbesPerObject;
  return model;
}

}  // namespace probeproxy
