#pragma once
// Whether a probe sees the room over a floor point: validate's influence_leak measures with it
// how much of a probe's influence falls behind a wall, and layout keeps every probe's inner
// range and band to floor it holds in sight. One definition, so the layout passes the rule it
// is judged by.
//
// A wall hides space from every point of view near the capture point and at every height; a
// pillar or a crate only from some. So a floor point counts as in sight when one of a few
// viewpoints (the capture point, and points up to 1.5 m beside it along the axes, short of any
// wall) sees the room over it: just under its ceiling (at most 10 m up, over crates and
// partitions), or at eye height (under a grating or a pergola, whose ceiling is the sky through
// its slats: darkzone's walkways, hidden from a probe under them by the slats alone).

#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace probeproxy {

// The capture point first, then up to four points beside it.
std::vector<glm::dvec3> roomViewpoints(const LevelRayCaster& level, glm::dvec3 captureMeters);

// What the viewpoints look for over a floor point.
struct RoomTargets {
  glm::dvec3 underCeilingMeters{0.0};
  glm::dvec3 atEyeHeightMeters{0.0};  // or just under a ceiling lower than that
};

RoomTargets roomTargetsOver(const LevelRayCaster& level, glm::dvec3 floorPointMeters);

bool roomInSight(const LevelRayCaster& level, std::span<const glm::dvec3> viewpoints,
                 const RoomTargets& targets);

}  // namespace probeproxy
