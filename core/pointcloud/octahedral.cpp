#include "core/pointcloud/octahedral.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace probeproxy {

namespace {

float signNotZero(float v) { return v < 0.0f ? -1.0f : 1.0f; }

}  // namespace

glm::vec2 octahedralUvFromDirection(glm::vec3 d) {
  const float l1 = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  if (!(l1 > 0.0f)) return {0.5f, 0.5f};
  glm::vec2 p(d.x / l1, d.y / l1);
  if (d.z < 0.0f) {
    p = glm::vec2((1.0f - std::abs(p.y)) * signNotZero(p.x),
                  (1.0f - std::abs(p.x)) * signNotZero(p.y));
  }
  // p in [-1, 1]^2 with +y up; v runs down.
  return {0.5f * (p.x + 1.0f), 0.5f * (1.0f - p.y)};
}

glm::vec3 directionFromOctahedralUv(glm::vec2 uv) {
  const glm::vec2 p(2.0f * uv.x - 1.0f, 1.0f - 2.0f * uv.y);
  glm::vec3 d(p.x, p.y, 1.0f - std::abs(p.x) - std::abs(p.y));
  if (d.z < 0.0f) {
    d.x = (1.0f - std::abs(p.y)) * signNotZero(p.x);
    d.y = (1.0f - std::abs(p.x)) * signNotZero(p.y);
  }
  return glm::normalize(d);
}

void wrapOctahedralTexel(int& col, int& row, int size) {
  if (col < 0) {
    col = -1 - col;
    row = size - 1 - row;
  } else if (col >= size) {
    col = 2 * size - 1 - col;
    row = size - 1 - row;
  }
  if (row < 0) {
    row = -1 - row;
    col = size - 1 - col;
  } else if (row >= size) {
    row = 2 * size - 1 - row;
    col = size - 1 - col;
  }
}

}  // namespace probeproxy
