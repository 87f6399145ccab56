#pragma once
// A box's blend band reaches kOuterBandOverGap gaps past its inner range, and where the range
// ends at a wall the band reaches through it, into floor its probe has never seen: the leak
// validate's influence_leak measures (skyway's layout: nearly all its leaks, 5-22% of a
// probe's influence). So a side whose band holds floor out of the probe's sight
// (geometry/raycast/room_in_sight.h) comes in, inner range and band together (they share a
// centre), until the share of its influence on such floor is under kLeakShareTarget. Its own
// floor by the wall is then in its band, where no other probe reaches through the wall either:
// the normalised weight is still its own, whole. Only as far as needed: a band pulled in
// blends less with the neighbours on that side. Where a strip narrower than the gap is still
// over the target so (floor out of sight along it, not past its end), an end comes in further,
// its floor left to the neighbours' bands or the uncovered floor's fills.

#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

namespace probeproxy {

// validate's influence_leak allows 5% (ValidateOptions::maxLeakShare); it walks a finer floor
// than the layout's cells.
inline constexpr double kLeakShareTarget = 0.04;

// innerLo/innerHi: an axis-aligned inner range (floorRectBounds) whose outer range reaches
// kOuterBandOverGap x gapMeters past it across the floor (influenceOfBounds); its x and y sides
// move in, keeping the capture point kCaptureMarginMeters inside.
void pullBandsIntoSight(const LevelRayCaster& level, const WalkableFloor& floor,
                        glm::dvec3 captureMeters, double gapMeters, glm::dvec3& innerLo,
                        glm::dvec3& innerHi);

}  // namespace probeproxy
