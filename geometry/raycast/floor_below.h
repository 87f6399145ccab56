#pragma once
// The floor under a point: the first level surface straight below it (world frame, Z up),
// e.g. under a game's spawn point, whose origin floats above the floor by a game-specific
// amount (Quake 3: 24 units) or more where the mapper placed it higher.

#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <optional>

namespace probeproxy {

// The height (world z, metres) of the first surface within `maxDropMeters` below
// `pointMeters`, either side facing up; nullopt if there is none.
std::optional<double> floorHeightBelow(const LevelRayCaster& level, const glm::dvec3& pointMeters,
                                       float maxDropMeters);

}  // namespace probeproxy
