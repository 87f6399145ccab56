#pragma once
// The depth cube seen from a capture point: one Embree ray per texel centre.

#include "core/cube/depth_cube.h"
#include "geometry/raycast/level_ray_caster.h"

namespace probeproxy {

DepthCube captureDepthCube(const LevelRayCaster& level, glm::dvec3 captureMeters, int faceSize);

// The rays captureDepthCube casts, face by face, row by row: for benchmarks and tests.
std::vector<Ray> depthCubeRays(glm::dvec3 captureMeters, int faceSize);

}  // namespace probeproxy
