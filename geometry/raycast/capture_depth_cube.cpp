#include "geometry/raycast/capture_depth_cube.h"

#include <stdexcept>

namespace probeproxy {

std::vector<Ray> depthCubeRays(glm::dvec3 captureMeters, int faceSize) {
  if (faceSize <= 0) throw std::invalid_argument("depth cube face size must be positive");
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(kCubeFaceCount) * faceSize * faceSize);
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < faceSize; ++row) {
      for (int col = 0; col < faceSize; ++col) {
        // Unit directions, so t is the Euclidean distance in metres.
        rays.push_back({captureMeters, texelDirection(CubeFace(f), col, row, faceSize)});
      }
    }
  }
  return rays;
}

std::vector<RayHit> castDepthCubeRays(const LevelRayCaster& level, glm::dvec3 captureMeters,
                                      int faceSize) {
  const std::vector<Ray> rays = depthCubeRays(captureMeters, faceSize);
  std::vector<RayHit> hits(rays.size());
  level.firstHits(rays, hits, /*coherent=*/true);
  return hits;
}

DepthCube depthCubeFromHits(std::span<const RayHit> hits, glm::dvec3 captureMeters, int faceSize) {
  DepthCube cube;
  cube.captureMeters = captureMeters;
  cube.faceSize = faceSize;
  const std::size_t perFace = static_cast<std::size_t>(faceSize) * faceSize;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    cube.distanceMeters[f].resize(perFace);
    for (std::size_t i = 0; i < perFace; ++i) cube.distanceMeters[f][i] = hits[f * perFace + i].t;
  }
  return cube;
}

DepthCube captureDepthCube(const LevelRayCaster& level, glm::dvec3 captureMeters, int faceSize) {
  return depthCubeFromHits(castDepthCubeRays(level, captureMeters, faceSize), captureMeters,
                           faceSize);
}

}  // namespace probeproxy
