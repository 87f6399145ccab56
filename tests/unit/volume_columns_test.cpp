// The column index of influence volumes answers what a scan over every volume would: every
// volume whose bounds meet a square, each once, in increasing order (the blend sums in volume
// order, so the layout's bytes depend on it).

#include "geometry/layout/volume_columns.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace probeproxy {
namespace {

TEST(VolumeColumns, NearHoldsEveryVolumeMeetingTheSquareOnceInOrder) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> at(-30.0, 90.0), size(0.2, 25.0), square(0.01, 6.0);
  std::vector<glm::dvec3> lo, hi;
  for (int v = 0; v < 400; ++v) {
    const glm::dvec3 corner(at(random), at(random), 0.0);
    lo.push_back(corner);
    hi.push_back(corner + glm::dvec3(size(random), size(random), 3.0));
  }
  const VolumeColumns columns(lo, hi);
  std::vector<std::uint32_t> near;
  for (int q = 0; q < 2000; ++q) {
    // Squares across the volumes' extent and past it on every side.
    const glm::dvec2 a(at(random) * 1.5 - 15.0, at(random) * 1.5 - 15.0);
    const glm::dvec2 b = a + glm::dvec2(square(random), square(random));
    columns.near(a, b, near);
    EXPECT_TRUE(std::is_sorted(near.begin(), near.end()));
    EXPECT_EQ(std::adjacent_find(near.begin(), near.end()), near.end());
    for (std::uint32_t v = 0; v < lo.size(); ++v) {
      const bool meets = lo[v].x <= b.x && a.x <= hi[v].x && lo[v].y <= b.y && a.y <= hi[v].y;
      if (meets) {
        EXPECT_TRUE(std::binary_search(near.begin(), near.end(), v)) << q << " " << v;
      }
    }
  }
}

TEST(VolumeColumns, NoVolumesGiveNothingNear) {
  const VolumeColumns columns({}, {});
  std::vector<std::uint32_t> near{3};
  columns.near({0.0, 0.0}, {1.0, 1.0}, near);
  EXPECT_TRUE(near.empty());
}

}  // namespace
}  // namespace probeproxy
