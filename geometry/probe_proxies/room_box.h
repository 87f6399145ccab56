#pragma once
// The room the capture point stands in, as an artist boxes it: along each world axis, both
// ways, how far the walls are. The hull of everything a probe sees is not its room: through a
// door or round an L's corner it sees the next room, the hull's facet spans the opening, and
// the wall beside the probe is lost from every plane subset. Rays along the axes find that
// wall. Each direction is a fan of parallel rays around the capture point and takes their
// median, so a pillar in front of the probe or a doorway beside it does not decide the face.

#include "core/proxy/proxy_shape.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <span>

namespace probeproxy {

inline constexpr double kRoomFanOffsetMeters = 1.0;  // the fan's rays stand this far apart

// Distances from the capture point to the walls along -x, +x, -y, +y, -z, +z; infinite where
// most rays of the fan reach nothing (sky).
std::array<double, 6> axisWallDistances(const LevelRayCaster& level, glm::dvec3 captureMeters);

// The box those walls make; a direction open to the sky takes the extent of `seenPointsMeters`
// there. Nothing when the sky is open that way and nothing is seen.
std::optional<BoxShape> roomBox(glm::dvec3 captureMeters, const std::array<double, 6>& walls,
                                std::span<const glm::dvec3> seenPointsMeters);

}  // namespace probeproxy
