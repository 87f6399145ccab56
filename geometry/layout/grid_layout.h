#pragma once
// The baseline layout users ask engines for (`layout --baseline grid`): a probe in every square
// of a regular grid that holds walkable floor (one per storey), its capture point over the
// floor cell nearest the square's centre, its influence the square's floor as a box
// (layout_influence.h). With a probe budget, the finest spacing (from the floor's cell size,
// coarser in 5% steps) that needs no more probes than that.

#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <vector>

namespace probeproxy {

struct GridCellProbe {
  glm::dvec3 captureMeters{0.0};
  std::vector<std::size_t> cells;  // the floor cells of its square and storey
};

std::vector<GridCellProbe> gridLayout(const LevelRayCaster& level, const WalkableFloor& floor,
                                      double spacingMeters, double captureHeightMeters);

// The grid of `spacingMeters`, or with `maxProbes` > 0 the finest with at most that many
// probes; `spacingTaken` says which.
std::vector<GridCellProbe> gridLayoutWithin(const LevelRayCaster& level, const WalkableFloor& floor,
                                            double spacingMeters, double captureHeightMeters,
                                            std::size_t maxProbes, double& spacingTaken);

}  // namespace probeproxy
