// Bevy's light probes with several reflection probes in a view (crates/bevy_pbr/src/
// light_probe.wesl, light_probe_iterator_next(); light_probe/environment_map.wesl,
// compute_radiances() and compute_cubemap_sample_dir()):
//   - a probe's weight at a fragment is min over its axes of saturate((1 - 2 |p|) / (2
//     falloff)), p the fragment in the probe's unit cube (light_from_world): 1 inside the
//     falloff band, 0 on the cube's faces;
//   - the weights of every probe that reaches the fragment are summed; if the sum is under
//     0.9999 the view's environment map takes 1 - sum; then everything is divided by the sum
//     (so overlapping probes are normalized, and a point reached by one fading probe shows the
//     environment in the rest);
//   - parallax correction (on by default, bounds = the cube) intersects the ray with the cube
//     in light-probe space and samples the cubemap with the hit point there, seen from the
//     cube's centre: the direction to the hit only for a cube that is not turned (engine_bevy.cpp
//     says why; `exact` in the preset).
// Bevy captures a probe's cubemap at its translation (the cube's centre).

#include "geometry/engines/blend_composition.h"
#include "geometry/engines/engine_model.h"
#include "geometry/engines/preset_boxes.h"

#include "core/scene/file_frame.h"

#include <glm/common.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>

namespace probeproxy {

namespace {

constexpr double kSmallestFalloff = 0.0001;  // light_probe_iterator_next's max(falloff, 0.0001)
constexpr double kFullWeight = 0.9999;       // compute_radiances: below it, the environment fills

// World offset from the cube's centre -> Bevy's sample direction, read back as a world
// direction: worldFromBevy * (scale^-1 * rotation^-1) * bevyFromWorld.
glm::dmat3 sampleDirectionFromOffset(const BevyLightProbe& preset) {
  const FileFrame gltf = gltfFrame();
  glm::dmat3 m(1.0);
  for (int column = 0; column < 3; ++column) {
    glm::dvec3 axis(0.0);
    axis[column] = 1.0;
    const glm::dvec3 local =
        (glm::conjugate(preset.rotation) * fileDirectionFromWorld(gltf, axis)) / preset.scale;
    m[column] = worldDirectionFromFile(gltf, local);
  }
  return m;
}

struct Cube {
  BoxShape box;
  glm::dvec3 falloff{0.0};  // per axis of the world box's own frame
};

}  // namespace

EngineModel bevyModel(const RuntimeExport& presets) {
  EngineModel model;
  model.engine = Engine::Bevy;
  std::vector<Cube> cubes;
  for (std::size_t i = 0; i < presets.probes.size(); ++i) {
    const auto& preset = presets.probes[i].engines.bevy;
    if (!preset) continue;
    const PresetBox held = bevyPresetBox(*preset);
    EngineProbe p;
    p.sceneProbe = static_cast<int>(i);
    p.captureMeters = held.captureMeters;
    p.projection = held.box;
    p.lookupOriginMeters = held.box.centerMeters;
    p.lookupFromWorld = sampleDirectionFromOffset(*preset);
    model.probes.push_back(std::move(p));
    // Falloff is per axis of the probe's own frame, permuted with it like a half-extent.
    cubes.push_back({held.box, worldHalfExtentsFromFile(gltfFrame(), preset->falloff)});
  }
  setBlend(
      model,
      [cubes = std::move(cubes)](glm::dvec3 x, glm::dvec3) {
        std::vector<ProbeFade> fades;
        for (std::size_t i = 0; i < cubes.size(); ++i) {
          const BoxShape& box = cubes[i].box;
          const glm::dvec3 unit = glm::conjugate(box.worldFromBox) * (x - box.centerMeters) /
                                  (2.0 * box.halfExtentsMeters);
          const glm::dvec3 falloff = glm::max(cubes[i].falloff, kSmallestFalloff);
          const glm::dvec3 axes =
              glm::clamp((1.0 - 2.0 * glm::abs(unit)) / (2.0 * falloff), 0.0, 1.0);
          const double weight = std::min({axes.x, axes.y, axes.z});
          if (weight == 0.0) continue;
          fades.push_back({static_cast<int>(i), weight});
        }
        return fades;
      },
      [](std::span<const ProbeFade> fades) {
        double sum = 0.0;
        for (const ProbeFade& f : fades) sum += f.fade;
        if (sum < kFullWeight) {
          EngineBlend blend;
          for (const ProbeFade& f : fades) blend.weights.push_back({f.probe, f.fade});
          blend.fallbackWeight = 1.0 - sum;
          return blend;
        }
        return normalizedFades(fades);
      });
  return model;
}

}  // namespace probeproxy
