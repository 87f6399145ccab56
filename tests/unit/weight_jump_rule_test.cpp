// validate's weight_jump counts only where a camera can be: over a floor, within head room of
// it, not inside a solid block whose bottom face the map compiler dropped
// (geometry/validate/weight_jump_rule.cpp).

#include "geometry/builtin/box_room.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/validate/validation_rules.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>
#include <vector>

namespace probeproxy {
namespace {

// A 10 x 6 x 3 m room; two probes whose bands meet, and only touch, at x = 5.
Scene bandsMeetingAtX5() {
  Scene scene;
  for (const auto& [name, lo, hi] :
       {std::tuple{"west", glm::dvec3(0, 0, -0.5), glm::dvec3(3.5, 6, 2.5)},
        std::tuple{"east", glm::dvec3(6.5, 0, -0.5), glm::dvec3(10, 6, 2.5)}}) {
    Probe probe;
    probe.name = name;
    probe.captureMeters = {0.5 * (lo.x + hi.x), 3, 1.6};
    probe.influence = influenceOfBounds(lo, hi, 1.0);  // bands 1.5 m
    scene.probes.push_back(probe);
  }
  return scene;
}

std::vector<ValidationFinding> weightJumps(const LevelMesh& mesh) {
  const LevelRayCaster level(mesh);
  ValidateOptions options;
  options.weightGridMeters = 0.04;
  std::vector<ValidationFinding> out;
  checkWeightJumps(bandsMeetingAtX5(), level, options, out);
  return out;
}

TEST(WeightJumpRule, BandsMeetingOverFloorJumpAndInsideABottomlessBlockOrHighOverAPitDoNot) {
  const LevelMesh room = boxRoom({0, 0, 0}, {10, 6, 3});
  const std::vector<ValidationFinding> open = weightJumps(room);
  ASSERT_EQ(open.size(), 1u);
  EXPECT_EQ(open[0].rule, "weight_jump");
  EXPECT_GT(open[0].value, 0.2);

  // A solid block 2 m high across the room at x 4..6, wound outwards, without its bottom face
  // (Quake 3's compiler drops the faces a block rests on): from inside it, the floor is below.
  LevelMesh block = boxRoom({4, 0, 0}, {6, 6, 2}, "block");
  for (glm::uvec3& t : block.triangles) std::swap(t.y, t.z);
  std::erase_if(block.triangles, [&](const glm::uvec3& t) {
    return block.positionsMeters[t.x].z == 0.0f && block.positionsMeters[t.y].z == 0.0f &&
           block.positionsMeters[t.z].z == 0.0f;
  });
  ASSERT_EQ(block.parts.size(), 1u);
  block.parts[0].triangleCount = static_cast<std::uint32_t>(block.triangles.size());
  LevelMesh withBlock = room;
  appendLevelMesh(withBlock, block);
  EXPECT_TRUE(weightJumps(withBlock).empty());

  // Nor in the air 5.6 m over the floor of a pit, where a camera only falls.
  EXPECT_TRUE(weightJumps(boxRoom({0, 0, -4}, {10, 6, 3})).empty());
}

}  // namespace
}  // namespace probeproxy
