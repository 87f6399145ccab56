// Validation against Cycles: the suite's mirror views rebuilt from each
// probe's Cycles cubemap, on the box room whose artist box is exactly the room (tiny_closet:
// one 1.0 x 0.8 x 2.2 m box, walls within half a metre of the probe, where parallax is
// largest). The bound is the true-hit reconstruction: the perfect proxy through the same
// cubemap.

#include "core/cube/cubemap_io.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/level/load_level.h"
#include "geometry/mirror_view/radiance_lookups.h"
#include "geometry/pointcloud/probe_point_cloud.h"
#include "geometry/probe_proxies/authored_proxy_shape.h"
#include "geometry/scene/scene_file.h"

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace probeproxy {
namespace {

const std::filesystem::path kSuite = PROBEPROXY_SUITE_DIR;
const std::filesystem::path kOut = PROBEPROXY_TEST_OUT_DIR;

struct BoxLevel {
  explicit BoxLevel(const std::string& name)
      : scene(readSceneFile(kSuite / name / (name + ".scene.json"))), level(loadLevel(scene)) {}
  Scene scene;
  LevelRayCaster level;
  const Probe& probe(const std::string& name) const {
    for (const Probe& p : scene.probes)
      if (p.name == name) return p;
    throw std::runtime_error("no probe " + name);
  }
  BoxShape box(const Probe& p) const {
    return std::get<BoxShape>(*authoredProxyShape(p.proxy, scene));
  }
  Cubemap cube(const Probe& p) const {
    return readCubemap((scene.file.parent_path() / *p.cubemap).string());
  }
};

// The same box through the obb method: turned a quarter about Z, with x and y swapped.
BoxShape asObb(const BoxShape& box) {
  BoxShape obb = box;
  obb.halfExtentsMeters = {box.halfExtentsMeters.y, box.halfExtentsMeters.x,
                           box.halfExtentsMeters.z};
  obb.worldFromBox = glm::angleAxis(glm::half_pi<double>(), glm::dvec3(0, 0, 1));
  return obb;
}

// The suite's levels that are one box whose artist box is exactly the room.
class BoxRoom : public ::testing::TestWithParam<std::string> {};

TEST_P(BoxRoom, ExactBoxIsWithinOneDecibelOfTheTrueHitBound) {
  const BoxLevel room(GetParam());
  for (const std::filesystem::path& file : mirrorViewFiles(room.scene)) {
    const MirrorView view = readMirrorView(file);
    const MirrorViewReference ref = loadMirrorViewReference(view);
    ASSERT_GT(std::count(ref.mask.begin(), ref.mask.end(), 1), 50) << file;
    const Probe& probe = mirrorViewProbe(room.scene, view);
    const Cubemap cube = room.cube(probe);
    const BoxShape box = room.box(probe);
    ASSERT_EQ(methodId(ProxyShape(asObb(box))), "obb");
    const glm::dvec3 c = probe.captureMeters;
    const auto run = [&](const std::string& name, const RadianceLookup& lookup) {
      const MirrorViewReconstruction rec = reconstructMirrorView(ref, lookup);
      writeMirrorViewImages(kOut / GetParam(), view.name + "_" + name, ref, rec);
      std::cout << view.name << " " << name << ": PSNR " << rec.error.psnrDb << " dB, MAE "
                << rec.error.meanAbsError << ", miss " << rec.error.missRate << ", peak "
                << rec.error.peak << ", pixels " << rec.error.pixels << "\n";
      return rec.error;
    };
    const ImageErrorFigures bound = run("true_hit", trueHitRadianceLookup(cube, room.level, c));
    const ImageErrorFigures aabb = run("aabb", proxyRadianceLookup(cube, box, c));
    const ImageErrorFigures obb = run("obb", proxyRadianceLookup(cube, asObb(box), c));
    const ImageErrorFigures infinite =
        run("infinite", proxyRadianceLookup(cube, InfiniteShape{}, c));
    EXPECT_EQ(bound.missRate, 0.0);
    EXPECT_EQ(aabb.missRate, 0.0);
    EXPECT_EQ(obb.missRate, 0.0);
    EXPECT_GT(aabb.psnrDb, bound.psnrDb - 1.0) << file;
    EXPECT_GT(obb.psnrDb, bound.psnrDb - 1.0) << file;
    EXPECT_LT(infinite.psnrDb, bound.psnrDb - 3.0) << file;
  }
}

TEST_P(BoxRoom, ExactBoxAngularErrorOnTheMirrorFloor) {
  const BoxLevel room(GetParam());
  for (const Probe& probe : room.scene.probes) {
    const std::vector<ReflectionSample> samples =
        buildReflectionSamples(room.level, probe, SampleSet::MirrorFloor);
    const glm::dvec3 c = probe.captureMeters;
    const ErrorFigures aabb = evaluateShape(room.box(probe), c, samples);
    const ErrorFigures obb = evaluateShape(asObb(room.box(probe)), c, samples);
    const ErrorFigures infinite = evaluateShape(InfiniteShape{}, c, samples);
    std::cout << probe.name << " p95 deg: aabb " << aabb.p95Deg << ", obb " << obb.p95Deg
              << ", infinite " << infinite.p95Deg << " (" << samples.size() << " samples)\n";
    EXPECT_LT(aabb.p95Deg, 0.05) << probe.name;
    EXPECT_LT(obb.p95Deg, 0.05) << probe.name;
    EXPECT_GT(infinite.p95Deg, 100.0 * aabb.p95Deg) << probe.name;
  }
}

// Hodgman's proxy-free method on levels where one box is not the answer: it must see the
// reflection (few misses) and beat the uncorrected cubemap.
class PointCloudView : public ::testing::TestWithParam<std::string> {};

TEST_P(PointCloudView, BeatsInfiniteWithFewMisses) {
  const BoxLevel room(GetParam());
  for (const std::filesystem::path& file : mirrorViewFiles(room.scene)) {
    const MirrorView view = readMirrorView(file);
    MirrorViewReference ref = loadMirrorViewReference(view);
    // Every 8th floor pixel: the splat costs about a millisecond per shading point.
    std::size_t seen = 0;
    for (std::uint8_t& m : ref.mask) m = m && seen++ % 8 == 0;
    const Probe& probe = mirrorViewProbe(room.scene, view);
    const Cubemap cube = room.cube(probe);
    const glm::dvec3 c = probe.captureMeters;
    const PointCloud cloud = probePointCloud(room.level, cube, c);
    const ImageErrorFigures bound =
        reconstructMirrorView(ref, trueHitRadianceLookup(cube, room.level, c)).error;
    const ImageErrorFigures infinite =
        reconstructMirrorView(ref, proxyRadianceLookup(cube, InfiniteShape{}, c)).error;
    const MirrorViewReconstruction points =
        reconstructMirrorView(ref, pointCloudRadianceLookup(cloud, PointCloudOptions{}));
    writeMirrorViewImages(kOut / GetParam(), view.name + "_pointcloud", ref, points);
    std::cout << view.name << ": pointcloud " << points.error.psnrDb << " dB (miss "
              << points.error.missRate << "), bound " << bound.psnrDb << ", infinite "
              << infinite.psnrDb << "\n";
    EXPECT_LT(points.error.missRate, 0.01) << file;
    EXPECT_GT(points.error.psnrDb, infinite.psnrDb + 3.0) << file;
  }
}

INSTANTIATE_TEST_SUITE_P(Suite, PointCloudView, ::testing::Values("corridor", "l_room"));

INSTANTIATE_TEST_SUITE_P(Suite, BoxRoom, ::testing::Values("tiny_closet", "corridor"));

}  // namespace
}  // namespace probeproxy
