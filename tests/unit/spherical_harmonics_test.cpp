// SH projection and irradiance (core/sh/spherical_harmonics.h) against analytic answers and
// brute-force integration over every texel of the same cubemap.

#include "core/sh/spherical_harmonics.h"
#include "core/cube/texel_solid_angle.h"

#include "analytic_cube.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

namespace probeproxy {
namespace {

using testing::cubeFromFunction;

constexpr double kPi = 3.14159265358979323846;

glm::vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<float> g;
  return glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
}

// Irradiance by brute force: every texel's radiance * max(0, n . w) * solid angle.
glm::dvec3 bruteForceIrradiance(const Cubemap& cube, glm::vec3 n) {
  const CubemapLevel& l = cube.levels[0];
  glm::dvec3 sum(0.0);
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < l.faceSize; ++row) {
      for (int col = 0; col < l.faceSize; ++col) {
        const double c = glm::dot(n, texelDirection(CubeFace(f), col, row, l.faceSize));
        if (c <= 0.0) continue;
        sum += glm::dvec3(cube.texel(CubeFace(f), 0, col, row)) * c *
               texelSolidAngle(col, row, l.faceSize);
      }
    }
  }
  return sum;
}

TEST(TexelSolidAngle, FacesSumToFourPi) {
  for (int n : {1, 2, 7, 64}) {
    double sum = 0.0;
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) sum += texelSolidAngle(col, row, n);
    }
    EXPECT_NEAR(6.0 * sum, 4.0 * kPi, 1e-12) << n;
  }
  EXPECT_NEAR(texelSolidAngle(0, 0, 1), 4.0 * kPi / 6.0, 1e-12);
}

TEST(SphericalHarmonics, WhiteFurnace) {
  const Cubemap white = cubeFromFunction(32, [](glm::vec3) { return glm::vec3(1.0f); });
  const ShRgb sh = projectCubemapToSh(white);
  EXPECT_NEAR(sh.coefficients[0].r, 2.0 * std::sqrt(kPi), 1e-5);
  for (int k = 1; k < kShL2Count; ++k) EXPECT_NEAR(sh.coefficients[k].g, 0.0f, 1e-5f) << k;
  std::mt19937 rng(4);
  for (int i = 0; i < 50; ++i) {
    const glm::vec3 n = randomUnit(rng);
    EXPECT_NEAR(irradianceFromSh(sh, n, ShOrder::L2).b, kPi, 1e-4);
    EXPECT_NEAR(irradianceFromSh(sh, n, ShOrder::L1).r, kPi, 1e-4);
    EXPECT_NEAR(evaluateSh(sh, n, ShOrder::L2).g, 1.0f, 1e-5f);
  }
}

TEST(SphericalHarmonics, LinearGradientIsCapturedExactlyByL1) {
  // Radiance a + b . w per channel: bands 0 and 1 only. Its irradiance is exactly
  // pi a + (2 pi / 3) b . n.
  const glm::vec3 a(2.0f, 3.0f, 1.5f);
  const glm::vec3 br(0.5f, -1.0f, 0.8f), bg(-2.0f, 0.3f, 0.1f), bb(0.0f, 0.0f, -1.4f);
  const auto radiance = [&](glm::vec3 w) {
    return a + glm::vec3(glm::dot(br, w), glm::dot(bg, w), glm::dot(bb, w));
  };
  const ShRgb sh = projectCubemapToSh(cubeFromFunction(32, radiance));
  for (int k = 4; k < kShL2Count; ++k) {
    EXPECT_NEAR(glm::length(sh.coefficients[k]), 0.0f, 2e-4f) << "band 2 coefficient " << k;
  }
  std::mt19937 rng(5);
  for (int i = 0; i < 100; ++i) {
    const glm::vec3 n = randomUnit(rng);
    const glm::vec3 exact =
        float(kPi) * a +
        float(2.0 * kPi / 3.0) * glm::vec3(glm::dot(br, n), glm::dot(bg, n), glm::dot(bb, n));
    // The midpoint quadrature over 32 x 32 faces and the 6-digit constants: 1e-3 relative.
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(irradianceFromSh(sh, n, ShOrder::L1)[c], exact[c], 1e-3f * float(kPi) * 3.0f);
      EXPECT_NEAR(evaluateSh(sh, n, ShOrder::L1)[c], radiance(n)[c], 3e-3f);
    }
  }
}

TEST(SphericalHarmonics, CosineLobeProjectsToTheKernelFactors) {
  // Funk-Hecke: max(0, a . w) has L_lm = A_l Y_lm(a), A = (pi, 2 pi / 3, pi / 4).
  const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  const ShRgb sh = projectCubemapToSh(cubeFromFunction(
      64, [&](glm::vec3 w) { return glm::vec3(std::max(0.0f, glm::dot(axis, w))); }));
  const std::array<float, kShL2Count> y = shBasis(axis);
  const float factor[3] = {float(kPi), float(2.0 * kPi / 3.0), float(kPi / 4.0)};
  for (int k = 0; k < kShL2Count; ++k) {
    const int band = k == 0 ? 0 : (k < 4 ? 1 : 2);
    EXPECT_NEAR(sh.coefficients[k].r, factor[band] * y[k], 2e-4f) << k;
  }
}

TEST(SphericalHarmonics, OneBrightTexelMatchesSeed002AddLightToSH) {
  // A small light: Lagarde's blog adds SHEvalDirection(l) * intensity; the projection of a texel of
  // radiance L adds Y(w) * L * solid angle: the same with intensity = L * solid angle.
  const int n = 16;
  const glm::vec3 light = texelDirection(CubeFace::py, 3, 11, n);
  const ShRgb sh = projectCubemapToSh(cubeFromFunction(n, [&](glm::vec3 w) {
    return glm::dot(w, light) > 0.99999f ? glm::vec3(100.0f, 50.0f, 10.0f) : glm::vec3(0.0f);
  }));
  const float intensity = 100.0f * float(texelSolidAngle(3, 11, n));
  const glm::vec4 seed(0.282095f, -0.488603f * light.y, 0.488603f * light.z, -0.488603f * light.x);
  const glm::vec4 red = seedL1Buffer(sh)[0];
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(red[k], seed[k] * intensity, 1e-6f) << k;
}

TEST(SphericalHarmonics, L2IrradianceWithinTheKernelBoundOfBruteForce) {
  // A sky gradient, a sun and a patch of wall: sharp features L2 cannot hold.
  const glm::vec3 sun = glm::normalize(glm::vec3(0.4f, 0.2f, 0.9f));
  const auto radiance = [&](glm::vec3 w) {
    glm::vec3 v = glm::vec3(0.2f, 0.3f, 0.6f) * (0.5f + 0.5f * w.z);
    if (glm::dot(w, sun) > 0.97f) v += glm::vec3(20.0f, 18.0f, 15.0f);
    if (w.x < -0.6f && w.z < 0.0f) v += glm::vec3(1.0f, 0.2f, 0.1f);
    return v;
  };
  const Cubemap cube = cubeFromFunction(32, radiance);
  const ShRgb sh = projectCubemapToSh(cube);
  // Bound: E(n) - E2(n) = integral of L(w) (K - K2)(n . w) dw, K the clamped cosine and
  // K2(t) = 3/32 + t/2 + 15 t^2 / 32 its bands 0..2. Both integrate to pi, so for
  // 0 <= L <= Lmax, |error| <= Lmax * (1/2) * integral of |K - K2| = 0.19273 * Lmax.
  double kernelL1 = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double t = -1.0 + (i + 0.5) * 2.0 / 200000;
    kernelL1 += std::abs(std::max(0.0, t) - (3.0 / 32 + t / 2 + 15.0 * t * t / 32)) * 2.0 / 200000;
  }
  kernelL1 *= 2.0 * kPi;
  EXPECT_NEAR(kernelL1, 0.38546, 1e-4);
  const glm::vec3 maxRadiance(20.2f, 18.3f, 15.6f);
  std::mt19937 rng(6);
  double worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 n = randomUnit(rng);
    const glm::dvec3 brute = bruteForceIrradiance(cube, n);
    const glm::vec3 fromSh = irradianceFromSh(sh, n, ShOrder::L2);
    for (int c = 0; c < 3; ++c) {
      const double error = std::abs(fromSh[c] - brute[c]);
      EXPECT_LE(error, 0.5 * kernelL1 * maxRadiance[c] + 1e-3) << "normal " << i;
      worst = std::max(worst, error / (0.5 * kernelL1 * maxRadiance[c]));
    }
  }
  std::printf("largest L2 irradiance error: %.3f of the bound\n", worst);
}

}  // namespace
}  // namespace probeproxy
