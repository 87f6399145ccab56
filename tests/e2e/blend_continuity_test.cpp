// The must-show on every suite level: Lagarde's blend weights are continuous (largest
// change of any probe's weight between neighbouring points of a 1 cm grid under 0.02) and sum
// to 1 wherever a volume covers the point. The grid spans the union of the influence volumes'
// bounds (nothing applies outside them) in the horizontal plane at each distinct capture
// height, where the point of interest (camera, player) moves, and counts the points above a
// floor of the level (a ray down meets an upward-facing surface, Embree): volumes reach into
// and past walls, where nobody stands. Prints the figures per level.

#include "core/blend/weight_continuity.h"
#include "geometry/level/load_level.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/scene/scene_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace probeproxy {
namespace {

const std::filesystem::path kSuite = PROBEPROXY_SUITE_DIR;
constexpr double kSpacingMeters = 0.01;
constexpr double kLargestJump = 0.02;

class BlendContinuity : public ::testing::TestWithParam<std::string> {};

TEST_P(BlendContinuity, LagardeWeightsAreContinuousOnA1cmGridAndSumToOne) {
  const Scene scene = readSceneFile(kSuite / GetParam() / (GetParam() + ".scene.json"));
  std::vector<InfluenceVolume> volumes;
  std::set<double> heights;
  for (const Probe& p : scene.probes) {
    volumes.push_back(p.influence);
    heights.insert(p.captureMeters.z);
  }
  const LevelRayCaster caster(loadLevel(scene));
  std::vector<Ray> rays;
  std::vector<RayHit> hits;
  const ReachableMask aboveFloor = [&](std::span<const glm::dvec3> points,
                                       std::span<char> reachable) {
    rays.assign(points.size(), Ray{});
    hits.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) rays[i] = {points[i], {0, 0, -1}};
    caster.firstHits(rays, hits, true);
    for (std::size_t i = 0; i < points.size(); ++i) {
      reachable[i] = hits[i].hit() && hits[i].geometricNormal.z > 0.5f;
    }
  };
  for (double z : heights) {
    const WeightContinuity c = measureWeightContinuity(
        volumes, gridOverVolumes(volumes, z, kSpacingMeters), {}, aboveFloor);
    std::printf(
        "%s z=%.2f m: largest jump %.4f (probe %s, (%.2f, %.2f) -> (%.2f, %.2f)), "
        "largest |sum - 1| %.1e, %lld covered of %lld points\n",
        GetParam().c_str(), z, c.largestJump,
        c.jumpProbe < 0 ? "-" : scene.probes[c.jumpProbe].name.c_str(), c.jumpFromMeters.x,
        c.jumpFromMeters.y, c.jumpToMeters.x, c.jumpToMeters.y, c.largestSumError, c.coveredPoints,
        c.points);
    EXPECT_LT(c.largestJump, kLargestJump) << "z = " << z;
    EXPECT_LT(c.largestSumError, 1e-12) << "z = " << z;
    EXPECT_GT(c.coveredPoints, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Suite, BlendContinuity,
                         ::testing::Values("corridor", "l_room", "u_corridors", "hall_pillars",
                                           "attic", "round_room", "courtyard", "tiny_closet",
                                           "hangar"),
                         [](const auto& param) { return param.param; });

}  // namespace
}  // namespace probeproxy
