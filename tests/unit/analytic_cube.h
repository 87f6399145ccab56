#pragma once
// Cubemaps whose texels hold an analytic function of their unit centre direction.

#include "core/cube/cubemap.h"

#include <functional>

namespace probeproxy::testing {

inline Cubemap cubeFromFunction(int n, const std::function<glm::vec3(glm::vec3)>& radiance) {
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const glm::vec3 v = radiance(texelDirection(CubeFace(f), col, row, n));
        faces[f].insert(faces[f].end(), {v.x, v.y, v.z});
      }
    }
  }
  return Cubemap::fromFaces(n, std::move(faces));
}

}  // namespace probeproxy::testing
