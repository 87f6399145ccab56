#pragma once
// Lagarde's normalized distance for an influence volume (Lagarde & Zanuttini 2012, bonus slides): 0
// inside the inner range, rising to 1 at the outer boundary, continuous in between; the influence
// factor is 1 - that. A sphere fades linearly from the inner to the outer radius. A box is measured
// in its own frame (rotation included): each axis fades linearly across its band, and the
// factor is the product of the three axes' factors. (The seed leaves the box's function open;
// the product, unlike the largest axis, keeps two boxes that fade towards the same wall in the
// ratio of their other axes, so blending them does not pop next to that wall.)
//
// An axis whose inner half-extent equals the outer one has no fade band: the factor stays at
// its other axes' value up to that side and drops to 0 on it (a step, which the blend then
// shows as a jump if another volume continues past that side). The outer boundary itself
// counts as outside: the seed's "0% at the boundary of the outer range".

#include "core/scene/influence_volume.h"

#include <glm/vec3.hpp>

namespace probeproxy {

// 0 in the inner range, 1 on and outside the outer boundary, in [0, 1] everywhere.
double normalizedDistance(const InfluenceVolume& influence, glm::dvec3 pointMeters);

// 1 - normalizedDistance: 1 in the inner range, 0 on and outside the outer boundary.
double influenceFactor(const InfluenceVolume& influence, glm::dvec3 pointMeters);

// Whether the volume contributes at the point (influenceFactor > 0): strictly inside the outer
// range.
bool coversPoint(const InfluenceVolume& influence, glm::dvec3 pointMeters);

}  // namespace probeproxy
