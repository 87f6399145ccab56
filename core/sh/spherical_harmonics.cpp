#include "core/sh/spherical_harmonics.h"

#include "core/cube/texel_solid_angle.h"

#include <glm/geometric.hpp>

#include <array>

namespace probeproxy {

std::array<float, kShL2Count> shBasis(glm::vec3 d) {
  return {0.282095f,
          -0.488603f * d.y,
          0.488603f * d.z,
          -0.488603f * d.x,
          1.092548f * d.x * d.y,
          -1.092548f * d.y * d.z,
          0.315392f * (3.0f * d.z * d.z - 1.0f),
          -1.092548f * d.x * d.z,
          0.546274f * (d.x * d.x - d.y * d.y)};
}

ShRgb projectCubemapToSh(const Cubemap& cube, int level) {
  const CubemapLevel& l = cube.levels.at(static_cast<std::size_t>(level));
  const int n = l.faceSize;
  std::array<glm::dvec3, kShL2Count> sum{};
  for (int face = 0; face < kCubeFaceCount; ++face) {
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const glm::vec3 d = texelDirection(CubeFace(face), col, row, n);
        const std::size_t at = (static_cast<std::size_t>(row) * n + col) * 3;
        const glm::dvec3 radiance(l.rgb[face][at], l.rgb[face][at + 1], l.rgb[face][at + 2]);
        const glm::dvec3 weighted = radiance * texelSolidAngle(col, row, n);
        const std::array<float, kShL2Count> y = shBasis(d);
        for (int k = 0; k < kShL2Count; ++k) sum[k] += weighted * static_cast<double>(y[k]);
      }
    }
  }
  ShRgb sh;
  for (int k = 0; k < kShL2Count; ++k) sh.coefficients[k] = glm::vec3(sum[k]);
  return sh;
}

glm::vec3 evaluateSh(const ShRgb& sh, glm::vec3 direction, ShOrder order) {
  const std::array<float, kShL2Count> y = shBasis(glm::normalize(direction));
  const int count = order == ShOrder::L1 ? 4 : kShL2Count;
  glm::vec3 radiance(0.0f);
  for (int k = 0; k < count; ++k) radiance += sh.coefficients[k] * y[k];
  return radiance;
}

glm::vec3 irradianceFromSh(const ShRgb& sh, glm::vec3 normal, ShOrder order) {
  constexpr float c1 = 0.429043f, c2 = 0.511664f, c3 = 0.743125f, c4 = 0.886227f, c5 = 0.247708f;
  const glm::vec3 n = glm::normalize(normal);
  const auto& L = sh.coefficients;
  // Ramamoorthi & Hanrahan eq. 13, with L1-1, L11, L2-1, L21 negated (Condon-Shortley phase).
  glm::vec3 e = c4 * L[0] + 2.0f * c2 * (-L[3] * n.x - L[1] * n.y + L[2] * n.z);
  if (order == ShOrder::L2) {
    e += c1 * L[8] * (n.x * n.x - n.y * n.y) + c3 * L[6] * n.z * n.z - c5 * L[6] +
         2.0f * c1 * (L[4] * n.x * n.y - L[7] * n.x * n.z - L[5] * n.y * n.z);
  }
  return e;
}

std::array<glm::vec4, 3> seedL1Buffer(const ShRgb& sh) {
  std::array<glm::vec4, 3> buffer;
  for (int c = 0; c < 3; ++c) {
    buffer[c] = {sh.coefficients[0][c], sh.coefficients[1][c], sh.coefficients[2][c],
                 sh.coefficients[3][c]};
  }
  return buffer;
}

}  // namespace probeproxy
