#pragma once
// A probe's influence volume around the floor it serves: an axis-aligned box whose inner range
// holds that floor (its cells whole, from just under the lowest to head room over the highest)
// and the capture point, and whose outer range reaches `bandMeters` further, into the
// neighbours', so the blend fades across the band instead of jumping at its edge.

#include "core/scene/influence_volume.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/floor_rectangles.h"

#include <glm/vec3.hpp>

#include <span>

namespace probeproxy {

// `cells` index floor.cells; at least one.
BoxInfluence influenceAroundFloor(const WalkableFloor& floor, std::span<const std::size_t> cells,
                                  glm::dvec3 captureMeters, double bandMeters);

// The box whose inner range is the rectangle's (floorRectBounds) and whose outer range reaches
// `bandMeters` past it on every side.
BoxInfluence influenceOfRect(const WalkableFloor& floor, const FloorRect& rect,
                             glm::dvec3 captureMeters, double bandMeters);

}  // namespace probeproxy
