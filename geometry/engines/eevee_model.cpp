// Blender 3.x EEVEE's Reflection Cubemap light probes (source/blender/draw/engines/eevee/
// eevee_lightprobes.c, EEVEE_lightprobes_cube_data_from_object(); eevee_lightcache.c,
// eevee_lightbake_gather_probes(); shaders/lightprobe_lib.glsl):
//   - the probe object's location is the capture point and the centre of both volumes; the
//     influence is the object's transform scaled by influence_distance, the parallax volume the
//     same transform scaled by parallax_distance (a uniformly scaled copy, same rotation);
//   - probe_attenuation_cube(): localpos in the influence's unit space, fac = saturate(a - a *
//     |localpos|) per axis (box: the smallest; sphere: of the length), a = 1 / falloff: 1 up to
//     1 - falloff of the way to each face, 0 on it, along Z too;
//   - fallback_cubemap(): probes in the light cache's order, each through accumulate_light(),
//     accum += min(fade, 1 - accum.a), until accum.a reaches 0.999; the world probe takes what
//     is left. The bake sorts cube probes by mat4_to_scale of their inverse influence matrix,
//     largest first: the smallest influence first;
//   - probe_evaluate_cube(): the ray from the shading point is intersected with the parallax
//     box (line_unit_box_intersect_dist) or sphere, and the lookup is hit - probe position.
//
// The preset is the export's eevee_reflection_cubemap (engine_probes.h says how it is made).

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

constexpr double kFull = 0.999;  // fallback_cubemap's loop and world test

double attenuation(const EeveeReflectionCubemap& e, glm::dvec3 x) {
  const double a = 1.0 / e.falloff;
  const glm::dvec3 local = glm::conjugate(e.rotation) * (x - e.location) / e.scale;
  if (e.sphere) return std::clamp(a - a * glm::length(local), 0.0, 1.0);
  const glm::dvec3 axes = glm::clamp(a - a * glm::abs(local), 0.0, 1.0);
  return std::min({axes.x, axes.y, axes.z});
}

// mat4_to_scale of the inverse influence matrix: |diag(1 / scale) R^T (1, 1, 1) / sqrt(3)|, in
// float as Blender holds the object's scale and sorts: two probes whose scales differ by less
// than a float (a layout's storeys, 3e-8 m apart) tie, and keep the order Blender gathered them
// in, the scene's. Blender's own float matrix inversion can still part such a tie by one unit
// in the last place (scripts/render_check.py found one on u_corridors' grid).
double inverseScale(const EeveeReflectionCubemap& e) {
  const glm::vec3 u = glm::conjugate(glm::quat(e.rotation)) * glm::vec3(1.0f / std::sqrt(3.0f));
  return glm::length(u / glm::vec3(e.scale));
}

}  // namespace

EngineModel eeveeModel(const RuntimeExport& presets) {
  EngineModel model;
  model.engine = Engine::Eevee;
  std::vector<EeveeReflectionCubemap> held;
  for (std::size_t i = 0; i < presets.probes.size(); ++i) {
    const auto& preset = presets.probes[i].engines.eevee;
    if (!preset) continue;
    EngineProbe p;
    p.sceneProbe = static_cast<int>(i);
    p.captureMeters = preset->location;
    p.lookupOriginMeters = preset->location;
    p.projection =
        BoxShape{preset->location, preset->parallaxDistance * preset->scale, preset->rotation};
    model.probes.push_back(std::move(p));
    held.push_back(*preset);
  }
  // The bake's bubble sort puts the largest inverse scale (the smallest influence) first.
  std::vector<int> order = orderedBy(
      held.size(), [&](int i) { return -inverseScale(held[static_cast<std::size_t>(i)]); });
  setBlend(
      model,
      [held = std::move(held), order = std::move(order)](glm::dvec3 x, glm::dvec3) {
        return fadesInOrder(order, [&](std::size_t i) { return attenuation(held[i], x); });
      },
      [](std::span<const ProbeFade> ordered) { return fillToOne(ordered, kFull); }, kFull);
  return model;
}

}  // namespace probeproxy
