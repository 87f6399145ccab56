#pragma once
// Where more outer ranges meet than the blend takes (ValidateOptions::maxOverlap: a probe
// drops out of the blend there and its lighting pops), outside every inner range (inside one,
// one probe takes 100% however many overlap) and where a camera can be (camera_space.h):
// validate's too_many_overlaps, and what the layout trims its bands for
// (geometry/layout/overlap_trim.h), on the same grid (validation_grid.h) over the volumes'
// bounds.

#include "core/scene/influence_volume.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/validate/validate_scene.h"
#include "geometry/validate/validation_grid.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace probeproxy {

struct OverlapPoint {
  glm::dvec3 pointMeters{0.0};
  std::vector<int> volumes;  // indices of the volumes whose outer ranges hold it, ascending
};

struct OverlapPoints {
  ValidationGrid grid;               // each point stands for one cell of it
  std::vector<OverlapPoint> points;  // in forEachPoint's order
};

OverlapPoints overlapsOverLimit(std::span<const InfluenceVolume> volumes,
                                const LevelRayCaster& level, const WalkableFloor& walked,
                                const ValidateOptions& options);

}  // namespace probeproxy
