#pragma once
// Floor the survey walks that the layout's coarser floor has no cell on: planks, gratings and
// ledges narrower than the candidates' 0.5 m grid (darkzone: 0.1% of its floor, three strips of
// grating, in no volume). And floor the volumes reach only with the far ends of their bands,
// where the blend pops (basement, darkzone: validate's weight_jump 0.03-0.3 per cm over such
// floor); a fill there is marked when it would make more bands meet than the blend takes.
// Each group of such cells gets a probe of its own: the cells within a gap of one another on
// one storey, its inner range over them, its band as every range's (kept to the floor in its
// probe's sight, bands_in_sight.h).

#include "core/scene/influence_volume.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace probeproxy {

struct FloorFill {
  glm::dvec3 captureMeters{0.0};
  BoxInfluence influence;
  // Over floor some volume covers, it makes more bands meet than the blend takes: it stays only
  // if trimming bands frees that crowd (overlap_trim.h).
  bool crowdsTheBlend = false;
};

// `floor` is the floor every point of which must lie in some volume (the survey's); a cell
// counts as covered as the survey counts a sample (its point, lifted kBlendLiftMeters, inside
// a volume), and as reached well when that point lies in the near two thirds of some band.
// Deterministic: groups in floor order.
std::vector<FloorFill> fillsForUncoveredFloor(const LevelRayCaster& level,
                                              const WalkableFloor& floor,
                                              std::span<const InfluenceVolume> volumes,
                                              double gapMeters, double captureHeightMeters);

}  // namespace probeproxy
