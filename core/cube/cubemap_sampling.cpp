#include "core/cube/cubemap_sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace probeproxy {

namespace {

glm::vec3 fetch(const CubemapLevel& l, int face, int col, int row) {
  const std::size_t at = (static_cast<std::size_t>(row) * l.faceSize + col) * 3;
  const std::vector<float>& rgb = l.rgb[face];
  return {rgb[at], rgb[at + 1], rgb[at + 2]};
}

// Texel (col, row) of `face`, where at most one of col, row may lie one texel outside the face:
// then the texel of the adjacent face that holds the extended centre's direction.
glm::vec3 fetchAcrossEdge(const CubemapLevel& l, CubeFace face, int col, int row) {
  const int n = l.faceSize;
  if (col >= 0 && col < n && row >= 0 && row < n) return fetch(l, static_cast<int>(face), col, row);
  const float size = static_cast<float>(n);
  const glm::vec2 uv((static_cast<float>(col) + 0.5f) / size,
                     (static_cast<float>(row) + 0.5f) / size);
  const FaceUv other = faceUvFromDirection(directionFromFaceUv(face, uv));
  const int c = std::clamp(static_cast<int>(std::floor(other.uv.x * size)), 0, n - 1);
  const int r = std::clamp(static_cast<int>(std::floor(other.uv.y * size)), 0, n - 1);
  return fetch(l, static_cast<int>(other.face), c, r);
}

glm::vec3 texelOrNeighbour(const CubemapLevel& l, CubeFace face, int col, int row) {
  const int n = l.faceSize;
  const bool colOut = col < 0 || col >= n;
  const bool rowOut = row < 0 || row >= n;
  if (!(colOut && rowOut)) return fetchAcrossEdge(l, face, col, row);
  // Beyond a cube corner: three faces meet there and no fourth texel exists. Use the mean of
  // the three corner texels, which every face around the corner sees the same way.
  const int cc = std::clamp(col, 0, n - 1);
  const int rr = std::clamp(row, 0, n - 1);
  return (fetch(l, static_cast<int>(face), cc, rr) + fetchAcrossEdge(l, face, col, rr) +
          fetchAcrossEdge(l, face, cc, row)) /
         3.0f;
}

glm::vec3 sampleLevel(const CubemapLevel& l, const FaceUv& at) {
  const float size = static_cast<float>(l.faceSize);
  // Continuous texel coordinates: texel (c, r) has its centre at (c, r).
  const float x = at.uv.x * size - 0.5f;
  const float y = at.uv.y * size - 0.5f;
  const float x0 = std::floor(x);
  const float y0 = std::floor(y);
  const float fx = x - x0;
  const float fy = y - y0;
  const int c0 = static_cast<int>(x0);
  const int r0 = static_cast<int>(y0);
  const glm::vec3 t00 = texelOrNeighbour(l, at.face, c0, r0);
  const glm::vec3 t10 = texelOrNeighbour(l, at.face, c0 + 1, r0);
  const glm::vec3 t01 = texelOrNeighbour(l, at.face, c0, r0 + 1);
  const glm::vec3 t11 = texelOrNeighbour(l, at.face, c0 + 1, r0 + 1);
  return (1.0f - fy) * ((1.0f - fx) * t00 + fx * t10) + fy * ((1.0f - fx) * t01 + fx * t11);
}

}  // namespace

glm::vec3 sampleBilinear(const Cubemap& cube, glm::vec3 direction, float level) {
  if (cube.levels.empty()) throw std::invalid_argument("sampleBilinear: the cubemap is empty");
  if (std::isnan(level) || std::isnan(direction.x) || std::isnan(direction.y) ||
      std::isnan(direction.z)) {
    throw std::invalid_argument("sampleBilinear: NaN level or direction");
  }
  const FaceUv at = faceUvFromDirection(direction);
  const float top = static_cast<float>(cube.numLevels() - 1);
  const float clamped = std::clamp(level, 0.0f, top);
  const int l0 = static_cast<int>(std::floor(clamped));
  const float t = clamped - static_cast<float>(l0);
  const glm::vec3 a = sampleLevel(cube.levels[static_cast<std::size_t>(l0)], at);
  if (t == 0.0f) return a;
  const glm::vec3 b = sampleLevel(cube.levels[static_cast<std::size_t>(l0 + 1)], at);
  return (1.0f - t) * a + t * b;
}

float mipFromRoughness(float roughness, int numMips) {
  if (numMips < 1) throw std::invalid_argument("mipFromRoughness: numMips must be at least 1");
  if (std::isnan(roughness)) throw std::invalid_argument("mipFromRoughness: roughness is NaN");
  if (roughness <= 0.0f) return 0.0f;
  const float mip = static_cast<float>(numMips) + 2.0f * std::log2(roughness);
  return std::clamp(mip, 0.0f, static_cast<float>(numMips - 1));
}

}  // namespace probeproxy
