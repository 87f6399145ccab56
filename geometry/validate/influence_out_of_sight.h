#pragma once
// How much of a probe's influence falls on walkable floor its capture point never saw: light
// leaking through a wall. Weighed by Lagarde's factor (core/blend), so a fade band reaching
// round a corner counts for what it contributes there; hidden is out of sight by
// geometry/raycast/room_in_sight.h. validate's influence_leak reports it; the layout keeps
// what it widens under that rule's limit (geometry/layout/widen_fades.h).

#include "core/scene/influence_volume.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <optional>
#include <span>

namespace probeproxy {

struct InfluenceOutOfSight {
  double share = 0.0;                           // of the influence on the floor; 0 on none
  std::optional<glm::dvec3> firstHiddenMeters;  // a floor point out of sight, the first met
};

// Each floor point is weighed kBlendLiftMeters over it, where the survey blends.
InfluenceOutOfSight influenceOutOfSight(const LevelRayCaster& level, glm::dvec3 captureMeters,
                                        const InfluenceVolume& influence,
                                        std::span<const FloorCell> floor);

}  // namespace probeproxy
