// A proxy judged on the floor its probe serves in the blend (geometry/survey/served_error.h),
// the one test validate's proxy rule and the layout's proxy choice share.

#include "geometry/survey/served_error.h"
#include "geometry/builtin/box_room.h"
#include "geometry/evaluation/reflection_samples.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace probeproxy {
namespace {

// A 10 x 6 x 3 m room, x -4..6: one probe's volume is the room, inner range and all.
const BoxShape kRoom{{1.0, 0.0, 1.5}, {5.0, 3.0, 1.5}, glm::dquat(1, 0, 0, 0)};

BoxInfluence boxVolume(glm::dvec3 lo, glm::dvec3 hi, glm::dvec3 innerLo, glm::dvec3 innerHi) {
  BoxInfluence v;
  v.centerMeters = 0.5 * (innerLo + innerHi);
  v.innerHalfExtentsMeters = 0.5 * (innerHi - innerLo);
  v.halfExtentsMeters = glm::max(v.centerMeters - lo, hi - v.centerMeters);
  return v;
}

class ServedFloor : public ::testing::Test {
 protected:
  LevelRayCaster level{boxRoom(glm::vec3(kRoom.centerMeters - kRoom.halfExtentsMeters),
                               glm::vec3(kRoom.centerMeters + kRoom.halfExtentsMeters))};
  Probe probe = [] {
    Probe p;
    p.name = "room";
    p.captureMeters = {-1.5, 0.5, 1.6};
    p.influence = boxVolume(
        kRoom.centerMeters - kRoom.halfExtentsMeters, kRoom.centerMeters + kRoom.halfExtentsMeters,
        kRoom.centerMeters - kRoom.halfExtentsMeters, kRoom.centerMeters + kRoom.halfExtentsMeters);
    return p;
  }();
  std::vector<ReflectionSample> samples =
      buildReflectionSamples(level, probe, SampleSet::MirrorFloor);
};

TEST_F(ServedFloor, ANeighboursSmallerInnerRangeTakesItsFloorAway) {
  // The east half's own probe, its inner range x 1..6: the smaller volume takes all of it.
  const std::vector<InfluenceVolume> volumes = {
      probe.influence, boxVolume({0, -3, 0}, {6, 3, 3}, {1, -3, 0}, {6, 3, 3})};
  const std::vector<double> alone = servedWeights({volumes.data(), 1}, 0, samples);
  const std::vector<double> shared = servedWeights(volumes, 0, samples);
  int east = 0, west = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    EXPECT_DOUBLE_EQ(alone[i], 1.0);
    const double x = samples[i].xMeters.x;
    if (x > 1.01) {
      EXPECT_EQ(shared[i], 0.0) << x;
      ++east;
    }
    if (x < -0.01) {  // outside the neighbour's outer range
      EXPECT_DOUBLE_EQ(shared[i], 1.0) << x;
      ++west;
    }
  }
  EXPECT_GT(east, 500);
  EXPECT_GT(west, 500);
}

TEST_F(ServedFloor, TheRoomsBoxServesItExactlyAndNoProxyMissesMostOfIt) {
  const std::vector<double> weights(samples.size(), 1.0);
  const ServedError exact = servedError(kRoom, probe.captureMeters, samples, weights, 5.0);
  const ServedError none = servedError(InfiniteShape{}, probe.captureMeters, samples, weights, 5.0);
  EXPECT_LT(exact.p95Deg, 0.05);
  EXPECT_EQ(exact.overShare, 0.0);
  EXPECT_GT(none.overShare, 0.5);
  EXPECT_GT(none.p95Deg, 20.0);
  EXPECT_TRUE(servesClearlyBetter(exact, none));
  EXPECT_FALSE(servesClearlyBetter(none, exact));
  // No weighted floor: nothing to judge, and nothing is better than it.
  const std::vector<double> zero(samples.size(), 0.0);
  const ServedError hidden = servedError(kRoom, probe.captureMeters, samples, zero, 5.0);
  EXPECT_TRUE(std::isnan(hidden.p95Deg));
  EXPECT_EQ(hidden.overShare, 0.0);
  EXPECT_FALSE(servesClearlyBetter(exact, hidden));
}

TEST(ServesClearlyBetter, LessFloorOverByTwoPointsWithATailNoWorseThanNoise) {
  const ServedError kept{9.0, 0.20};
  EXPECT_TRUE(servesClearlyBetter({9.2, 0.17}, kept));   // within 2% + 0.05 deg
  EXPECT_FALSE(servesClearlyBetter({9.3, 0.10}, kept));  // a worse tail
  EXPECT_FALSE(servesClearlyBetter({5.0, 0.19}, kept));  // one point less is noise
}

TEST(ServesClearlyBetter, PastAGrossTailTheFloorOverTheToleranceDecides) {
  // aneurysm's probe_008: the obb's served floor 85% over 5 deg, p95 112 deg; a convex fit's
  // 31%, p95 a miss.
  const ServedError gross{112.0, 0.85};
  EXPECT_TRUE(servesClearlyBetter({180.0, 0.31}, gross));
  EXPECT_FALSE(servesClearlyBetter({180.0, 0.84}, gross));  // one point less is noise still
  const ServedError justUnder{89.9, 0.85};
  EXPECT_FALSE(servesClearlyBetter({180.0, 0.31}, justUnder));
}

}  // namespace
}  // namespace probeproxy
