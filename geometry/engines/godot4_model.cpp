// Godot 4's Forward+ renderer (servers/rendering/renderer_rd/shaders/forward_clustered/
// scene_forward_clustered.glsl and scene_forward_lights_inc.glsl, reflection_process(), as of
// the versions with ReflectionProbe.blend_distance):
//   - a probe applies where its box holds the fragment; with blend_distance b != 0 its blend is
//     per axis clamp(1 - (|local| - extents + min(b, extents)) / min(b, extents), 0, 1), the
//     three multiplied and squared; with b = 0 it is 1 over the whole box;
//   - reflection_blend = max(0, blend - reflection_accum.a) and reflection_accum += (radiance *
//     reflection_blend, reflection_blend): each probe adds what its blend has over the sum so
//     far, nothing once the sum is 1; the sky fills what is left (reflection_accum.rgb +=
//     indirect_specular_light * (1 - reflection_accum.a));
//   - the cluster lists probes in the order RenderForwardClustered sorts them, by depth from the
//     camera (reflection_sort[].depth = -camera_inverse.xform(origin).z), and the shader visits
//     each 32-probe word from its highest bit (findMSB): the farthest first. The model takes
//     the depth along the ray from the camera to the shaded point (the camera's axis differs
//     by at most half its field of view) and ignores the 32-probe word boundaries.

#include "geometry/engines/blend_composition.h"
#include "geometry/engines/godot_probes.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace probeproxy {

EngineModel godot4Model(const RuntimeExport& presets) {
  GodotProbes held = godotProbes(presets, /*godot4=*/true);
  EngineModel model;
  model.engine = Engine::Godot4;
  model.probes = std::move(held.probes);
  setBlend(
      model,
      [boxes = std::move(held.boxes)](glm::dvec3 x, glm::dvec3 eye) {
        struct Reached {
          ProbeFade fade;
          double depth;
        };
        std::vector<Reached> reached;
        const glm::dvec3 forward = glm::normalize(x - eye);
        for (std::size_t i = 0; i < boxes.size(); ++i) {
          const BoxShape& box = boxes[i].box;
          const std::optional<glm::dvec3> local = godotLocalPosition(box, x);
          if (!local) continue;
          double blend = 1.0;
          if (boxes[i].fadeMeters != 0.0) {
            double product = 1.0;
            for (int axis = 0; axis < 3; ++axis) {
              const double extent = box.halfExtentsMeters[axis];
              const double distance = std::min(boxes[i].fadeMeters, extent);
              const double into = (std::abs((*local)[axis]) - extent + distance) / distance;
              product *= std::clamp(1.0 - into, 0.0, 1.0);
            }
            blend = product * product;
          }
          if (blend > 0.0)
            reached.push_back(
                {{static_cast<int>(i), blend}, glm::dot(box.centerMeters - eye, forward)});
        }
        std::stable_sort(reached.begin(), reached.end(),
                         [](const Reached& a, const Reached& b) { return a.depth > b.depth; });
        std::vector<ProbeFade> ordered;
        for (const Reached& r : reached) ordered.push_back(r.fade);
        return ordered;
      },
      upToLargestFade, 1.0);
  return model;
}

}  // namespace probeproxy
