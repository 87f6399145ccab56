#include "core/cube/cube_face.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace probeproxy {

const std::array<CubeFaceAxes, kCubeFaceCount>& cubeFaceAxes() {
  static const std::array<CubeFaceAxes, kCubeFaceCount> axes = {{
      {{+1, 0, 0}, {0, 0, +1}, {0, -1, 0}},  // px
      {{-1, 0, 0}, {0, 0, +1}, {0, +1, 0}},  // nx
      {{0, +1, 0}, {0, 0, +1}, {+1, 0, 0}},  // py
      {{0, -1, 0}, {0, 0, +1}, {-1, 0, 0}},  // ny
      {{0, 0, +1}, {0, +1, 0}, {-1, 0, 0}},  // pz
      {{0, 0, -1}, {0, -1, 0}, {-1, 0, 0}},  // nz
  }};
  return axes;
}

std::string_view cubeFaceName(CubeFace face) {
  static constexpr std::string_view names[kCubeFaceCount] = {"px", "nx", "py", "ny", "pz", "nz"};
  return names[static_cast<int>(face)];
}

glm::vec3 directionFromFaceUv(CubeFace face, glm::vec2 uv) {
  const CubeFaceAxes& a = cubeFaceAxes()[static_cast<int>(face)];
  return a.forward + (2.0f * uv.x - 1.0f) * a.right + (1.0f - 2.0f * uv.y) * a.up;
}

glm::vec3 texelDirection(CubeFace face, int col, int row, int faceSize) {
  const float n = static_cast<float>(faceSize);
  const glm::vec2 uv((static_cast<float>(col) + 0.5f) / n, (static_cast<float>(row) + 0.5f) / n);
  return glm::normalize(directionFromFaceUv(face, uv));
}

FaceUv faceUvFromDirection(glm::vec3 d) {
  const glm::vec3 m = glm::abs(d);
  CubeFace face;
  if (m.x >= m.y && m.x >= m.z) {
    face = d.x >= 0 ? CubeFace::px : CubeFace::nx;
  } else if (m.y >= m.z) {
    face = d.y >= 0 ? CubeFace::py : CubeFace::ny;
  } else {
    face = d.z >= 0 ? CubeFace::pz : CubeFace::nz;
  }
  const float major = std::max(m.x, std::max(m.y, m.z));
  if (major == 0.0f) return {CubeFace::px, {0.5f, 0.5f}};
  // Project onto the face plane at distance 1, then read the right/up coordinates.
  const CubeFaceAxes& a = cubeFaceAxes()[static_cast<int>(face)];
  const glm::vec3 onFace = d / major;
  const float s = glm::dot(onFace, a.right);  // [-1, 1], left to right
  const float t = glm::dot(onFace, a.up);     // [-1, 1], bottom to top
  return {face, {0.5f * (s + 1.0f), 0.5f * (1.0f - t)}};
}

}  // namespace probeproxy
