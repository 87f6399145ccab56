#pragma once
// The depth cube seen from a capture point: one Embree ray per texel centre.

#include "core/cube/depth_cube.h"
#include "geometry/raycast/level_ray_caster.h"

namespace probeproxy {

DepthCube captureDepthCube(const LevelRayCaster& level, glm::dvec3 captureMeters, int faceSize);

// The rays captureDepthCube casts, face by face, row by row: for benchmarks and tests.
std::vector<Ray> depthCubeRays(glm::dvec3 captureMeters, int faceSize);

// Their hits, in the same order (t in metres: the rays are unit length).
std::vector<RayHit> castDepthCubeRays(const LevelRayCaster& level, glm::dvec3 captureMeters,
                                      int faceSize);

// The depth cube those hits make.
DepthCube depthCubeFromHits(std::span<const RayHit> hits, glm::dvec3 captureMeters, int faceSize);

}  // namespace probeproxy
