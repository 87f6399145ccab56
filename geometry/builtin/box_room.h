#pragma once
// A closed axis-aligned box room, faces wound to face inwards. The analytic test level: every
// distance and every true hit in it has an exact answer.

#include "geometry/level/level_mesh.h"

#include <string>

namespace probeproxy {

LevelMesh boxRoom(glm::vec3 minMeters, glm::vec3 maxMeters, const std::string& name = "room");

// Exact distance from `insideMeters` along unit `direction` to the walls of that room.
double boxRoomDistance(glm::dvec3 minMeters, glm::dvec3 maxMeters, glm::dvec3 insideMeters,
                       glm::dvec3 direction);

}  // namespace probeproxy
