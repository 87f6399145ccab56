#pragma once
// The check both mixing-step tests share: the per-texel (mixing_plane) and rasterized
// (raster_convex) lookup cubes agree within half a texel in direction, texel by texel, at every
// mip level's face size; where exactly one of them misses, the ray must graze the proxy (its
// chord is shorter than a micrometre, or it leaves the proxy within one at E').

#include "core/mixing/lookup_cube.h"
#include "core/mixing/mixing_plane.h"
#include "core/mixing/raster_convex.h"
#include "core/proxy/convex_proxy.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace probeproxy::test {

inline double angleRadians(glm::dvec3 a, glm::dvec3 b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// Half the angular size of texel (col, row): half the smaller of its widths across and down,
// each the angle between the directions through its opposite edge midpoints.
inline double halfTexelRadians(CubeFace face, int col, int row, int n) {
  const double u0 = double(col) / n, u1 = double(col + 1) / n, uc = (col + 0.5) / n;
  const double v0 = double(row) / n, v1 = double(row + 1) / n, vc = (row + 0.5) / n;
  const CubeFaceAxes& a = cubeFaceAxes()[static_cast<int>(face)];
  auto dir = [&](double u, double v) {
    return glm::dvec3(a.forward) + (2 * u - 1) * glm::dvec3(a.right) +
           (1 - 2 * v) * glm::dvec3(a.up);
  };
  return 0.5 *
         std::min(angleRadians(dir(u0, vc), dir(u1, vc)), angleRadians(dir(uc, v0), dir(uc, v1)));
}

struct AgreementFigures {
  int bothHit = 0;
  int bothMiss = 0;
  int grazingMismatches = 0;
  double worstRatio = 0.0;  // largest angle / half texel over the texels both hit
};

inline AgreementFigures expectMixingMethodsAgree(const ConvexProxy& proxy, glm::dvec3 capture,
                                                 glm::dvec3 reflectedCamera, int faceSize) {
  const LookupCube perTexel = mixingPlaneLookups(proxy, capture, reflectedCamera, faceSize);
  const LookupCube raster = rasterConvexLookups(proxy, capture, reflectedCamera, faceSize);
  AgreementFigures figures;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < faceSize; ++row) {
      for (int col = 0; col < faceSize; ++col) {
        const std::size_t i = static_cast<std::size_t>(row) * faceSize + col;
        const glm::dvec3 a = perTexel.lookupMeters[f][i], b = raster.lookupMeters[f][i];
        const std::string where = "face " + std::to_string(f) + " texel (" + std::to_string(col) +
                                  ", " + std::to_string(row) + ") of " + std::to_string(faceSize);
        EXPECT_TRUE(std::isfinite(a.x + a.y + a.z) && std::isfinite(b.x + b.y + b.z)) << where;
        if (perTexel.miss[f][i] && raster.miss[f][i]) {
          ++figures.bothMiss;
        } else if (perTexel.miss[f][i] != raster.miss[f][i]) {
          const glm::dvec3 d =
              glm::normalize(texelRayDirection(static_cast<CubeFace>(f), col, row, faceSize));
          const RayChord chord = rayChord(proxy.planes, reflectedCamera, d);
          const double margin = std::abs(chord.exit - std::max(chord.enter, 0.0));
          EXPECT_LT(margin, 1e-6) << where << ": only one method misses, chord " << chord.enter
                                  << " .. " << chord.exit;
          ++figures.grazingMismatches;
        } else {
          ++figures.bothHit;
          const double ratio =
              angleRadians(a, b) / halfTexelRadians(static_cast<CubeFace>(f), col, row, faceSize);
          figures.worstRatio = std::max(figures.worstRatio, ratio);
          EXPECT_LE(ratio, 1.0) << where;
        }
      }
    }
  }
  return figures;
}

}  // namespace probeproxy::test
