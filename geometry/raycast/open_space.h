#pragma once
// Straight up and down from a point: whether it is inside a solid, and how far the floor under
// it is (validate's camera space, geometry/validate/camera_space.h, builds on it). A point
// inside a solid block sees the back of the block's faces: straight up, the underside of its top
// (a floor's surface, facing up); straight down, the inside of its bottom (facing down). Quake
// 3's compiler drops the faces a block rests on or shares with another, so only one of the two
// may be there (basement: a 6 m block under the upper storey with no bottom, from inside which
// the floor below is in plain view): either one counts. A one-sided surface with nothing under
// it (a bridge made of a curved patch) reads as solid under it too.

#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace probeproxy {

struct VerticalView {
  bool insideSolid = false;
  // How far below the first surface straight down is, when it is a floor (facing up) and the
  // point is not inside a solid; infinity otherwise.
  float floorBelowMeters = 0.0f;
};

// Two rays a point, batched.
std::vector<VerticalView> lookUpAndDown(const LevelRayCaster& level,
                                        std::span<const glm::dvec3> pointsMeters);

}  // namespace probeproxy
