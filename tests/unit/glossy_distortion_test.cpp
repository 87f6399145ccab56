// The glossy analysis of Lagarde & Zanuttini's bonus slides (core/mixing/glossy_distortion.h) in
// the box room with a mirror floor and the room's exact box as proxy.

#include "core/mixing/glossy_distortion.h"
#include "core/proxy/proxy_shape.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iostream>

namespace probeproxy {
namespace {

GlossySetup boxRoomSetup(double bottomMeters) {
  // The room is 6 x 4 x 3 m above the floor z = 0; the proxy reaches down to bottomMeters.
  const double top = 3.0;
  GlossySetup setup;
  setup.proxy = convexFromBox({{0.0, 0.0, 0.5 * (top + bottomMeters)},
                               {3.0, 2.0, 0.5 * (top - bottomMeters)},
                               {1, 0, 0, 0}});
  setup.captureMeters = {0.5, 0.3, 1.4};
  setup.cameraMeters = {1.1, -0.7, 1.7};
  setup.plane = {{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}};
  setup.pixels = 2048;
  return setup;
}

TEST(GlossyDistortion, ZeroAtRoughnessZeroAndGrowingWithRoughness) {
  const auto results = glossyDistortion(boxRoomSetup(0.0), {0.0, 0.1, 0.3, 0.5});
  ASSERT_EQ(results.size(), 4u);
  // A flat mirror: the ray (E', r) passes through x, so both lookups are the same point.
  EXPECT_LT(results[0].figures.maxDeg, 1e-9);
  EXPECT_EQ(results[0].figures.missRate, 0.0);
  EXPECT_EQ(results[0].belowPlane, 0u);
  for (std::size_t i = 1; i < results.size(); ++i) {
    EXPECT_GT(results[i].figures.p95Deg, results[i - 1].figures.p95Deg);
    EXPECT_GT(results[i].figures.medianDeg, results[i - 1].figures.medianDeg);
  }
  for (const GlossyDistortion& r : results)
    std::cout << "roughness " << r.roughness << ": median " << r.figures.medianDeg << " p95 "
              << r.figures.p95Deg << " max " << r.figures.maxDeg << " deg, mixing miss rate "
              << r.figures.missRate << ", below plane " << r.belowPlane << " of "
              << r.figures.samples + r.belowPlane << "\n";
}

TEST(GlossyDistortion, ReflectedCameraOutsideTheProxyMissesAndEnlargingFixesIt) {
  // The seed's red texels: E' = (1.1, -0.7, -1.7) is below the room's proxy, and perturbed
  // reflections that dip under the floor miss it from there.
  const auto room = glossyDistortion(boxRoomSetup(0.0), {0.5});
  EXPECT_GT(room[0].belowPlane, 0u);
  EXPECT_EQ(room[0].mixingMissesBelowPlane, room[0].belowPlane);
  // "Enlarge geometry proxy": 2 m below the floor holds E', and nothing misses any more.
  const auto enlarged = glossyDistortion(boxRoomSetup(-2.0), {0.1, 0.3, 0.5});
  for (const GlossyDistortion& r : enlarged)
    std::cout << "enlarged, roughness " << r.roughness << ": median " << r.figures.medianDeg
              << " p95 " << r.figures.p95Deg << " deg, mixing miss rate " << r.figures.missRate
              << "\n";
  EXPECT_EQ(enlarged[2].mixingMissesBelowPlane, 0u);
  EXPECT_EQ(enlarged[2].figures.missRate, 0.0);
  // Same points and normals: the same number dip below the plane.
  EXPECT_EQ(enlarged[2].belowPlane, room[0].belowPlane);
}

TEST(GlossyDistortion, DeterministicAndChecksItsInput) {
  const auto a = glossyDistortion(boxRoomSetup(0.0), {0.3});
  const auto b = glossyDistortion(boxRoomSetup(0.0), {0.3});
  ASSERT_EQ(a[0].errorsDeg.size(), b[0].errorsDeg.size());
  for (std::size_t i = 0; i < a[0].errorsDeg.size(); ++i)
    EXPECT_EQ(std::memcmp(&a[0].errorsDeg[i], &b[0].errorsDeg[i], sizeof(double)), 0);
  GlossySetup below = boxRoomSetup(0.0);
  below.cameraMeters.z = -1.0;
  EXPECT_THROW(glossyDistortion(below, {0.3}), std::invalid_argument);
  EXPECT_THROW(glossyDistortion(boxRoomSetup(0.0), {1.5}), std::invalid_argument);
}

}  // namespace
}  // namespace probeproxy
