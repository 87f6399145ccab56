#pragma once
// Enlighten's blend distance (the Enlighten documentation): the squared distance from a point to
// the closest point of the probe's box, measured in the box's own frame; the weight is 1 / (epsilon
// + distSq). A sphere influence is measured to its bounding cube, as the runtime export writes it
// (geometry/export/make_runtime_export.cpp), so a runtime gets the same weights.

#include "core/scene/influence_volume.h"

#include <glm/vec3.hpp>

namespace probeproxy {

inline constexpr double kEnlightenEpsilon =
    1e-6;  // the Enlighten documentation: 1 / (epsilon + distSq), m^2

// Squared metres; 0 inside the box.
double enlightenDistanceSq(const InfluenceVolume& influence, glm::dvec3 pointMeters);

}  // namespace probeproxy
