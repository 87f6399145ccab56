// The mixing step's angular error (geometry/evaluation/evaluate_mixing.h) in a box room that
// is its own proxy: every error is the corrected cube's resolution, so it shrinks as the cube
// grows, and both mixing methods (per texel, rasterized) agree.

#include "geometry/evaluation/evaluate_mixing.h"
#include "core/mixing/corrected_cubemap.h"
#include "core/proxy/proxy_shape.h"
#include "geometry/builtin/box_room.h"
#include "geometry/evaluation/reflection_samples.h"

#include <gtest/gtest.h>

namespace probeproxy {
namespace {

const BoxShape kRoom{{1.0, 0.0, 1.5}, {5.0, 3.0, 1.5}, glm::dquat(1, 0, 0, 0)};
const ReflectionPlane kFloor{{0, 0, 0}, {0, 0, 1}};

struct RoomSamples {
  Probe probe;
  std::vector<ReflectionSample> samples;
};

const RoomSamples& roomSamples() {
  static const RoomSamples room = [] {
    RoomSamples r;
    r.probe.name = "room";
    r.probe.captureMeters = {2.0, 0.5, 1.6};
    BoxInfluence influence;
    influence.centerMeters = kRoom.centerMeters;
    influence.halfExtentsMeters = influence.innerHalfExtentsMeters = kRoom.halfExtentsMeters;
    r.probe.influence = influence;
    const LevelRayCaster level(boxRoom(glm::vec3(kRoom.centerMeters - kRoom.halfExtentsMeters),
                                       glm::vec3(kRoom.centerMeters + kRoom.halfExtentsMeters)));
    ReflectionSampleOptions options;
    options.targetSamples = 1024;
    options.camerasAcross = 4;
    r.samples = buildReflectionSamples(level, r.probe, SampleSet::MirrorFloor, options);
    return r;
  }();
  return room;
}

ErrorFigures mixingError(MixingMethod method, int faceSize) {
  const RoomSamples& room = roomSamples();
  return evaluateMixing(method, convexFromBox(kRoom), room.probe.captureMeters, kFloor,
                        room.samples, faceSize);
}

TEST(EvaluateMixing, EveryFloorSampleIsOnTheMirror) {
  const RoomSamples& room = roomSamples();
  ASSERT_GT(room.samples.size(), 500u);
  EXPECT_EQ(samplesOnPlane(room.samples, kFloor).size(), room.samples.size());
  // A plane 1 cm above the floor holds none of them.
  EXPECT_TRUE(samplesOnPlane(room.samples, {{0, 0, 0.01}, {0, 0, 1}}).empty());
}

TEST(EvaluateMixing, ErrorIsTheCubesResolution) {
  const ErrorFigures coarse = mixingError(MixingMethod::MixingPlane, 32);
  const ErrorFigures fine = mixingError(MixingMethod::MixingPlane, 128);
  EXPECT_EQ(fine.samples, roomSamples().samples.size());
  // Texels 4 times smaller: lookups about 4 times closer (nearest texel).
  EXPECT_LT(fine.p95Deg, 0.5 * coarse.p95Deg);
  EXPECT_LT(fine.medianDeg, 0.5 * coarse.medianDeg);
  EXPECT_LT(fine.medianDeg, 1.0);
  // Misses only where a texel's ray crosses the floor just past a wall: fewer as texels shrink.
  EXPECT_LE(fine.missRate, coarse.missRate);
  EXPECT_LT(fine.missRate, 0.02);
}

TEST(EvaluateMixing, RasterizedAndPerTexelAgree) {
  const ErrorFigures perTexel = mixingError(MixingMethod::MixingPlane, 64);
  const ErrorFigures raster = mixingError(MixingMethod::RasterConvex, 64);
  EXPECT_NEAR(raster.p95Deg, perTexel.p95Deg, 1e-3);
  EXPECT_NEAR(raster.medianDeg, perTexel.medianDeg, 1e-3);
  EXPECT_NEAR(raster.missRate, perTexel.missRate, 0.002);
}

TEST(EvaluateMixing, NearestTexelHoldsTheDirection) {
  // The centre of +x's face and a direction just inside its last column.
  EXPECT_EQ(nearestCubeTexel({1, 0, 0}, 4).face, CubeFace::px);
  const CubeTexel t = nearestCubeTexel({1, 0.99, 0}, 4);
  EXPECT_EQ(t.face, CubeFace::px);
  EXPECT_EQ(t.index % 4 == 0 || t.index % 4 == 3, true);
}

}  // namespace
}  // namespace probeproxy
