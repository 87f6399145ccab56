// The layout's influence volumes: fills over floor no range reaches, kept clear of the ranges'
// inner ranges (docs/layout.md).

#include "core/blend/blend_weights.h"
#include "core/blend/influence_factor.h"
#include "core/blend/weight_continuity.h"
#include "geometry/builtin/box_room.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/candidate_service.h"
#include "geometry/layout/floor_rectangles.h"
#include "geometry/layout/head_room.h"
#include "geometry/layout/layout_candidates.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/layout/layout_proxy.h"
#include "geometry/layout/leftover_floor.h"
#include "geometry/layout/near_ranges.h"
#include "geometry/layout/overlap_trim.h"
#include "geometry/layout/thin_ranges.h"
#include "geometry/layout/uncovered_floor_fills.h"
#include "geometry/layout/widen_fades.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/survey/blended_error.h"
#include "geometry/validate/camera_space.h"

#include <gtest/gtest.h>
#include <glm/common.hpp>

#include <array>
#include <initializer_list>
#include <set>
#include <vector>

namespace probeproxy {
namespace {

glm::dvec3 innerLo(const InfluenceVolume& v) {
  const BoxInfluence& b = std::get<BoxInfluence>(v);
  return b.centerMeters - b.innerHalfExtentsMeters;
}
glm::dvec3 innerHi(const InfluenceVolume& v) {
  const BoxInfluence& b = std::get<BoxInfluence>(v);
  return b.centerMeters + b.innerHalfExtentsMeters;
}

bool innerRangesOverlap(const InfluenceVolume& a, const InfluenceVolume& b) {
  return glm::all(glm::lessThan(innerLo(a), innerHi(b))) &&
         glm::all(glm::lessThan(innerLo(b), innerHi(a)));
}

TEST(FloorRect, FloorIsUnderTheInnerRangeExactlyWhereTheSurveyFindsItThere) {
  // A range of one 0.5 m cell over floor at z 1.25. The survey asks which ranges hold a floor
  // sample with the sample lifted kBlendLiftMeters: warfare's fill over floor 0.51 m under a
  // range (a hair past the step the range reaches down) grew inside it, where no fill may.
  WalkableFloor floor;
  floor.spacingMeters = 0.5, floor.columns = floor.rows = 1;
  const FloorRect rect{0, 0, 0, 0, 1.25};
  glm::dvec3 lo, hi;
  floorRectBounds(floor, rect, {0.25, 0.25, 2.85}, lo, hi);
  const InfluenceVolume range = influenceOfBounds(lo, hi, 1.0);
  for (double under : {0.3, 0.5, 0.51, 0.549, 0.551, 0.6}) {
    FloorCell cell;
    cell.pointMeters = {0.25, 0.25, 1.25 - under};
    const glm::dvec3 sample = cell.pointMeters + glm::dvec3(0, 0, kBlendLiftMeters);
    EXPECT_EQ(rect.underInnerRange(cell), insideInnerRange(range, sample)) << under << " m under";
  }
}

TEST(KeepClearOfInnerRanges, APitFillStopsUnderTheRangeOverIt) {
  // A range over a 10 x 10 m floor at z 0 whose box spans a pit 2 m deep at [2, 4]^2.
  const std::vector<InfluenceVolume> range{influenceOfBounds({0, 0, -0.5}, {10, 10, 2.5}, 1.0)};
  glm::dvec3 lo{2, 2, -2.5}, hi{4, 4, 0.5}, capture{3, 3, -0.4};
  keepClearOfInnerRanges(lo, hi, capture, -2.0, range, 1.0, StripForHeadRoom::atMostAQuarter);
  EXPECT_NEAR(hi.z, -0.5, 2e-3);
  EXPECT_LT(hi.z, -0.5);
  EXPECT_DOUBLE_EQ(lo.z, -2.5);
  EXPECT_NEAR(capture.z, -1.25, 1e-3) << "half way up what is left";
  EXPECT_FALSE(innerRangesOverlap(range[0], influenceOfBounds(lo, hi, 1.0)));
}

TEST(KeepClearOfInnerRanges, AFillOnARangesOwnFloorIsNotCut) {
  // The other range spans the fill's floor: cutting it would leave the floor outside both.
  const std::vector<InfluenceVolume> range{influenceOfBounds({0, 0, -0.5}, {10, 10, 2.5}, 1.0)};
  glm::dvec3 lo{2, 2, -0.3}, hi{4, 4, 2.7}, capture{3, 3, 1.8};
  keepClearOfInnerRanges(lo, hi, capture, 0.2, range, 1.0, StripForHeadRoom::atMostAQuarter);
  EXPECT_DOUBLE_EQ(lo.z, -0.3);
  EXPECT_DOUBLE_EQ(hi.z, 2.7);
  EXPECT_DOUBLE_EQ(capture.z, 1.8);
}

TEST(KeepClearOfInnerRanges, ARangeStartingJustOverTheFloorIsNotCut) {
  // A platform one step up (its range starts 1e-4 m over this floor, warfare): cut under it,
  // this range would keep no air over its floor and its capture point would sit on the floor.
  const std::vector<InfluenceVolume> platform{influenceOfBounds({0, 0, 5.5}, {10, 10, 8.5}, 1.0)};
  glm::dvec3 lo{2, 2, 5.0}, hi{4, 4, 8.0}, capture{3, 3, 7.1};
  keepClearOfInnerRanges(lo, hi, capture, 5.5 - 1e-4, platform, 1.0,
                         StripForHeadRoom::atMostAQuarter);
  EXPECT_DOUBLE_EQ(hi.z, 8.0);
  EXPECT_DOUBLE_EQ(capture.z, 7.1);
  // 8 cm of air is enough (skyway): cut, the capture point half way up it.
  glm::dvec3 lo2{2, 2, 4.92}, hi2{4, 4, 7.92}, capture2{3, 3, 7.02};
  keepClearOfInnerRanges(lo2, hi2, capture2, 5.42, platform, 1.0, StripForHeadRoom::atMostAQuarter);
  EXPECT_NEAR(hi2.z, 5.5, 2e-3);
  EXPECT_NEAR(capture2.z, 5.46, 1e-3);
}

TEST(KeepClearOfInnerRanges, ARangeOnALedgeBesideAnotherKeepsTheGapInPlan) {
  // A range over floor at z 0, x 0..5, and one on a ledge 0.75 m up, x 5..10, that reached to
  // it (downer): their inner ranges touched at x 5 over the same heights, and the weight of
  // either probe went from 1 to 0 there.
  const InfluenceVolume low = influenceOfBounds({0, 0, -0.5}, {5, 10, 2.5}, 1.0);
  const glm::dvec3 ledgeLo{5, 0, 0.25}, ledgeHi{10, 10, 3.25};
  glm::dvec3 lo = ledgeLo, hi = ledgeHi, capture{8, 5, 2.35};
  keepClearOfInnerRanges(lo, hi, capture, 0.75, std::span(&low, 1), 1.0,
                         StripForHeadRoom::atMostAQuarter);
  EXPECT_DOUBLE_EQ(lo.x, 6.0) << "one gap from the other range";
  EXPECT_EQ(hi, ledgeHi);
  EXPECT_EQ(glm::dvec2(lo.y, lo.z), glm::dvec2(ledgeLo.y, ledgeLo.z));
  EXPECT_EQ(capture, glm::dvec3(8, 5, 2.35));

  // What validate's weight_jump measures, at the capture height: over 1 per cm before, under
  // its limit of 0.02 per cm after.
  const auto largestJumpPerCm = [&](glm::dvec3 ledgeInnerLo) {
    const std::vector<InfluenceVolume> volumes{low, influenceOfBounds(ledgeInnerLo, hi, 1.0)};
    WeightGrid grid = gridOverVolumes(volumes, 2.35, 0.02);
    return measureWeightContinuity(volumes, grid).largestJump / 2.0;
  };
  EXPECT_GT(largestJumpPerCm(ledgeLo), 0.4);
  EXPECT_LT(largestJumpPerCm(lo), 0.02);
  // The floor it gave up stays in its band.
  EXPECT_TRUE(insideInfluence(influenceOfBounds(lo, hi, 1.0), {5.01, 5, 0.8}));
}

TEST(KeepClearOfInnerRanges, AFillGivesUpAStripThatLeavesItAGapWideARangeAQuarterAtMost) {
  // A range starting 1 m over the floor, over the far part of a 4 x 4 m range: a strip of
  // 1.2 m, 30% of the plan; with the 1 m gap kept from it, 1.8 m are left.
  const InfluenceVolume over = influenceOfBounds({2.8, 0, 1.0}, {8, 4, 4}, 1.0);
  const glm::dvec3 wideHi{4, 4, 2.5};
  glm::dvec3 lo{0, 0, -0.5}, hi = wideHi, capture{0.5, 2, 1.6};
  keepClearOfInnerRanges(lo, hi, capture, 0.0, std::span(&over, 1), 1.0,
                         StripForHeadRoom::atMostAQuarterOrLeavingAGap);
  EXPECT_DOUBLE_EQ(hi.x, 1.8) << "the fill gives up the strip and the gap";
  EXPECT_DOUBLE_EQ(hi.z, 2.5) << "and keeps its head room";
  glm::dvec3 rangeLo{0, 0, -0.5}, rangeHi = wideHi, rangeCapture{0.5, 2, 1.6};
  keepClearOfInnerRanges(rangeLo, rangeHi, rangeCapture, 0.0, std::span(&over, 1), 1.0,
                         StripForHeadRoom::atMostAQuarter);
  EXPECT_DOUBLE_EQ(rangeHi.x, 4.0) << "a selected range keeps its plan";
  EXPECT_NEAR(rangeHi.z, 1.0, 2e-3) << "and stops under the range over it";
  // A fill 2.5 m wide under a range over its far 0.8 m: the strip and the gap would leave it
  // 0.7 m wide, a sliver whose band is most of its influence (downer); it stops under the
  // range instead.
  const InfluenceVolume overNarrow = influenceOfBounds({1.7, 0, 1.0}, {8, 4, 4}, 1.0);
  glm::dvec3 narrowLo{0, 0, -0.5}, narrowHi{2.5, 4, 2.5}, narrowCapture{0.5, 2, 1.6};
  keepClearOfInnerRanges(narrowLo, narrowHi, narrowCapture, 0.0, std::span(&overNarrow, 1), 1.0,
                         StripForHeadRoom::atMostAQuarterOrLeavingAGap);
  EXPECT_DOUBLE_EQ(narrowHi.x, 2.5);
  EXPECT_NEAR(narrowHi.z, 1.0, 2e-3);
  EXPECT_LT(narrowCapture.z, narrowHi.z) << "its capture point comes down under the cut";
}

TEST(KeepClearOfInnerRanges, ARangeACaptureMarginFromTheOtherComesBackOnlyToItsCapture) {
  const InfluenceVolume other = influenceOfBounds({0, 0, -0.5}, {5, 10, 2.5}, 1.0);
  glm::dvec3 lo{5.2, 0, -0.5}, hi{9, 10, 2.5}, capture{5.6, 5, 1.6};
  keepClearOfInnerRanges(lo, hi, capture, 0.0, std::span(&other, 1), 1.0,
                         StripForHeadRoom::atMostAQuarter);
  EXPECT_DOUBLE_EQ(lo.x, 5.6 - kCaptureMarginMeters) << "its capture point stays inside";
}

TEST(ClearCaptureAbove, ACellWhoseCentreLiesInAWallsFaceCapturesAQuarterCellOffItOnTheRoomsSide) {
  // The layout's floor of a 4 x 4 x 4 m room; then a wall 0.3 m thick whose face passes through the
  // centre of the cell nearest (2, 2) (warfare's one-cell fills: their capture points lay in a
  // face and the layout could not be written).
  const glm::dvec3 seed{1.0, 1.0, 1.6};
  const WalkableFloor floor = walkableFloor(LevelRayCaster(boxRoom({0, 0, 0}, {4, 4, 4})),
                                            std::span(&seed, 1), WalkableFloorOptions{0.5});
  std::size_t cell = 0;
  for (std::size_t c = 0; c < floor.cells.size(); ++c)
    if (glm::distance(floor.cells[c].pointMeters, glm::dvec3(2, 2, 0)) <
        glm::distance(floor.cells[cell].pointMeters, glm::dvec3(2, 2, 0)))
      cell = c;
  const glm::dvec3 centre = floor.cells[cell].pointMeters;
  LevelMesh mesh = boxRoom({0, 0, 0}, {4, 4, 4});
  LevelMesh wall = boxRoom(glm::vec3(centre.x, centre.y - 1.0, 0),
                           glm::vec3(centre.x + 0.3, centre.y + 1.0, 4), "wall");
  for (glm::uvec3& t : wall.triangles) std::swap(t.y, t.z);  // faces outwards: a solid
  appendLevelMesh(mesh, wall);
  const LevelRayCaster walled(mesh);
  const std::array<std::size_t, 1> cells{cell};
  EXPECT_LT(nearestSurface(walled, captureAbove(walled, centre, 1.6)).distanceMeters,
            kMinCaptureClearanceMeters)
      << "over the centre, the capture point lies in the wall's face";
  const ClearCapture clear = clearCaptureAbove(walled, floor, cells, 1.6);
  EXPECT_GE(clear.clearanceMeters, kLayoutCaptureClearanceMeters);
  EXPECT_NEAR(clear.captureMeters.x, centre.x - 0.25 * floor.spacingMeters, 1e-9)
      << "a quarter cell off, in the room, not inside the wall";
  EXPECT_NEAR(clear.captureMeters.z, centre.z + 1.6, 1e-9);
}

TEST(ClearMovedCapture, ACaptureCutDownUnderARampsFaceRisesOverTheRamp) {
  // A 6 x 6 x 4 m room with a ramp along y, one face rising from z 0 at y 0 to 1.2 at y 4, its
  // underside open (a map's ramp: one-sided, nothing under it). A range over the room's floor
  // (z 0) cut under a range above at 1.6 m put its capture point half way up, 0.8 m: under the
  // ramp's face (darkzone's fill, which then saw none of its floor: influence_leak).
  LevelMesh mesh = boxRoom({0, 0, 0}, {6, 6, 4});
  LevelMesh ramp;
  ramp.positionsMeters = {{0, 0, 0}, {6, 0, 0}, {6, 4, 1.2f}, {0, 4, 1.2f}};
  ramp.triangles = {{0, 1, 2}, {0, 2, 3}};
  ramp.parts = {{"ramp", {}, 0, 2}};
  appendLevelMesh(mesh, ramp);
  const LevelRayCaster level(mesh);
  const glm::dvec3 chosen{3, 3, 2.5}, cut{3, 3, 0.8};  // the ramp's face is at z 0.9 there
  glm::dvec3 capture = cut;
  ASSERT_TRUE(clearMovedCapture(level, chosen, capture, 0.0, 1.6));
  EXPECT_DOUBLE_EQ(capture.x, 3.0);
  EXPECT_DOUBLE_EQ(capture.y, 3.0);
  EXPECT_NEAR(capture.z, 0.9 + 0.5 * (1.6 - 0.9), 1e-6) << "half way up the air over the ramp";
  EXPECT_GE(nearestSurface(level, capture).distanceMeters, kLayoutCaptureClearanceMeters);

  // A top under the ramp's face there leaves no air over it: the probe is not made.
  glm::dvec3 under = {3, 3, 0.4};
  EXPECT_FALSE(clearMovedCapture(level, chosen, under, 0.0, 0.85));
  // A point the cut did not move stays.
  glm::dvec3 unmoved = chosen;
  EXPECT_TRUE(clearMovedCapture(level, chosen, unmoved, 0.0, 1.6));
  EXPECT_EQ(unmoved, chosen);
}

TEST(KeepClearOfInnerRanges, BoxesOverlappingInPlanAtOneHeightComeApartOnTheSideThatGivesLeast) {
  // The selection claims floor cells, not plan: two ranges' rectangles can both take a column
  // with no floor in it (a pillar's), and their boxes overlap there (bloodprison, darkzone).
  const std::vector<InfluenceVolume> others{influenceOfBounds({0, 0, -0.5}, {5, 5, 2.5}, 1.0)};
  glm::dvec3 lo{4, 0, -0.5}, hi{10, 5, 2.5}, capture{6, 2, 1.6};
  keepClearOfInnerRanges(lo, hi, capture, 0.0, others, 1.0, StripForHeadRoom::atMostAQuarter);
  EXPECT_GE(lo.x, 5.0) << "the west side, 1 m into the other, comes back (not the 5 m in y)";
  EXPECT_EQ(lo.y, 0.0);
  EXPECT_EQ(hi, glm::dvec3(10, 5, 2.5));
  EXPECT_LE(lo.x, capture.x - kCaptureMarginMeters) << "never past the capture point";
  EXPECT_FALSE(innerRangesOverlap(others[0], influenceOfBounds(lo, hi, 1.0)));
}

TEST(KeepClearOfInnerRanges, ARaisedFloorOverAnEdgeTakesAStripAndABridgeOverTheMiddleTheHeight) {
  // A range over a 10 x 10 m floor at z 0, and a raised floor 1.75 m up beside it whose range
  // overhangs this one's east edge by 0.5 m (warfare): cut under it, this range kept 1.25 m of
  // its 2.5 m head room over all its floor, and a camera standing there was in no volume.
  const std::vector<InfluenceVolume> raised{influenceOfBounds({9.5, 0, 1.25}, {15, 10, 4.25}, 1.0)};
  glm::dvec3 lo{0, 0, -0.5}, hi{10, 10, 2.5}, capture{5, 5, 1.6};
  keepClearOfInnerRanges(lo, hi, capture, 0.0, raised, 1.0, StripForHeadRoom::atMostAQuarter);
  EXPECT_EQ(hi.z, 2.5) << "the head room is kept";
  EXPECT_LE(hi.x, 9.5 - 1.0) << "the east side comes back, a gap from the raised range";
  EXPECT_EQ(lo, glm::dvec3(0, 0, -0.5));
  EXPECT_EQ(capture, glm::dvec3(5, 5, 1.6));
  EXPECT_TRUE(insideInnerRange(influenceOfBounds(lo, hi, 1.0), {5, 5, 2.4}));
  EXPECT_FALSE(innerRangesOverlap(raised[0], influenceOfBounds(lo, hi, 1.0)));

  // A bridge 2.5 m up across the middle of the room: coming back in plan past it would give up
  // half the room, the air under the bridge much less.
  const std::vector<InfluenceVolume> bridge{influenceOfBounds({0, 4, 2.0}, {10, 6, 5.0}, 1.0)};
  glm::dvec3 lo2{0, 0, -0.5}, hi2{10, 10, 2.5}, capture2{5, 2, 1.6};
  keepClearOfInnerRanges(lo2, hi2, capture2, 0.0, bridge, 1.0, StripForHeadRoom::atMostAQuarter);
  EXPECT_NEAR(hi2.z, 2.0, 2e-3);
  EXPECT_EQ(glm::dvec2(hi2), glm::dvec2(10, 10)) << "the plan is whole";
  EXPECT_FALSE(innerRangesOverlap(bridge[0], influenceOfBounds(lo2, hi2, 1.0)));
}

TEST(FillsForUncoveredFloor, FloorBeyondEveryBandGetsOneProbeAndIsThenCovered) {
  // A 10 x 10 m room; one range over x 0..5 whose band reaches to x 6.5 (1.5 gaps of 1 m).
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 10, 3.5f}));
  const glm::dvec3 seed{2.0, 2.0, 1.6};
  const WalkableFloor floor = walkableFloor(level, std::span(&seed, 1));
  std::vector<InfluenceVolume> volumes{influenceOfBounds({0, 0, -0.5}, {5, 10, 2.5}, 1.0)};
  const std::vector<FloorFill> fills = fillsForUncoveredFloor(level, floor, volumes, 1.0, 1.6);
  ASSERT_EQ(fills.size(), 1u) << "the floor x 6.5..10 is one piece";
  EXPECT_TRUE(insideInfluence(fills[0].influence, fills[0].captureMeters));
  EXPECT_FALSE(innerRangesOverlap(volumes[0], fills[0].influence));
  EXPECT_GE(innerLo(fills[0].influence).x, 5.0 + 1.0) << "a gap from the range";
  volumes.push_back(fills[0].influence);
  for (const FloorCell& c : floor.cells) {
    const glm::dvec3 at = c.pointMeters + glm::dvec3(0, 0, kBlendLiftMeters);
    EXPECT_TRUE(insideInfluence(volumes[0], at) || insideInfluence(volumes[1], at))
        << c.pointMeters.x << ", " << c.pointMeters.y;
  }
}

TEST(FillsForUncoveredFloor,
     FloorAtTheFarEndOfBandsThatOnlyTouchGetsAFillAndTheWeightsTurnSmoothly) {
  // A 10 x 4 m room; ranges over x 0..3.5 and 6.5..10, their 1.5 m bands touching at x 5: over
  // the floor there each probe's weight is whole on its side (alone in its band) and the
  // lighting flips from one to the other.
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 4, 3.5f}));
  const glm::dvec3 seed{2.0, 2.0, 1.6};
  const WalkableFloor floor = walkableFloor(level, std::span(&seed, 1));
  std::vector<InfluenceVolume> volumes{influenceOfBounds({0, 0, -0.5}, {3.5, 4, 2.5}, 1.0),
                                       influenceOfBounds({6.5, 0, -0.5}, {10, 4, 2.5}, 1.0)};
  const auto steepest = [&] {
    const WeightGrid grid = gridOverVolumes(volumes, 1.6, 0.01);
    return measureWeightContinuity(volumes, grid, BlendOptions{}).largestJump;  // 1 cm apart
  };
  EXPECT_GT(steepest(), 0.9) << "per cm, where the bands touch";
  const std::vector<FloorFill> fills = fillsForUncoveredFloor(level, floor, volumes, 1.0, 1.6);
  ASSERT_EQ(fills.size(), 1u) << "the floor around x 5";
  EXPECT_FALSE(innerRangesOverlap(volumes[0], fills[0].influence));
  EXPECT_FALSE(innerRangesOverlap(volumes[1], fills[0].influence));
  volumes.push_back(fills[0].influence);
  EXPECT_LE(steepest(), 0.02) << "validate's weight_jump limit, per cm";
}

// Probes over a 10 x 6 m room, one a range x lo..hi, y ylo..yhi each (bands 1.5 m).
// Every floor cell in some volume.
void expectEveryCellCovered(const WalkableFloor& floor, std::span<const InfluenceVolume> volumes) {
  for (const FloorCell& cell : floor.cells) {
    bool covered = false;
    for (const InfluenceVolume& v : volumes)
      covered = covered || insideInfluence(v, cell.pointMeters);
    EXPECT_TRUE(covered) << cell.pointMeters.x << ", " << cell.pointMeters.y;
  }
}

TEST(FillsForUncoveredFloor, ARangeOverACornerTakesAStripOfTheFillNotItsHeadRoom) {
  // A 16 x 14 m room; a range from 1.5 m up over its corner x 10..16, y 9..14 (a storey's
  // range over a low passage), 13% of the plan. A fill over the whole floor cut under it kept
  // 1.5 m over all its floor, its capture point 0.75 m up, the cameras' eyes out of its range
  // (runningman: 16 x 14 m cut to 1.5 m by a range over a tenth of it). The fill gives up a
  // strip instead; the rounds fill the rest, under the corner's range there.
  const LevelRayCaster level(boxRoom({0, 0, 0}, {16, 14, 3.5f}));
  const glm::dvec3 seed{2.0, 2.0, 1.6};
  const WalkableFloor floor = walkableFloor(level, std::span(&seed, 1));
  std::vector<InfluenceVolume> volumes{influenceOfBounds({10, 9, 1.5}, {16, 14, 4.0}, 1.0)};
  const std::vector<FloorFill> fills = fillsForUncoveredFloor(level, floor, volumes, 1.0, 1.6);
  ASSERT_GE(fills.size(), 2u);
  EXPECT_NEAR(innerHi(fills[0].influence).z, kInfluenceHeadRoomMeters, 1e-3) << "head room kept";
  EXPECT_GE(fills[0].captureMeters.z, 1.5);
  for (const FloorFill& f : fills) {
    for (const InfluenceVolume& v : volumes) EXPECT_FALSE(innerRangesOverlap(v, f.influence));
    volumes.push_back(f.influence);
  }
  expectEveryCellCovered(floor, volumes);
}

TEST(FillsForUncoveredFloor, FloorAnEarlierFillHoldsGetsNoFillOfItsOwn) {
  // A 10 x 10 m room whose floor is a raised ring, 0.2502 m up, round a 4 x 4 m pit: the pit's
  // floor lies a hair past the 0.25 m a storey reaches down, so the ring's cells and the pit's
  // are two groups. The ring's fill, over the whole room, holds the pit's floor in its inner
  // range too; a second fill over the pit stood inside the ring's plan, where nothing parts two
  // inner ranges (runningman: two fills overlapping by 239 m^3).
  LevelMesh mesh = boxRoom({0, 0, 0}, {10, 10, 3.5f});
  LevelMesh ring;
  constexpr float kUp = 0.2502f;
  const auto slab = [&](float x0, float y0, float x1, float y1) {
    const auto first = static_cast<unsigned>(ring.positionsMeters.size());
    ring.positionsMeters.insert(ring.positionsMeters.end(),
                                {{x0, y0, kUp}, {x1, y0, kUp}, {x1, y1, kUp}, {x0, y1, kUp}});
    ring.triangles.push_back({first, first + 1, first + 2});
    ring.triangles.push_back({first, first + 2, first + 3});
  };
  slab(0, 0, 10, 3), slab(0, 7, 10, 10), slab(0, 3, 3, 7), slab(7, 3, 10, 7);
  ring.parts = {{"ring", {}, 0, static_cast<std::uint32_t>(ring.triangles.size())}};
  appendLevelMesh(mesh, ring);
  const LevelRayCaster level(mesh);
  const glm::dvec3 seed{1.0, 1.0, 1.6};
  const WalkableFloor floor = walkableFloor(level, std::span(&seed, 1));
  ASSERT_TRUE(std::any_of(floor.cells.begin(), floor.cells.end(), [](const FloorCell& c) {
    return c.pointMeters.z < 0.1;
  })) << "the pit's floor is walkable from the ring";
  const std::vector<FloorFill> fills = fillsForUncoveredFloor(level, floor, {}, 1.0, 1.6);
  ASSERT_EQ(fills.size(), 1u) << "the ring's fill holds the pit's floor";
  const std::array<InfluenceVolume, 1> volumes{fills[0].influence};
  expectEveryCellCovered(floor, volumes);
}

TEST(FillsForUncoveredFloor, FloorAFillsCutLeavesIsFilledAgain) {
  // A 10 x 10 m room with one range over its corner x, y 0..6 and one over the whole room from
  // 1.5 m up, where the cameras' eyes are (a storey's range over a low passage): the floor
  // beyond the corner is an L, one group, under the range above. Its fill, kept a gap from the
  // corner's range, can hold one arm only; the other arm, left uncovered, gets a fill of its
  // own.
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 10, 3.5f}));
  const glm::dvec3 seed{2.0, 2.0, 1.6};
  const WalkableFloor floor = walkableFloor(level, std::span(&seed, 1));
  std::vector<InfluenceVolume> volumes{influenceOfBounds({0, 0, -0.5}, {6, 6, 1.5}, 1.0),
                                       influenceOfBounds({0, 0, 1.5}, {10, 10, 4.0}, 1.0)};
  const std::vector<FloorFill> fills = fillsForUncoveredFloor(level, floor, volumes, 1.0, 1.6);
  EXPECT_EQ(fills.size(), 2u) << "one fill per arm";
  for (const FloorFill& f : fills) {
    EXPECT_FALSE(innerRangesOverlap(volumes[0], f.influence));
    EXPECT_FALSE(innerRangesOverlap(volumes[1], f.influence));
    volumes.push_back(f.influence);
  }
  ASSERT_EQ(volumes.size(), 4u);
  EXPECT_FALSE(innerRangesOverlap(volumes[2], volumes[3]));
  expectEveryCellCovered(floor, volumes);
}

struct RangesInARoom {
  LevelRayCaster level{boxRoom({0, 0, 0}, {10, 6, 3.5f})};
  WalkableFloor floor;
  std::vector<LayoutProbe> probes;
  explicit RangesInARoom(std::initializer_list<std::array<double, 4>> ranges)
      : RangesInARoom(std::span(ranges.begin(), ranges.size())) {}
  explicit RangesInARoom(std::span<const std::array<double, 4>> ranges) {
    const glm::dvec3 seed{2.0, 2.0, 1.6};
    floor = walkableFloor(level, std::span(&seed, 1));
    for (const auto& [lo, hi, ylo, yhi] : ranges)
      probes.push_back(LayoutProbe{glm::dvec3(0.5 * (lo + hi), 0.5 * (ylo + yhi), 1.6),
                                   influenceOfBounds({lo, ylo, -0.5}, {hi, yhi, 2.5}, 1.0),
                                   kRoomFitMeters});
  }
  const BoxInfluence& box(std::size_t p) const {
    return std::get<BoxInfluence>(probes[p].influence);
  }
  std::size_t widenFades() {
    return widenFadesWhereWeightsJump(level, floor, 1.0, ValidateOptions{}, {}, probes);
  }
  std::vector<InfluenceVolume> volumes() const {
    std::vector<InfluenceVolume> v;
    for (const LayoutProbe& p : probes) v.push_back(p.influence);
    return v;
  }
  // The steepest change of a weight between points 1 cm apart at eye height, where a camera can
  // be, as validate measures: the bands reach past the room's walls.
  double steepestWhereCamerasAre() const {
    const ReachableMask cameras = [&](std::span<const glm::dvec3> points, std::span<char> out) {
      markCameraSpace(level, floor, 2.5, points, out);
    };
    const std::vector<InfluenceVolume> v = volumes();
    return measureWeightContinuity(v, gridOverVolumes(v, 1.6, 0.01), {}, cameras).largestJump;
  }
  // Most volumes over one point at eye height, outside every inner range (too_many_overlaps).
  int mostMeeting() const {
    int most = 0;
    for (double x = 0.05; x < 10.0; x += 0.1) {
      for (double y = 0.05; y < 6.0; y += 0.1) {
        int meeting = 0;
        bool inner = false;
        for (const LayoutProbe& p : probes) {
          const double a = normalizedDistance(p.influence, {x, y, 1.6});
          meeting += a < 1.0, inner = inner || a == 0.0;
        }
        if (!inner) most = std::max(most, meeting);
      }
    }
    return most;
  }
};

// South: 0..3, a 0.5 m strip at 4..4.5, 5.5..10; north, across a 1 m gap: 0..4.25 and
// 5.25..10. Over the gap by the strip five bands meet (basement's crossing, probe_068;
// eggandbacon's probe_106).
constexpr std::array<std::array<double, 4>, 5> kCrossingByAStrip{
    {{0, 3, 0, 2.5}, {4, 4.5, 0, 2.5}, {5.5, 10, 0, 2.5}, {0, 4.25, 3.5, 6}, {5.25, 10, 3.5, 6}}};

// Whether the whole square of a floor cell (where the survey's samples of it lie), lifted as
// the blend weighs it, is in one of the probes' volumes.
bool cellSquareCovered(const WalkableFloor& floor, const FloorCell& cell,
                       std::span<const LayoutProbe> probes) {
  const double h = 0.5 * floor.spacingMeters - 1e-3;
  for (double dx : {-h, h})
    for (double dy : {-h, h}) {
      const glm::dvec3 at = cell.pointMeters + glm::dvec3(dx, dy, kBlendLiftMeters);
      if (std::none_of(probes.begin(), probes.end(),
                       [&](const LayoutProbe& p) { return insideInfluence(p.influence, at); }))
        return false;
    }
  return true;
}

// A 10 x 4 m room and its floor, with probes whose ranges run across it: x lo..hi, the whole
// width, from the floor up (bands 1.5 m), each captured 0.6 m over the floor at `captureX`.
struct StripRoom {
  LevelRayCaster level{boxRoom({0, 0, 0}, {10, 4, 3.5f})};
  WalkableFloor floor;
  StripRoom() {
    const glm::dvec3 seed{2.0, 2.0, 1.6};
    floor = walkableFloor(level, std::span(&seed, 1));
  }
  static LayoutProbe range(double captureX, double lo, double hi) {
    return {{captureX, 2.0, 0.6}, influenceOfBounds({lo, 0, -0.5}, {hi, 4, 2.5}, 1.0)};
  }
};

TEST(CoverLeftoverFloor, AStripNoVolumeReachesJoinsTheBandThatGrowsLeastAndNoInnerRangeMoves) {
  // Ranges over x 0..3.5 and 7..10: the floor x 5..5.5 lies in no volume (as a stair under a
  // range above, where no fill's capture point is clear).
  const StripRoom room;
  const WalkableFloor& floor = room.floor;
  std::vector<LayoutProbe> probes{StripRoom::range(1.75, 0, 3.5), StripRoom::range(8.5, 7, 10)};
  const std::vector<LayoutProbe> before = probes;
  const auto strip = std::count_if(floor.cells.begin(), floor.cells.end(), [&](const FloorCell& c) {
    return !cellSquareCovered(floor, c, probes);
  });
  ASSERT_GT(strip, 0) << "the strip between the bands";
  EXPECT_TRUE(coverLeftoverFloor(room.level, floor, 1.0, {}, probes).empty());
  for (const FloorCell& c : floor.cells)
    EXPECT_TRUE(cellSquareCovered(floor, c, probes)) << c.pointMeters.x << ", " << c.pointMeters.y;
  for (std::size_t i = 0; i < probes.size(); ++i) {
    EXPECT_EQ(innerLo(probes[i].influence), innerLo(before[i].influence)) << i;
    EXPECT_EQ(innerHi(probes[i].influence), innerHi(before[i].influence)) << i;
  }
  // The first band is 0.25 m nearer the strip's first cells than the second: it takes the strip.
  const auto& grown = std::get<BoxInfluence>(probes[0].influence);
  EXPECT_NEAR(grown.centerMeters.x + grown.halfExtentsMeters.x, 5.5, 0.01);
  EXPECT_EQ(std::get<BoxInfluence>(probes[1].influence).halfExtentsMeters,
            std::get<BoxInfluence>(before[1].influence).halfExtentsMeters);
}

TEST(CoverLeftoverFloor, FloorMoreThanAGapPastEveryBandOrHiddenFromItsProbeIsLeftAndReturned) {
  // Bands end at x 5 and begin at x 8: the floor x 6.25..6.75 lies more than a 1 m gap past
  // both, so no band grows that far. Then a band 0.25 m short of the floor x 3.5..5.5 whose
  // capture point stands behind the room's east wall: it does not see that floor, so it does
  // not grow; the first band grows a gap and takes what lies within it.
  const StripRoom room;
  const WalkableFloor& floor = room.floor;
  std::vector<LayoutProbe> probes{StripRoom::range(1.75, 0, 3.5), StripRoom::range(9.75, 9.5, 10)};
  const std::vector<std::size_t> left = coverLeftoverFloor(room.level, floor, 1.0, {}, probes);
  ASSERT_FALSE(left.empty());
  for (std::size_t c : left) {
    const double x = floor.cells[c].pointMeters.x;
    EXPECT_GT(x, 5.0 + 1.0 - 0.125) << "within a gap of the first band";
    EXPECT_LT(x, 8.0 - 1.0 + 0.125) << "within a gap of the second band";
  }
  std::vector<LayoutProbe> hidden{StripRoom::range(1.0, 0, 2), StripRoom::range(10.5, 7, 10.75)};
  const std::vector<std::size_t> unseen = coverLeftoverFloor(room.level, floor, 1.0, {}, hidden);
  ASSERT_FALSE(unseen.empty());
  for (std::size_t c : unseen) EXPECT_GT(floor.cells[c].pointMeters.x, 3.5 + 1.0 - 0.125);
  EXPECT_EQ(std::get<BoxInfluence>(hidden[1].influence).halfExtentsMeters,
            influenceOfBounds({7, 0, -0.5}, {10.75, 4, 2.5}, 1.0).halfExtentsMeters);
}

TEST(JoinThinRanges, AStripInARowJoinsANeighbourAndNoMoreThanTheBlendTakesMeet) {
  RangesInARoom room(kCrossingByAStrip);
  EXPECT_EQ(room.mostMeeting(), 5);
  joinThinRanges(room.level, room.floor, 1.0, {}, room.probes);
  ASSERT_EQ(room.probes.size(), 4u);
  EXPECT_DOUBLE_EQ(innerHi(room.probes[0].influence).x, 4.5) << "the first as near as any";
  EXPECT_EQ(room.mostMeeting(), 4);
  const std::vector<InfluenceVolume> volumes = room.volumes();
  EXPECT_LE(measureWeightContinuity(volumes, gridOverVolumes(volumes, 1.6, 0.01)).largestJump, 0.02)
      << "1 cm apart";
}

TEST(JoinThinRanges, NoJoinBringsRangesCloserThanTheGap) {
  // Joined with the left range the strip at 4..4.5 (y 2..6) would reach over the small range
  // at its foot (4..4.5, y 0..1), which joins the strip instead.
  RangesInARoom room({{{0, 3, 0, 6}}, {{4, 4.5, 2, 6}}, {{4, 4.5, 0, 1}}});
  joinThinRanges(room.level, room.floor, 1.0, {}, room.probes);
  ASSERT_EQ(room.probes.size(), 2u);
  EXPECT_DOUBLE_EQ(innerHi(room.probes[0].influence).x, 3.0);
  EXPECT_DOUBLE_EQ(innerLo(room.probes[1].influence).y, 0.0);
  EXPECT_DOUBLE_EQ(innerHi(room.probes[1].influence).y, 6.0);
}

TEST(TrimBandsOverOverlapLimit, FiveBandsOverTheGapBesideAStripComeDownToFourAndStaySmooth) {
  // The crossing left as it is (no join).
  RangesInARoom room(kCrossingByAStrip);
  ASSERT_EQ(room.mostMeeting(), 5);
  const std::vector<InfluenceVolume> before = room.volumes();
  trimBandsOverOverlapLimit(room.level, room.floor, 1.0, ValidateOptions{}, {}, room.probes);
  EXPECT_EQ(room.mostMeeting(), 4);
  int trimmed = 0;
  for (std::size_t p = 0; p < before.size(); ++p) {
    const BoxInfluence& was = std::get<BoxInfluence>(before[p]);
    const BoxInfluence& is = std::get<BoxInfluence>(room.probes[p].influence);
    EXPECT_EQ(is.innerHalfExtentsMeters, was.innerHalfExtentsMeters) << "inner ranges stay";
    EXPECT_EQ(is.halfExtentsMeters.z, was.halfExtentsMeters.z) << "storeys' bands stay";
    for (int axis : {0, 1})
      EXPECT_GE(is.halfExtentsMeters[axis] - is.innerHalfExtentsMeters[axis], 1.0) << "a gap";
    trimmed += is.halfExtentsMeters != was.halfExtentsMeters;
  }
  EXPECT_GE(trimmed, 1);
  EXPECT_LE(room.steepestWhereCamerasAre(), 0.02) << "0.0207 before";
  expectEveryCellCovered(room.floor, room.volumes());
}

TEST(TrimBandsOverOverlapLimit, ABandHoldingItsProbesCapturePointIsNotTrimmedPastIt) {
  // A fill's capture point may stand in its band (the nearest clear cell to its middle): each
  // probe's in turn stands 2 cm inside each side of its box, and no trim leaves it outside.
  int trims = 0;
  for (std::size_t p = 0; p < kCrossingByAStrip.size(); ++p) {
    for (int axis : {0, 1}) {
      for (int side : {-1, 1}) {
        RangesInARoom room(kCrossingByAStrip);
        const BoxInfluence was = room.box(p);
        room.probes[p].captureMeters[axis] =
            was.centerMeters[axis] + side * (was.halfExtentsMeters[axis] - 0.02);
        trimBandsOverOverlapLimit(room.level, room.floor, 1.0, ValidateOptions{}, {}, room.probes);
        trims += room.box(p).halfExtentsMeters != was.halfExtentsMeters;
        for (const LayoutProbe& probe : room.probes)
          EXPECT_TRUE(insideInfluence(probe.influence, probe.captureMeters))
              << "probe " << p << " axis " << axis << " side " << side;
      }
    }
  }
  EXPECT_GE(trims, 1) << "the other sides are trimmed still";
}

TEST(TrimBandsOverOverlapLimit, AFillWhoseBandsCannotBeTrimmedMovesAFaceOffTheCrowd) {
  // Trimmed to keep 1.5 m, bands 1.5 m deep cannot be trimmed: an optional fill's case.
  RangesInARoom trimmedOnly(kCrossingByAStrip), facesMoved(kCrossingByAStrip);
  trimBandsOverOverlapLimit(trimmedOnly.level, trimmedOnly.floor, 1.5, ValidateOptions{}, {},
                            trimmedOnly.probes);
  EXPECT_EQ(trimmedOnly.mostMeeting(), 5);
  // Taken as an optional fill: the south-west range (0..3).
  const std::set<std::size_t> fill{0};
  trimBandsOverOverlapLimit(facesMoved.level, facesMoved.floor, 1.5, ValidateOptions{}, {},
                            facesMoved.probes, fill);
  EXPECT_EQ(facesMoved.mostMeeting(), 4);
  const std::vector<InfluenceVolume> before = RangesInARoom(kCrossingByAStrip).volumes();
  for (std::size_t p = 0; p < before.size(); ++p) {
    const BoxInfluence& was = std::get<BoxInfluence>(before[p]);
    const BoxInfluence& is = std::get<BoxInfluence>(facesMoved.probes[p].influence);
    if (p != 0) {
      EXPECT_EQ(is.centerMeters, was.centerMeters) << p;
      EXPECT_EQ(is.halfExtentsMeters, was.halfExtentsMeters) << p;
      continue;
    }
    for (int axis : {0, 1, 2})
      EXPECT_NEAR(is.halfExtentsMeters[axis] - is.innerHalfExtentsMeters[axis],
                  was.halfExtentsMeters[axis] - was.innerHalfExtentsMeters[axis], 1e-12)
          << "its bands keep their width";
    EXPECT_NEAR(innerLo(is).x, 0.0, 1e-12) << "the west face stays";
    EXPECT_LT(innerHi(is).x, 3.0) << "the east face, beside the strip's crossing, moves in";
    EXPECT_EQ(innerLo(is).y, 0.0);
    EXPECT_EQ(innerHi(is).y, 2.5);
    EXPECT_TRUE(insideInfluence(is, facesMoved.probes[p].captureMeters));
  }
  EXPECT_LE(facesMoved.steepestWhereCamerasAre(), 0.02);
  expectEveryCellCovered(facesMoved.floor, facesMoved.volumes());
}

TEST(WidenFadesWhereWeightsJump, BandsWhoseFarEndsAloneMeetReachFurtherUntilTheBlendIsSmooth) {
  // 2.6 m apart with bands 1.5 m deep, the two ranges' bands share 0.4 m, where each weighs
  // little: the share turns across it at 2.9 per metre (downer's probe_106 and probe_129).
  RangesInARoom room({{{0, 3, 0, 6}}, {{5.6, 10, 0, 6}}});
  const std::vector<InfluenceVolume> before = room.volumes();
  ASSERT_GT(room.steepestWhereCamerasAre(), 0.025);
  EXPECT_GE(room.widenFades(), 1u);
  EXPECT_LE(room.steepestWhereCamerasAre(), 0.02) << "1 cm apart, as validate measures";
  for (std::size_t p = 0; p < before.size(); ++p) {
    const BoxInfluence& was = std::get<BoxInfluence>(before[p]);
    const BoxInfluence& is = room.box(p);
    EXPECT_EQ(is.centerMeters, was.centerMeters);
    EXPECT_EQ(is.halfExtentsMeters.y, was.halfExtentsMeters.y) << "only across the gap";
    EXPECT_GE(is.halfExtentsMeters.x, was.halfExtentsMeters.x) << "no outer range comes in";
    EXPECT_LE(is.innerHalfExtentsMeters.x, was.innerHalfExtentsMeters.x) << "no inner grows";
  }
  expectEveryCellCovered(room.floor, room.volumes());
}

TEST(WidenFadesWhereWeightsJump, ByAnInnerFaceWhereANeighbourWeighsMuchTheFadeDeepensInwards) {
  // 0.3 m apart (partNearRanges would part them; here they stay): leaving either inner range,
  // the other weighs (1 - 0.2) / 0.2 = 4 already, and the weight turns at 4 / 1.5 per metre
  // (warfare's probe_019 by probe_141).
  RangesInARoom room({{{0, 4, 0, 6}}, {{4.3, 10, 0, 6}}});
  const std::vector<InfluenceVolume> before = room.volumes();
  ASSERT_GT(room.steepestWhereCamerasAre(), 0.025);
  EXPECT_GE(room.widenFades(), 1u);
  EXPECT_LE(room.steepestWhereCamerasAre(), 0.02);
  for (std::size_t p = 0; p < before.size(); ++p) {
    const BoxInfluence& was = std::get<BoxInfluence>(before[p]);
    const BoxInfluence& is = room.box(p);
    EXPECT_EQ(is.halfExtentsMeters, was.halfExtentsMeters) << "nothing reaches further";
    EXPECT_EQ(is.innerHalfExtentsMeters.y, was.innerHalfExtentsMeters.y);
    EXPECT_LE(is.innerHalfExtentsMeters.x, was.innerHalfExtentsMeters.x);
  }
  expectEveryCellCovered(room.floor, room.volumes());
}

TEST(WidenFadesWhereWeightsJump, RangesAGapApartAreSmoothAlreadyAndStayAsTheyAre) {
  RangesInARoom room({{{0, 4, 0, 6}}, {{5, 10, 0, 6}}});
  const std::vector<InfluenceVolume> before = room.volumes();
  ASSERT_LE(room.steepestWhereCamerasAre(), 0.02);
  EXPECT_EQ(room.widenFades(), 0u);
  for (std::size_t p = 0; p < before.size(); ++p) {
    EXPECT_EQ(room.box(p).halfExtentsMeters, std::get<BoxInfluence>(before[p]).halfExtentsMeters);
    EXPECT_EQ(room.box(p).innerHalfExtentsMeters,
              std::get<BoxInfluence>(before[p]).innerHalfExtentsMeters);
  }
}

TEST(PartNearRanges, ARangeHeldNearItsNeighbourByItsCapturePartsFromItTheOtherWay) {
  // 0.2 m apart across the room (toxic's probe_080 and probe_130); the narrow one's capture
  // point, at its middle, leaves it no room to give.
  RangesInARoom room({{{0, 4, 0, 6}}, {{4.2, 4.5, 0, 6}}, {{5.5, 10, 0, 6}}});
  const std::vector<InfluenceVolume> before = room.volumes();
  const auto steepest = [&](std::span<const InfluenceVolume> volumes) {
    return measureWeightContinuity(volumes, gridOverVolumes(volumes, 1.6, 0.01)).largestJump;
  };
  EXPECT_GT(steepest(before), 0.04) << "1 cm apart";
  partNearRanges(1.0, {}, room.probes);
  const std::vector<InfluenceVolume> after = room.volumes();
  EXPECT_NEAR(innerHi(after[0]).x, 4.2 - 0.7, 1e-12) << "the wide one gives what is missing";
  EXPECT_EQ(innerLo(after[0]).x, 0.0);
  const BoxInfluence& wide = std::get<BoxInfluence>(after[0]);
  EXPECT_NEAR(wide.halfExtentsMeters.x - wide.innerHalfExtentsMeters.x, 1.5, 1e-12) << "its band";
  // The narrow one and the wide one east of it: 1 m apart already.
  EXPECT_EQ(innerLo(after[1]), innerLo(before[1]));
  EXPECT_EQ(innerHi(after[1]), innerHi(before[1]));
  EXPECT_EQ(innerLo(after[2]), innerLo(before[2]));
  EXPECT_LE(steepest(after), 0.02) << "1 cm apart";
  expectEveryCellCovered(room.floor, after);
}

TEST(PartNearRanges, TwoRangesWithLittleRoomEachGiveWhatTheyHave) {
  // Captures at their middles: 0.2 m to give on the left one's east side, 0.15 m on the right
  // one's west side; 0.1 m apart, 0.6 m missing: 0.45 m apart after.
  RangesInARoom room({{{3.5, 4, 0, 6}}, {{4.1, 4.5, 0, 6}}});
  partNearRanges(1.0, {}, room.probes);
  EXPECT_NEAR(innerHi(room.probes[0].influence).x, 4.0 - 0.2, 1e-12);
  EXPECT_NEAR(innerLo(room.probes[1].influence).x, 4.1 + 0.15, 1e-12);
}

// A 10 x 6 x 6 m room whose east part, x 6..10, is a ledge 1.5 m up (more than a step: a
// seed of its own), with one range over both floors from the ground's storey.
struct LedgeRoom {
  LevelRayCaster level;
  WalkableFloor floor;
  // With `landing`, the ledge's last 0.5 m (x 9.5..10) is a block 3 m tall, not walked.
  explicit LedgeRoom(bool landing = false)
      : level([&] {
          LevelMesh mesh = boxRoom({0, 0, 0}, {10, 6, 6});
          for (auto [lo, hi] :
               {std::pair{glm::vec3(6, 0, 0), glm::vec3(10, 6, 1.5f)},
                std::pair{glm::vec3(9.5f, 0, 0), glm::vec3(10, 6, landing ? 3 : 0)}}) {
            if (hi.z == 0) continue;
            LevelMesh block = boxRoom(lo, hi, "block");
            for (glm::uvec3& t : block.triangles) std::swap(t.y, t.z);  // faces outwards: a solid
            appendLevelMesh(mesh, block);
          }
          return mesh;
        }()) {
    const std::array<glm::dvec3, 2> seeds{glm::dvec3{2, 3, 1.6}, glm::dvec3{8, 3, 3.1}};
    floor = walkableFloor(level, seeds);
  }
  // The ground storey's range over x 0..toX (head room over z 0), raised among `others`.
  static InfluenceVolume ground(double toX) {
    return influenceOfBounds({0, 0, -0.5}, {toX, 6, 2.5}, 1.0);
  }
  LayoutProbe raised(double toX, std::span<const InfluenceVolume> others,
                     glm::dvec3 capture = {3, 3, 1.6}) const {
    std::vector<LayoutProbe> probes{{capture, ground(toX), kRoomFitMeters}};
    raiseRangesOverRaisedFloor(floor, 1.0, others, probes);
    return probes[0];
  }
};

TEST(RaiseRangesOverRaisedFloor, ACameraOverALedgeInTheWindowStaysInTheInnerRange) {
  const LedgeRoom room;
  const glm::dvec3 overLedge{8, 3, 1.5 + 2.2};  // 2.2 m over the ledge: a camera
  EXPECT_EQ(normalizedDistance(LedgeRoom::ground(10), overLedge), 1.0) << "over the band's top";
  const LayoutProbe probe = room.raised(10, {});
  EXPECT_NEAR(innerHi(probe.influence).z, 1.5 + kInfluenceHeadRoomMeters, 1e-4);
  EXPECT_EQ(innerLo(probe.influence), glm::dvec3(0, 0, -0.5));
  EXPECT_EQ(normalizedDistance(probe.influence, overLedge), 0.0);
  EXPECT_EQ(probe.captureMeters, glm::dvec3(3, 3, 1.6));
}

TEST(RaiseRangesOverRaisedFloor, ARangeRisesOverFloorInItsGapUpToARangeAboveAndNoFurther) {
  const LedgeRoom room;
  // The ground's range ends at x 5.5; the ledge's begins a gap away, at 6.5. The ledge floor
  // x 6..6.5 lies in the ground range's gap, in its height window: its top rises over it.
  const InfluenceVolume ledge = influenceOfBounds({6.5, 0, 1.0}, {10, 6, 4.0}, 1.0);
  const InfluenceVolume overGap = room.raised(5.5, std::span(&ledge, 1)).influence;
  EXPECT_NEAR(innerHi(overGap).z, 4.0, 1e-4);
  EXPECT_FALSE(innerRangesOverlap(overGap, ledge));

  // A range over the ground, 3 m up (a gallery), stops the rise under it.
  const InfluenceVolume gallery = influenceOfBounds({0, 0, 3.0}, {4, 6, 6.0}, 1.0);
  EXPECT_NEAR(innerHi(room.raised(5.5, std::array{ledge, gallery}).influence).z,
              3.0 - kInnerClearanceMeters, 1e-9);
}

TEST(RaiseRangesOverRaisedFloor, ARangeBesideItsHeightWithinTheGapDoesNotStopTheRise) {
  const LedgeRoom room;
  // The ledge's range reaches down to 2 m, 0.5 m from the ground's (cut back to its capture
  // point): the rise brings the two no nearer in plan.
  const InfluenceVolume beside = influenceOfBounds({6, 0, 2.0}, {10, 6, 5.0}, 1.0);
  const InfluenceVolume risen = room.raised(5.5, std::span(&beside, 1)).influence;
  EXPECT_NEAR(innerHi(risen).z, 4.0, 1e-4);
  EXPECT_DOUBLE_EQ(innerHi(risen).x, 5.5);
  EXPECT_FALSE(innerRangesOverlap(risen, beside));
}

TEST(RaiseRangesOverRaisedFloor, UnderARangeAboveItGivesThatRangeTheGapInPlanAndRises) {
  // A landing 3 m up at x 9.5..10, its range from 2.5 m (head room over the ground): the
  // ground's range, holding the ledge, would stop at 2.5 m, 1 m over the ledge.
  const LedgeRoom room(true);
  const InfluenceVolume landing = influenceOfBounds({9.5, 0, 2.5}, {10, 6, 5.5}, 1.0);
  const InfluenceVolume risen = room.raised(10, std::span(&landing, 1)).influence;
  EXPECT_DOUBLE_EQ(innerHi(risen).x, 8.5) << "a gap from the landing's range";
  EXPECT_NEAR(innerHi(risen).z, 4.0, 1e-4);
  EXPECT_EQ(innerLo(risen), glm::dvec3(0, 0, -0.5));
  EXPECT_FALSE(innerRangesOverlap(risen, landing));

  // Its capture point at x 9 keeps the plan, and the range stops under the landing's.
  EXPECT_EQ(innerHi(room.raised(10, std::span(&landing, 1), {9, 3, 1.6}).influence),
            glm::dvec3(10, 6, 2.5));
  // A landing range 3 m wide: the cut would give up more than a fifth of the plan, and leave
  // ledge floor under the landing's range 3.5 m from every range over its height.
  const InfluenceVolume wide = influenceOfBounds({7, 0, 2.5}, {10, 6, 5.5}, 1.0);
  EXPECT_EQ(innerHi(room.raised(10, std::span(&wide, 1)).influence), glm::dvec3(10, 6, 2.5));
}

TEST(RaiseRangesOverRaisedFloor,
     UnderAStoreyAndALandingItGivesTheLandingTheGapAndRisesToTheStorey) {
  // The landing of the test above, and a gallery storey over all of the room from 3.2 m that
  // no cut in plan can clear (it spans the capture point). The gallery bounds the rise; the
  // landing, lower, must not: the range stopped at 2.5 m, 1 m over the ledge (stormkeep: a
  // camera over a stair stood between the two storeys' bands).
  const LedgeRoom room(true);
  const InfluenceVolume landing = influenceOfBounds({9.5, 0, 2.5}, {10, 6, 5.5}, 1.0);
  const InfluenceVolume gallery = influenceOfBounds({0, 0, 3.2}, {10, 6, 6.0}, 1.0);
  const InfluenceVolume risen = room.raised(10, std::array{landing, gallery}).influence;
  EXPECT_DOUBLE_EQ(innerHi(risen).x, 8.5) << "a gap from the landing's range";
  EXPECT_NEAR(innerHi(risen).z, 3.2 - kInnerClearanceMeters, 1e-9) << "up to the gallery";
  EXPECT_EQ(innerLo(risen), glm::dvec3(0, 0, -0.5));
  EXPECT_FALSE(innerRangesOverlap(risen, landing));
  EXPECT_FALSE(innerRangesOverlap(risen, gallery));
}

TEST(FillsForUncoveredFloor, EyesOverALedgeOverTheirRangesTopGetAFillStartingOverThatTop) {
  // The ground's range stops at 2.5 m (as under a gallery range above it, head_room.h): an eye
  // 1.6 m over the ledge (z 3.1) is over its band too, in no volume; its floor is covered.
  const LedgeRoom room;
  const std::vector<InfluenceVolume> volumes{LedgeRoom::ground(10)};
  const std::vector<FloorFill> fills =
      fillsForUncoveredFloor(room.level, room.floor, volumes, 1.0, 1.6);
  ASSERT_EQ(fills.size(), 1u) << "the ledge's eyes, one group";
  EXPECT_TRUE(fills[0].optional) << "its floor is in the ground's range";
  EXPECT_DOUBLE_EQ(innerLo(fills[0].influence).z, 2.5 + kInnerClearanceMeters) << "over its top";
  EXPECT_DOUBLE_EQ(innerHi(fills[0].influence).z, 1.5 + 2.5) << "head room over the ledge";
  EXPECT_FALSE(innerRangesOverlap(volumes[0], fills[0].influence));
  for (const FloorCell& c : room.floor.cells) {
    if (c.pointMeters.z < 1.0) continue;
    const glm::dvec3 eye = c.pointMeters + glm::dvec3(0, 0, 1.6);
    EXPECT_LE(normalizedDistance(fills[0].influence, eye), 0.67) << eye.x << ", " << eye.y;
  }
}

TEST(MajorityRange, EndsHalfWayAcrossTheGapWhereANeighbourWeighsAsMuch) {
  // Two ranges a gap (1 m) apart along x, each band kOuterBandOverGap gaps deep.
  const double gap = 1.0, band = kOuterBandOverGap * gap;
  const auto box = [&](double centreX) {
    BoxInfluence b;
    b.centerMeters = {centreX, 0, 1};
    b.innerHalfExtentsMeters = {2, 2, 1};
    b.halfExtentsMeters = b.innerHalfExtentsMeters + glm::dvec3(band, band, kVerticalBandMeters);
    return InfluenceVolume{b};
  };
  const std::array<InfluenceVolume, 2> volumes{box(0), box(4 + gap)};
  const InfluenceVolume majorityVolume = majorityRange(volumes[0]);
  const auto& majority = std::get<BoxInfluence>(majorityVolume);
  const double face = majority.centerMeters.x + majority.halfExtentsMeters.x;
  EXPECT_NEAR(face, 2 + 0.5 * gap, 1e-12);
  const auto weightOfFirst = [&](double x) {
    for (const ProbeWeight& w : blendWeights(volumes, {x, 0, 1}))
      if (w.probe == 0) return w.weight;
    return 0.0;
  };
  EXPECT_NEAR(weightOfFirst(face), 0.5, 1e-9);
  EXPECT_GT(weightOfFirst(face - 0.01), 0.5);
  EXPECT_LT(weightOfFirst(face + 0.01), 0.5);
  EXPECT_NEAR(majority.halfExtentsMeters.z, 1 + kVerticalBandMeters / 3, 1e-12);
}

}  // namespace
}  // namespace probeproxy
