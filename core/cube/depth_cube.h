#pragma once
// How far the level is from a capture point in every texel direction: the depth a probe's
// cubemap lacks. Owns its faces.

#include "core/cube/cube_face.h"

#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace probeproxy {

struct DepthCube {
  glm::dvec3 captureMeters{0.0};  // world frame
  int faceSize = 0;               // N: every face is N x N texels
  // distanceMeters[face][row * N + col]: Euclidean distance from the capture point to the first
  // surface along the texel's centre direction (cube_face.h); +inf where nothing is hit (sky).
  std::array<std::vector<float>, kCubeFaceCount> distanceMeters;

  float at(CubeFace face, int col, int row) const {
    return distanceMeters[static_cast<int>(face)][static_cast<std::size_t>(row) * faceSize + col];
  }
};

}  // namespace probeproxy
