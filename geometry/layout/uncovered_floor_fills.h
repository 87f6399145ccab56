#pragma once
// Floor the survey walks that the layout's coarser floor has no cell on: planks, gratings and
// ledges narrower than the candidates' 0.5 m grid (darkzone: 0.1% of its floor, three strips of
// grating, in no volume). And floor the volumes reach only with the far ends of their bands,
// where the blend pops (basement, darkzone: validate's weight_jump 0.03-0.3 per cm over such
// floor). Then floor whose cameras (an eye 1.6 m over it, a head just under 2.5 m) only the far
// ends of bands reach: over a ramp whose range stops under a range above it (head_room.h;
// warfare, stormkeep, bloodprison), where the camera stands over that range's top; a fill there
// starts over that top, its capture point half way up the head room left.
// Each group of such cells gets a probe of its own: the cells within a gap of one another on
// one storey, its inner range over them, its band as every range's (kept to the floor in its
// probe's sight, bands_in_sight.h); floor a fill's cut left uncovered is grouped and filled
// again. A fill over floor a volume covers already is optional: it is not made when its band
// must be pulled into sight, and run_layout drops it when it is in a crowd of bands the trim
// cannot free (overlap_trim.h).

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
  bool optional = false;  // over floor some volume covers already
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
