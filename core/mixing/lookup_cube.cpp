#include "core/mixing/lookup_cube.h"

#include <stdexcept>

namespace probeproxy {

LookupCube emptyLookupCube(int faceSize) {
  if (faceSize < 1) throw std::invalid_argument("lookup cube face size must be at least 1");
  LookupCube cube;
  cube.faceSize = faceSize;
  const auto texels = static_cast<std::size_t>(faceSize) * static_cast<std::size_t>(faceSize);
  for (int f = 0; f < kCubeFaceCount; ++f) {
    cube.lookupMeters[f].assign(texels, glm::dvec3(0.0));
    cube.miss[f].assign(texels, 1);
  }
  return cube;
}

glm::dvec3 texelRayDirection(CubeFace face, int col, int row, int faceSize) {
  const CubeFaceAxes& a = cubeFaceAxes()[static_cast<int>(face)];
  const double n = faceSize;
  const double u = (col + 0.5) / n;
  const double v = (row + 0.5) / n;
  return glm::dvec3(a.forward) + (2.0 * u - 1.0) * glm::dvec3(a.right) +
         (1.0 - 2.0 * v) * glm::dvec3(a.up);
}

}  // namespace probeproxy
