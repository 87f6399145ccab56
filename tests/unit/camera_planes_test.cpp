// weight_jump's planes: the capture heights, one a band of height, the lowest in it.

#include "geometry/validate/camera_planes.h"

#include <gtest/gtest.h>

#include <vector>

namespace probeproxy {
namespace {

TEST(CameraPlaneHeights, HeightsWithinABandOfTheLowestAreOnePlane) {
  const std::vector<double> captures{1.65, 1.6, 0.2, 1.6000001, 1.71, 1.95, 0.2};
  EXPECT_EQ(cameraPlaneHeights(captures), (std::vector<double>{0.2, 1.6, 1.71, 1.95}));
}

TEST(CameraPlaneHeights, AHeightForEveryProbeOnAHillBecomesAPlaneATenthOfAMetre) {
  std::vector<double> captures;
  for (int p = 0; p < 1000; ++p) captures.push_back(0.25 + 0.003 * p);  // 3 m of hill
  const std::vector<double> planes = cameraPlaneHeights(captures);
  EXPECT_LE(planes.size(), 31u);
  for (std::size_t i = 1; i < planes.size(); ++i)
    EXPECT_GE(planes[i], planes[i - 1] + kCameraPlaneBandMeters);
  EXPECT_EQ(planes.front(), 0.25);
}

}  // namespace
}  // namespace probeproxy
