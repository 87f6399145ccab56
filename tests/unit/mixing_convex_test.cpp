// The two mixing-step methods on a 20-plane convex proxy: planes tangent to an ellipsoid at the
// 20 corners of a regular dodecahedron (deterministic), closed into a polytope by
// geometry/fit/polytope_from_planes.h. Links geometry for that polytope only.

#include "core/mixing/reflected_camera.h"
#include "geometry/builtin/twenty_plane_proxy.h"
#include "tests/unit/mixing_agreement.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <iostream>

namespace probeproxy {
namespace {

TEST(MixingStep, PerTexelAndRasterizedAgreeOnATwentyPlaneProxyAtEveryMipSize) {
  const glm::dvec3 center(0.4, -0.2, 1.6);
  const ConvexProxy proxy = twentyPlaneProxy(center, {3.5, 2.5, 1.8});
  ASSERT_EQ(proxy.planes.size(), 20u);
  const glm::dvec3 capture = center + glm::dvec3(0.3, 0.2, -0.1);
  const ReflectionPlane floor{{0.0, 0.0, 0.2}, {0.0, 0.0, 1.0}};
  // One camera whose reflection lies outside the proxy, one (closer to the floor) inside.
  for (glm::dvec3 camera : {glm::dvec3(1.2, 0.5, 1.9), glm::dvec3(-0.6, 0.3, 0.5)}) {
    const glm::dvec3 reflected = reflectThroughPlane(camera, floor);
    for (int n = 128; n >= 1; n /= 2) {
      SCOPED_TRACE("camera z " + std::to_string(camera.z) + ", face size " + std::to_string(n));
      const test::AgreementFigures figures =
          test::expectMixingMethodsAgree(proxy, capture, reflected, n);
      EXPECT_GT(figures.bothHit, 0);
      EXPECT_LE(figures.grazingMismatches, 4 * n);
      if (n == 128)
        std::cout << "camera z " << camera.z << ": worst angle / half texel " << figures.worstRatio
                  << ", grazing mismatches " << figures.grazingMismatches << " of " << 6 * n * n
                  << "\n";
    }
  }
}

}  // namespace
}  // namespace probeproxy
