#pragma once
// Where `layout` may put a probe: capture points over the walkable floor, one per floor cell
// on a grid of the layout's spacing (every storey of a grid column its own), at a capture
// height that suits the room (the layout's height, at most half the free height above the
// floor, so a low passage gets its probe in its middle), and at least
// kLayoutCaptureClearanceMeters from every surface. Deterministic, in floor cell order.

#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <span>
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

// The capture point over the first of `cells` (the caller's order of preference: nearest the
// middle of what the probe serves first) that stands kLayoutCaptureClearanceMeters clear of
// every surface, else over the clearest of them, with its clearance; where no centre is
// kMinCaptureClearanceMeters clear, the same a quarter cell off the centres. A floor cell's centre
// can lie in a wall's plane (the map's grid and the floor's agree: warfare's fills had a capture
// point 0.5 mm from a wall), and a scene may not hold such a probe.
struct ClearCapture {
  glm::dvec3 captureMeters{0.0};
  double clearanceMeters = -1.0;
};
ClearCapture clearCaptureAbove(const LevelRayCaster& level, const WalkableFloor& floor,
                               std::span<const std::size_t> cells, double heightMeters);

// A capture point that a cut under a range above brought down from `chosenMeters`
// (keepClearOfInnerRanges moves it half way up the air left over `floorMeters`, under
// `topMeters`) can land in a surface: under a ramp's face (darkzone: its fill saw none of its
// floor), on a platform's underside (warfare with a 0.75 m band: the layout could not be
// written). Over the same point in plan, it moves to the first of half way up the air over the
// floor under it (a ramp's, a stair's), then lower and higher, that stands over a floor, not in
// a solid (geometry/raycast/open_space.h), kLayoutCaptureClearanceMeters clear. False where none
// does: so little air is left that the probe is not made (a fill 8 cm tall under warfare's
// probe_101 captured 2 cm over its floor, and the blend at that height popped). A point not moved
// stays.
bool clearMovedCapture(const LevelRayCaster& level, glm::dvec3 chosenMeters,
                       glm::dvec3& captureMeters, double floorMeters, double topMeters);

// `cells` nearest (in plan) to `middleMeters` first; ties in the given order.
std::vector<std::size_t> nearestFirst(const WalkableFloor& floor, std::vector<std::size_t> cells,
                                      glm::dvec3 middleMeters);

}  // namespace probeproxy
