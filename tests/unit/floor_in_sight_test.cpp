// Which floor a capture point holds in sight (geometry/raycast/room_in_sight.h, the leak rule's
// test), as the layout asks it (geometry/layout/floor_in_sight.h): a wall hides the next room,
// a pillar no more than its lee. And the layout's bands kept out of the next room
// (geometry/layout/bands_in_sight.h), judged by the leak rule itself.

#include "geometry/layout/floor_in_sight.h"
#include "geometry/builtin/box_room.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/bands_in_sight.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/validate/validation_rules.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace probeproxy {
namespace {

// Two 8 x 6 m rooms 3 m high, side by side along x behind a 0.2 m wall, the first with a
// 1 x 1 m pillar from floor to ceiling.
LevelMesh twoRoomsAndAPillar() {
  LevelMesh level = boxRoom({0, 0, 0}, {8, 6, 3}, "a");
  appendLevelMesh(level, boxRoom({8.2f, 0, 0}, {16.2f, 6, 3}, "b"));
  LevelMesh pillar = boxRoom({4, 2.5f, 0}, {5, 3.5f, 3}, "pillar");  // wound inwards: flip
  for (glm::uvec3& t : pillar.triangles) std::swap(t.y, t.z);
  appendLevelMesh(level, pillar);
  return level;
}

TEST(FloorInSight, TheNextRoomIsHiddenAndFloorBehindAPillarIsNot) {
  const LevelMesh mesh = twoRoomsAndAPillar();
  const LevelRayCaster level(mesh);
  const std::vector<glm::dvec3> seeds{{2, 3, 0.5}, {12, 3, 0.5}};
  WalkableFloorOptions fo;
  fo.gridSpacingMeters = 0.5;
  const WalkableFloor floor = walkableFloor(level, seeds, fo);
  const std::vector<glm::dvec3> captures{{2, 3, 1.6}};
  const FloorInSight sight(level, floor, captures);
  std::size_t inA = 0, inSightA = 0, inB = 0, behindPillar = 0;
  for (std::size_t c = 0; c < floor.cells.size(); ++c) {
    const glm::dvec3 p = floor.cells[c].pointMeters;
    const bool seen = sight.inSight(0, c);
    EXPECT_EQ(sight.inSight(0, c), seen);  // asked again: the cached answer
    if (p.x > 8.2) {
      EXPECT_FALSE(seen) << "next room's floor at " << p.x << ", " << p.y;
      ++inB;
    } else {
      ++inA;
      inSightA += seen;
      // The pillar's shadow from (2, 3) past the reach of the viewpoints beside it.
      if (p.x > 7.5 && p.y > 2.5 && p.y < 3.5) {
        EXPECT_TRUE(seen) << "floor behind the pillar at " << p.x << ", " << p.y;
        ++behindPillar;
      }
    }
  }
  EXPECT_GT(inB, 100u);
  EXPECT_GT(inA, 100u);
  // Only the floor in the pillar's lee, 2.5 m x 1 m of it, is out of sight: a pillar is no
  // wall, and the leak rule allows 5%.
  EXPECT_GT(static_cast<double>(inSightA), 0.95 * static_cast<double>(inA));
  EXPECT_LT(inSightA, inA);
  EXPECT_GE(behindPillar, 2u);
}

// The cache's blocks are squares of 32 x 32 grid columns; the answer is the same asked once
// (not kept), asked and kept, or read back, over a floor of several blocks and two captures.
TEST(FloorInSight, AskedOnceOrKeptTheAnswerIsTheSameInEveryBlock) {
  const LevelMesh mesh = twoRoomsAndAPillar();
  const LevelRayCaster level(mesh);
  const std::vector<glm::dvec3> seeds{{2, 3, 0.5}, {12, 3, 0.5}};
  const WalkableFloor floor = walkableFloor(level, seeds);  // 0.25 m: 65 x 24 columns
  int lastColumn = 0;
  for (const FloorCell& cell : floor.cells) lastColumn = std::max(lastColumn, cell.column);
  ASSERT_GE(lastColumn, 64);  // three blocks along x
  const std::vector<glm::dvec3> captures{{2, 3, 1.6}, {12, 3, 1.6}};
  const FloorInSight once(level, floor, captures), kept(level, floor, captures);
  std::size_t seen = 0;
  for (std::size_t capture = 0; capture < captures.size(); ++capture)
    for (std::size_t c = 0; c < floor.cells.size(); ++c) {
      const bool answer = once.inSightOnce(capture, c);
      EXPECT_EQ(kept.inSight(capture, c), answer) << "cell " << c << ", capture " << capture;
      EXPECT_EQ(kept.inSightOnce(capture, c), answer);  // read back from the cache
      EXPECT_EQ(once.inSightOnce(capture, c), answer);
      seen += answer;
    }
  // Each capture point holds its own room in sight and not the other; the pillar's lee is
  // out of the first's.
  EXPECT_GT(static_cast<double>(seen), 0.95 * static_cast<double>(floor.cells.size()));
  EXPECT_LT(seen, floor.cells.size());
}

// The leak rule's findings for a probe at `capture` with the box of inner range (lo, hi).
std::vector<ValidationFinding> leaks(const LevelRayCaster& level, const WalkableFloor& floor,
                                     glm::dvec3 capture, glm::dvec3 lo, glm::dvec3 hi) {
  Probe probe;
  probe.name = "a";
  probe.captureMeters = capture;
  probe.influence = influenceOfBounds(lo, hi, 1.0);
  std::vector<ValidationFinding> out;
  checkInfluenceLeak(level, probe, floor.cells, ValidateOptions{}, out);
  return out;
}

TEST(PullBandsIntoSight, ABandThroughAWallComesBackAndTheOtherSidesStay) {
  const LevelMesh mesh = twoRoomsAndAPillar();
  const LevelRayCaster level(mesh);
  const std::vector<glm::dvec3> seeds{{2, 3, 0.5}, {12, 3, 0.5}};
  const WalkableFloor floor = walkableFloor(level, seeds);  // 0.25 m: the rule's own
  // The first room's floor by the wall to the next, its band 1.5 m past: 1.3 m into the next.
  const glm::dvec3 capture(3, 1.5, 1.6);
  glm::dvec3 lo(1, 0.5, -0.5), hi(8, 2.25, 2.5);
  ASSERT_EQ(leaks(level, floor, capture, lo, hi).size(), 1u);
  pullBandsIntoSight(level, floor, capture, 1.0, lo, hi);
  EXPECT_TRUE(leaks(level, floor, capture, lo, hi).empty());
  EXPECT_LT(hi.x, 8.0);  // the side at the wall came in, by at most the band
  EXPECT_GE(hi.x, 8.0 - 1.5);
  EXPECT_EQ(lo, glm::dvec3(1, 0.5, -0.5));  // the others reach no floor out of sight
  EXPECT_EQ(hi.y, 2.25);
  EXPECT_EQ(hi.z, 2.5);
}

// A strip of a range along a corridor, its capture point near one end, and for the other half
// of its length a room behind the corridor's wall: the strip's band reaches into the room
// along its side, which no pull by the band's width clears and the capture point keeps from
// coming in. Its far end comes in past its band instead, as far as the leak needs.
TEST(PullBandsIntoSight, AStripBesideARoomAlongHalfItsLengthComesInPastItsBand) {
  LevelMesh mesh = boxRoom({0, 0, 0}, {1.2f, 20, 3}, "corridor");
  appendLevelMesh(mesh, boxRoom({1.4f, 0, 0}, {4, 9, 3}, "room"));
  const LevelRayCaster level(mesh);
  const std::vector<glm::dvec3> seeds{{0.6, 10, 0.5}, {2.5, 4, 0.5}};
  const WalkableFloor floor = walkableFloor(level, seeds);
  const glm::dvec3 capture(0.6, 18, 1.6);
  glm::dvec3 lo(0.35, 1, -0.5), hi(0.85, 19, 2.5);
  ASSERT_EQ(leaks(level, floor, capture, lo, hi).size(), 1u);
  pullBandsIntoSight(level, floor, capture, 1.0, lo, hi);
  EXPECT_TRUE(leaks(level, floor, capture, lo, hi).empty());
  EXPECT_GT(lo.y, 1.0 + 1.5);  // past the band's width
  EXPECT_LT(lo.y, 9.0);        // not past the room: the leak is under the limit sooner
  EXPECT_EQ(hi.y, 19.0);
}

}  // namespace
}  // namespace probeproxy
