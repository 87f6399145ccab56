#include "core/cube/write_depth_cube.h"

#include "core/image/write_exr.h"

#include <stdexcept>

namespace probeproxy {

std::filesystem::path cubeFacePath(const std::string& pattern, CubeFace face) {
  const std::string token = "{face}";
  const std::size_t at = pattern.find(token);
  if (at == std::string::npos)
    throw std::invalid_argument("cube file pattern lacks {face}: " + pattern);
  std::string path = pattern;
  path.replace(at, token.size(), cubeFaceName(face));
  return path;
}

void writeDepthCube(const DepthCube& cube, const std::string& pattern) {
  for (int f = 0; f < kCubeFaceCount; ++f) {
    writeExr(cubeFacePath(pattern, CubeFace(f)), cube.faceSize, cube.faceSize, {"Z"},
             cube.distanceMeters[f]);
  }
}

}  // namespace probeproxy
