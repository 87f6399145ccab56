#pragma once
// What an engine shows in a mirror at one shaded point, as a renderer's pixel would: each
// probe that reaches the point looks its cubemap up (engineLookup), and a cubemap texel holds
// the level point its capture point sees in that direction. The pixel is the blend of those
// points' colours. With position-coded walls (a surface's colour is its world position) and a
// black sky, the blend normalised by its weight is the weight-averaged level point: what
// scripts/render_check.py decodes from EEVEE's and Godot's frames, and compares with this.
// World frame (Z up), metres.

#include "geometry/engines/engine_model.h"
#include "geometry/evaluation/reflection_sample.h"
#include "geometry/raycast/level_ray_caster.h"

#include <optional>
#include <vector>

namespace probeproxy {

struct ShownTexel {
  double weight = 0.0;  // the probe's blend weight
  glm::dvec3 pointMeters{0.0};
};

struct EngineReflection {
  // The weight-averaged level point the lookups show; none when no weighted lookup meets a
  // surface (all sky, or no probe reaches the point).
  std::optional<glm::dvec3> shownMeters;
  double surfaceWeight = 0.0;   // the weights whose lookups meet a surface
  double skyWeight = 0.0;       // the weights whose lookups leave the level (a black sky)
  double fallbackWeight = 1.0;  // the engine's sky / ambient share: no probe's
  // Each weighted lookup that meets a surface, in the engine's order: a pixel's colour is their
  // weighted colours' sum, which a colour code that is not linear in position (a phase) needs.
  std::vector<ShownTexel> texels;
};

// `sample`'s x, normal, eye and reflected direction are used; its true hit is not.
EngineReflection engineReflection(const LevelRayCaster& level, const EngineModel& model,
                                  const ReflectionSample& sample);

}  // namespace probeproxy
