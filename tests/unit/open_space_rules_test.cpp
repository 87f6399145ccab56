// validate's weight_jump and too_many_overlaps count only where a camera can be
// (geometry/validate/camera_space.h): over the walked floor, within head room, and not inside a
// solid block, even one whose bottom face the map compiler dropped
// (geometry/raycast/open_space.h); capture_outside_level holds a capture point over a platform
// open to the sky inside the level.

#include "geometry/builtin/box_room.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/raycast/open_space.h"
#include "geometry/validate/validation_rules.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace probeproxy {
namespace {

// A 10 x 6 x 3 m room with a solid block `height` m high across it at x 4..6, wound outwards,
// without its bottom face (Quake 3's compiler drops the faces a block rests on).
LevelMesh roomWithBottomlessBlock(double height = 2.0) {
  LevelMesh level = boxRoom({0, 0, 0}, {10, 6, 3});
  LevelMesh block = boxRoom({4, 0, 0}, {6, 6, height}, "block");
  for (glm::uvec3& t : block.triangles) std::swap(t.y, t.z);
  std::erase_if(block.triangles, [&](const glm::uvec3& t) {
    return block.positionsMeters[t.x].z == 0.0f && block.positionsMeters[t.y].z == 0.0f &&
           block.positionsMeters[t.z].z == 0.0f;
  });
  block.parts[0].triangleCount = static_cast<std::uint32_t>(block.triangles.size());
  appendLevelMesh(level, block);
  return level;
}

Probe boxProbe(const std::string& name, glm::dvec3 innerLo, glm::dvec3 innerHi) {
  Probe probe;
  probe.name = name;
  probe.captureMeters = 0.5 * (innerLo + innerHi);
  probe.influence = influenceOfBounds(innerLo, innerHi, 1.0);  // bands 1.5 m
  return probe;
}

TEST(OpenSpace, InsideABottomlessBlockIsSolidAndOverItsTopIsOverAFloor) {
  const LevelRayCaster level(roomWithBottomlessBlock());
  const std::vector<glm::dvec3> points{{2, 3, 1.6}, {5, 3, 1.0}, {5, 3, 2.5}};
  const std::vector<VerticalView> views = lookUpAndDown(level, points);
  EXPECT_FALSE(views[0].insideSolid);
  EXPECT_FLOAT_EQ(views[0].floorBelowMeters, 1.6f);
  EXPECT_TRUE(views[1].insideSolid) << "the floor below is in plain view, yet it is solid";
  EXPECT_FALSE(views[2].insideSolid);
  EXPECT_FLOAT_EQ(views[2].floorBelowMeters, 0.5f) << "the block's top is a floor";
}

std::vector<ValidationFinding> weightJumps(const LevelMesh& mesh) {
  // Two probes whose bands meet, and only touch, at x = 5.
  Scene scene;
  scene.probes = {boxProbe("west", {0, 0, -0.5}, {3.5, 6, 2.5}),
                  boxProbe("east", {6.5, 0, -0.5}, {10, 6, 2.5})};
  const LevelRayCaster level(mesh);
  ValidateOptions options;
  options.weightGridMeters = 0.04;
  std::vector<ValidationFinding> out;
  checkWeightJumps(scene, level, walkedFloor(scene, level, options), options, out);
  return out;
}

TEST(WeightJumpRule, BandsMeetingOverWalkedFloorJumpAndElsewhereDoNot) {
  const std::vector<ValidationFinding> open = weightJumps(boxRoom({0, 0, 0}, {10, 6, 3}));
  ASSERT_EQ(open.size(), 1u);
  EXPECT_EQ(open[0].rule, "weight_jump");
  EXPECT_GT(open[0].value, 0.2);
  EXPECT_TRUE(weightJumps(roomWithBottomlessBlock()).empty()) << "inside a block";
  // Over the top of a wall 0.8 m high (a floor, but no step reaches it), 0.2 m under the
  // capture points' height: the old rule's "over a floor" counted it.
  EXPECT_TRUE(weightJumps(roomWithBottomlessBlock(0.8)).empty()) << "over an unwalked top";
  // Nor in the air 5 m over the floor of a pit, where a camera only falls.
  EXPECT_TRUE(weightJumps(boxRoom({0, 0, -4}, {10, 6, 3})).empty());
}

std::vector<ValidationFinding> overlaps(const LevelMesh& mesh, double xFrom) {
  // Five volumes over x xFrom..xFrom + 3, their inner ranges 0.4 m wide side by side, 0.2 m
  // apart, and 1.5 m high: their bands (1.5 m across, 0.25 m up) all cover x xFrom + 0.9 to
  // xFrom + 1.9, up to 1.75 m over the floor.
  Scene scene;
  for (int i = 0; i < 5; ++i) {
    const double lo = xFrom + 0.6 * i;
    scene.probes.push_back(
        boxProbe(std::string(1, static_cast<char>('a' + i)), {lo, 2, -0.5}, {lo + 0.4, 4, 1.5}));
  }
  const LevelRayCaster level(mesh);
  const ValidateOptions options;
  std::vector<ValidationFinding> out;
  checkOverlaps(scene, level, walkedFloor(scene, level, options), options, out);
  return out;
}

TEST(TooManyOverlapsRule, FiveVolumesMeetingInTheOpenAreFoundAndInsideABlockAreNot) {
  const LevelMesh level = roomWithBottomlessBlock();
  const std::vector<ValidationFinding> open = overlaps(level, 0.5);
  ASSERT_EQ(open.size(), 1u);
  EXPECT_EQ(open[0].rule, "too_many_overlaps");
  EXPECT_EQ(open[0].value, 5.0);
  EXPECT_TRUE(overlaps(level, 3.5).empty()) << "they meet at x 4.4..5.4, inside the 2 m block";
}

std::vector<ValidationFinding> captureOutside(const LevelRayCaster& level, glm::dvec3 capture) {
  Probe probe = boxProbe("p", capture - glm::dvec3(1), capture + glm::dvec3(1));
  std::vector<ValidationFinding> out;
  checkCaptureInsideLevel(level, probe, out);
  return out;
}

TEST(CaptureOutsideLevelRule, OverAPlatformInOpenSpaceIsInsideAndBelowOrBesideItIsNot) {
  // A solid 10 x 10 m platform 0.5 m thick, wound outwards, alone in space: a player stands on
  // its top; over its centre the sky and the void past its edges fill well over half the view.
  LevelMesh platform = boxRoom({-5, -5, -0.5}, {5, 5, 0}, "platform");
  for (glm::uvec3& t : platform.triangles) std::swap(t.y, t.z);
  const LevelRayCaster level(platform);
  EXPECT_TRUE(captureOutside(level, {0, 0, 1.6}).empty()) << "standing on the platform";
  const std::vector<ValidationFinding> below = captureOutside(level, {0, 0, -2.1});
  ASSERT_EQ(below.size(), 1u) << "under the platform: the void below and round its underside";
  EXPECT_EQ(below[0].rule, "capture_outside_level");
  EXPECT_GT(below[0].value, 0.6);
  EXPECT_EQ(captureOutside(level, {20, 0, 1.6}).size(), 1u) << "beside it, over nothing";
  EXPECT_EQ(captureOutside(level, {0, 0, -0.25}).size(), 1u) << "inside the platform";
}

TEST(CaptureOutsideLevelRule, OverANarrowWalkwayIsInsideAndBesideItIsNot) {
  // A walkway 2 m wide and 40 m long in space: under a point 1.6 m over it, the void on either
  // side fills most of the lower half too; right under it is the walkway.
  LevelMesh walkway = boxRoom({-20, -1, -0.5}, {20, 1, 0}, "walkway");
  for (glm::uvec3& t : walkway.triangles) std::swap(t.y, t.z);
  const LevelRayCaster level(walkway);
  EXPECT_TRUE(captureOutside(level, {0, 0, 1.6}).empty()) << "standing on the walkway";
  EXPECT_EQ(captureOutside(level, {0, 3, 1.6}).size(), 1u) << "beside it, over the void";
}

}  // namespace
}  // namespace probeproxy
