#pragma once
// Where `layout` may put a probe: capture points over the walkable floor, one per floor cell
// on a grid of the layout's spacing (every storey of a grid column its own), at a capture
// height that suits the room (the layout's height, at most half the free height above the
// floor, so a low passage gets its probe in its middle), and at least
// kLayoutCaptureClearanceMeters from every surface. Deterministic, in floor cell order.

#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <vector>

namespace probeproxy {

inline constexpr double kLayoutCaptureClearanceMeters = 0.1;

struct LayoutCandidate {
  glm::dvec3 captureMeters{0.0};
  std::size_t cell = 0;  // the floor cell under it (WalkableFloor::cells)
};

struct LayoutCandidates {
  std::vector<LayoutCandidate> points;
  double spacingMeters = 0.0;  // the grid's, after coarsening
};

// At most `maxCandidates`: the grid's step grows (by whole floor cells) until it fits.
LayoutCandidates layoutCandidates(const LevelRayCaster& level, const WalkableFloor& floor,
                                  double spacingMeters, double captureHeightMeters,
                                  std::size_t maxCandidates);

// The capture point above a floor point: `heightMeters` up, at most half the free height.
glm::dvec3 captureAbove(const LevelRayCaster& level, glm::dvec3 floorMeters, double heightMeters);

}  // namespace probeproxy
