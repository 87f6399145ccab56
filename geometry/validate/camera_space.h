#pragma once
// Where a camera can be, which is where a blend can pop: Lagarde blends the probes at the point
// of interest, the camera (Lagarde & Zanuttini 2012), so weight_jump and too_many_overlaps look
// there only. A camera stands over the floor a player walks (walkedFloor: the floor survey measures
// and floor_not_covered covers), at most head room above it, in the open. Bands reach into walls,
// over the tops of walls and onto ledges no one reaches, where volumes of neighbouring rooms
// meet at the far edge of both their bands and their normalised weights swing within a
// centimetre (basement: all ten worst jumps of its layout, 0.4 to 1.6 m from the walked floor).

#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <span>

namespace probeproxy {

// reachable[i]: whether the first surface straight under point i is a cell of `walked`, at most
// `headRoomMeters` below it, and the point is not inside a solid block (open_space.h).
void markCameraSpace(const LevelRayCaster& level, const WalkableFloor& walked,
                     double headRoomMeters, std::span<const glm::dvec3> pointsMeters,
                     std::span<char> reachable);

}  // namespace probeproxy
