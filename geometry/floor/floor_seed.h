#pragma once
// Where the walkable floor starts on a level that says nothing of it: a bare mesh with no spawn
// points and no probes. The floor is then the regions a player could stand on inside the level:
// the walkable floor flood-filled from the centres of the largest upward-facing triangles under
// a ceiling (as wound: the top of a ceiling slab faces down, so a roof is not taken for a floor
// unless nothing has a ceiling, an open level); the largest region, and every other at least a
// quarter its size (a storey no stair joins; a crate's top is far smaller). Deterministic.

#include "geometry/floor/walkable_floor.h"
#include "geometry/level/level_mesh.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <vector>

namespace probeproxy {

struct FloorSeed {
  glm::dvec3 pointMeters{0.0};   // a seed point, 0.5 m over the floor
  double floorSquareMeters = 0;  // of the walkable floor it reaches
};

// One seed per region, largest first; empty when no upward-facing triangle holds a floor a
// player fits on.
std::vector<FloorSeed> floorRegionSeeds(const LevelMesh& mesh, const LevelRayCaster& level,
                                        const WalkableFloorOptions& options);

}  // namespace probeproxy
