// survey (geometry/survey/): the walkable floor's flood fill on a synthetic level with an
// unreachable platform and a sealed void, the blend of two overlapping probes against a
// hand-computed value, area-weighted percentiles, storeys, what the worst floor reaches, the JSON
// names and the error map.

#include "core/errors/input_error.h"
#include "geometry/builtin/box_room.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/export/runtime_probe_shape.h"
#include "geometry/floor/floor_graph.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/survey/area_percentile.h"
#include "geometry/survey/blended_error.h"
#include "geometry/survey/run_survey.h"
#include "geometry/survey/storeys.h"
#include "geometry/survey/survey_map.h"
#include "geometry/survey/worst_floor.h"
#include "plugin/jobs/survey/survey_report.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace probeproxy {
namespace {

// A solid block (a pillar, a platform): a box room turned inside out, faces outwards.
LevelMesh block(glm::vec3 lo, glm::vec3 hi) {
  LevelMesh b = boxRoom(lo, hi, "block");
  for (glm::uvec3& t : b.triangles) std::swap(t.y, t.z);
  return b;
}

// A 10 x 10 x 3.5 m room with a 1 m tall pillar [4, 6]^2 (its top has head room but is more
// than a step up), a 0.3 m platform [1, 3]^2 (a step up: walkable), and a sealed room beside
// it, [12, 16] x [0, 4], that nothing connects to.
LevelMesh pillarRoomAndVoid() {
  LevelMesh level = boxRoom({0, 0, 0}, {10, 10, 3.5f});
  appendLevelMesh(level, block({4, 4, 0}, {6, 6, 1.0f}));
  appendLevelMesh(level, block({1, 1, 0}, {3, 3, 0.3f}));
  appendLevelMesh(level, boxRoom({12, 0, 0}, {16, 4, 3}, "void"));
  return level;
}

TEST(WalkableFloor, PillarTopAndSealedVoidAreNotWalkable) {
  const LevelRayCaster level(pillarRoomAndVoid());
  const glm::dvec3 seed{8.0, 8.0, 1.6};
  const WalkableFloor floor = walkableFloor(level, std::span(&seed, 1));
  // 0.25 m cells on a grid from x = 0: the room is 40 x 40 cells, the pillar takes 8 x 8.
  ASSERT_DOUBLE_EQ(floor.spacingMeters, 0.25);
  EXPECT_EQ(floor.seedsOnFloor, 1u);
  EXPECT_EQ(floor.cells.size(), 40u * 40u - 8u * 8u);
  EXPECT_NEAR(floor.areaSquareMeters(), 96.0, 1e-9);
  bool platformTop = false;
  for (const FloorCell& c : floor.cells) {
    EXPECT_LT(c.pointMeters.x, 10.0) << "the sealed room is not reached";
    EXPECT_GT(std::abs(c.pointMeters.z - 1.0), 0.01) << "the pillar top is not reached";
    platformTop = platformTop || std::abs(c.pointMeters.z - 0.3) < 1e-4;
  }
  EXPECT_TRUE(platformTop) << "a 0.3 m platform is a step up";
  // The pillar top, the void's floor and both roofs (the outside of the map) were floor
  // candidates: the flood fill left them out.
  EXPECT_EQ(floor.candidateCells, floor.cells.size() + 8u * 8u + 16u * 16u + 40u * 40u + 16u * 16u);
}

TEST(WalkableFloor, ASeedOnThePillarReachesOnlyItsTop) {
  const LevelRayCaster level(pillarRoomAndVoid());
  const glm::dvec3 seed{5.0, 5.0, 2.0};
  const WalkableFloor floor = walkableFloor(level, std::span(&seed, 1));
  EXPECT_EQ(floor.cells.size(), 64u);
  EXPECT_NEAR(floor.areaSquareMeters(), 4.0, 1e-9);
}

TEST(WalkableFloor, ALowCeilingIsNotWalkable) {
  // Under a 1.5 m slab over [0, 2] x [0, 10] a player cannot stand (head clearance 1.8 m).
  LevelMesh room = boxRoom({0, 0, 0}, {10, 10, 3});
  appendLevelMesh(room, block({0, 0, 1.5f}, {2, 10, 3}));
  const LevelRayCaster level(room);
  const glm::dvec3 seed{8.0, 8.0, 1.6};
  const WalkableFloor floor = walkableFloor(level, std::span(&seed, 1));
  EXPECT_NEAR(floor.areaSquareMeters(), 80.0, 1e-9);
}

TEST(WalkableFloor, AWallWithADoorConnectsOnlyThroughTheDoor) {
  // Two rooms side by side with a 1 m door: the far room is reached; with no door it is not.
  for (const bool door : {true, false}) {
    LevelMesh level = boxRoom({0, 0, 0}, {10, 4, 3});
    appendLevelMesh(level, block({4.9f, 0, 0}, {5.1f, door ? 1.5f : 4.0f, 3}));
    if (door) appendLevelMesh(level, block({4.9f, 2.5f, 0}, {5.1f, 4, 3}));
    const LevelRayCaster caster(level);
    const glm::dvec3 seed{1.0, 2.0, 1.6};
    const WalkableFloor floor = walkableFloor(caster, std::span(&seed, 1));
    const bool farRoom = std::any_of(floor.cells.begin(), floor.cells.end(),
                                     [](const FloorCell& c) { return c.pointMeters.x > 6.0; });
    EXPECT_EQ(farRoom, door);
  }
}

TEST(WalkableFloor, TheBackOfACeilingIsFloorOnlyWhereWindingIsNotTrusted) {
  // A roof terrace at the height of a room's ceiling: the terrace's top faces up, the room's
  // ceiling down. Where faces are one-sided (a BSP), the ceiling's back is the void over the
  // map and the walk stays on the terrace; a plain mesh's winding is not trusted, so there the
  // walk steps onto the roof as well.
  for (const bool oneSided : {true, false}) {
    LevelMesh mesh = boxRoom({0, 0, 0}, {10, 4, 3});
    appendLevelMesh(mesh, block({10, 0, 2.9f}, {14, 4, 3}));
    mesh.facesOneSided = oneSided;
    const LevelRayCaster level(mesh);
    const glm::dvec3 seed{12.0, 2.0, 4.6};
    const WalkableFloor floor = walkableFloor(level, std::span(&seed, 1));
    EXPECT_NEAR(floor.areaSquareMeters(), oneSided ? 16.0 : 56.0, 1e-9) << oneSided;
  }
}

// layout fills one level-wide graph for each candidate instead of casting a walkable floor per
// region: where the region starts at the level's corner the two grids coincide, and the fill
// must give the region's own walkable floor cell for cell. A region that cuts the room in two
// along the wall of the door keeps the fill from walking around it.
TEST(FloorGraph, ARegionFillIsTheRegionsWalkableFloor) {
  LevelMesh level = boxRoom({0, 0, 0}, {10, 4, 3});
  appendLevelMesh(level, block({4.9f, 0, 0}, {5.1f, 1.5f, 3}));
  appendLevelMesh(level, block({4.9f, 2.5f, 0}, {5.1f, 4, 3}));
  appendLevelMesh(level, block({7, 1, 0}, {8, 3, 1.0f}));
  const LevelRayCaster caster(level);
  const FloorGraph graph = buildFloorGraph(caster, WalkableFloorOptions{});
  const glm::dvec3 seed{1.0, 1.0, 1.6};
  for (const glm::dvec2 regionMax :
       {glm::dvec2(3.0, 4.0), glm::dvec2(8.6, 1.4), glm::dvec2(1e9, 1e9), glm::dvec2(5.0, 2.2)}) {
    WalkableFloorOptions region;
    region.regionMinMeters = glm::dvec2(-5.0, -5.0);
    region.regionMaxMeters = regionMax;
    const WalkableFloor want = walkableFloor(caster, std::span(&seed, 1), region);
    const WalkableFloor got =
        reachableFloor(graph, std::span(&seed, 1), region.regionMinMeters, regionMax);
    ASSERT_EQ(got.cells.size(), want.cells.size())
        << "region to " << regionMax.x << ", " << regionMax.y;
    EXPECT_GT(got.cells.size(), 0u);
    for (std::size_t i = 0; i < got.cells.size(); ++i) {
      EXPECT_EQ(got.cells[i].pointMeters, want.cells[i].pointMeters);
      EXPECT_EQ(got.cells[i].areaSquareMeters, want.cells[i].areaSquareMeters);
    }
    EXPECT_EQ(got.candidateCells, want.candidateCells);
    EXPECT_EQ(got.seedsOnFloor, 1u);
  }
  // The region that ends at y = 1.4 holds the wall's lower part but not the door (y 1.5 to
  // 2.5): the far room lies beyond the wall for a walk that may not leave the region.
  const glm::dvec2 lo(-5.0), hi(8.6, 1.4);
  for (const FloorCell& c : reachableFloor(graph, std::span(&seed, 1), lo, hi).cells)
    EXPECT_LT(c.pointMeters.x, 5.0);
}

TEST(WalkableFloor, BadOptionsAreOneLineInputErrors) {
  WalkableFloorOptions o;
  o.gridSpacingMeters = 0.0;
  EXPECT_THROW(o.check(), InputError);
  o = {};
  o.kneeHeightMeters = 0.1;  // under the step height: a stair's riser would be a wall
  EXPECT_THROW(o.check(), InputError);
}

// Two box influences over a 10 x 4 x 3 m room, overlapping on x in [4, 6]: A around x = 3
// (inner range x in [2, 4]), B around x = 7 (inner x in [6, 8]); full height and width.
std::vector<SurveyProbe> twoProbes(ProxyShape proxyA, ProxyShape proxyB) {
  auto influence = [](double x) {
    BoxInfluence b;
    b.centerMeters = {x, 2.0, 1.5};
    b.halfExtentsMeters = {3.0, 2.0, 1.5};
    b.innerHalfExtentsMeters = {1.0, 2.0, 1.5};
    return InfluenceVolume(b);
  };
  return {{{3.0, 2.0, 1.5}, influence(3.0), std::move(proxyA)},
          {{7.0, 2.0, 1.5}, influence(7.0), std::move(proxyB)}};
}

const BoxShape kRoom{{5.0, 2.0, 1.5}, {5.0, 2.0, 1.5}, glm::dquat(1, 0, 0, 0)};

ReflectionSample sampleAt(const LevelRayCaster& level, glm::dvec3 x, glm::dvec3 r) {
  ReflectionSample s;
  s.xMeters = x;
  s.normal = {0, 0, 1};
  s.reflected = glm::normalize(r);
  s.eyeMeters = x - glm::dvec3(-s.reflected.x, -s.reflected.y, s.reflected.z);
  traceTrueHit(level, s);
  return s;
}

std::vector<InfluenceVolume> volumesOf(const std::vector<SurveyProbe>& probes) {
  std::vector<InfluenceVolume> v;
  for (const SurveyProbe& p : probes) v.push_back(p.influence);
  return v;
}

TEST(BlendedError, TwoOverlappingProbesAgainstAHandComputedValue) {
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 4, 3}));
  // At x = 4.5: A's normalized distance (4.5 - 3 - 1) / (3 - 1) = 0.25, B's (7 - 4.5 - 1) / 2
  // = 0.75; Lagarde weights (1 - a) / a = 3 and 1/3, normalized 0.9 and 0.1.
  // r = (1, 0, 1)/sqrt 2 from (4.5, 2, 0) meets the ceiling at H = (7.5, 2, 3). A looks up
  // through the exact room box (error 0); B through no proxy: d = r against d* = H - C_B =
  // (0.5, 0, 1.5), an angle of atan(3) - 45 deg = 26.5651 deg. So 0.9 * 0 + 0.1 * 26.5651.
  const auto probes = twoProbes(kRoom, InfiniteShape{});
  const auto volumes = volumesOf(probes);
  const ReflectionSample s = sampleAt(level, {4.5, 2.0, 0.0}, {1, 0, 1});
  ASSERT_NEAR(glm::distance(s.trueHitMeters, glm::dvec3(7.5, 2.0, 3.0)), 0.0, 1e-4);
  const double expected = 0.1 * (std::atan(3.0) * 180.0 / M_PI - 45.0);
  const SurveySampleError e = blendedSampleError(level, probes, volumes, s, BlendOptions{});
  EXPECT_FALSE(e.uncovered);
  EXPECT_EQ(e.occludedWeight, 0.0);
  EXPECT_NEAR(e.errorDeg, expected, 1e-4);
  EXPECT_NEAR(expected, 2.65651, 1e-5);
  EXPECT_EQ(e.heaviestProbe, 0) << "A weighs 0.9";
}

TEST(BlendedError, AMissCountsAs180Degrees) {
  // B's proxy is a small box away from x: the ray from x never leaves it, a miss.
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 4, 3}));
  const BoxShape away{{7.0, 2.0, 1.5}, {0.5, 0.5, 0.5}, glm::dquat(1, 0, 0, 0)};
  const auto probes = twoProbes(kRoom, away);
  const auto volumes = volumesOf(probes);
  const ReflectionSample s = sampleAt(level, {4.5, 2.0, 0.0}, {1, 0, 1});
  const SurveySampleError e = blendedSampleError(level, probes, volumes, s, BlendOptions{});
  EXPECT_NEAR(e.errorDeg, 0.1 * kMissErrorDeg, 1e-4);
}

TEST(BlendedError, NoCoveringProbeIsUncoveredAndAHiddenProbeIsOccludedWeight) {
  // A wall at x = 5.5 (up to the ceiling) hides H = (7.5, 2, 3) from A's capture point,
  // not from B's: A's weight 0.9 is occluded, the error is B's alone.
  LevelMesh room = boxRoom({0, 0, 0}, {10, 4, 3});
  appendLevelMesh(room, block({5.4f, 0, 2.0f}, {5.6f, 4, 3}));
  const LevelRayCaster level(room);
  const auto probes = twoProbes(kRoom, InfiniteShape{});
  const auto volumes = volumesOf(probes);
  const ReflectionSample s = sampleAt(level, {4.5, 2.0, 0.0}, {1, 0, 1});
  ASSERT_TRUE(trueHitHiddenFrom(level, probes[0].captureMeters, s));
  ASSERT_FALSE(trueHitHiddenFrom(level, probes[1].captureMeters, s));
  const SurveySampleError e = blendedSampleError(level, probes, volumes, s, BlendOptions{});
  EXPECT_NEAR(e.occludedWeight, 0.9, 1e-9);
  EXPECT_EQ(e.heaviestProbe, 1) << "the heaviest probe is of those that see the hit";
  const glm::dvec3 ideal = s.trueHitMeters - probes[1].captureMeters;
  const double expected =
      std::acos(std::clamp(glm::dot(glm::normalize(ideal), s.reflected), -1.0, 1.0)) * 180.0 / M_PI;
  EXPECT_NEAR(e.errorDeg, expected, 1e-4);

  const ReflectionSample outside = sampleAt(level, {20.0, 2.0, 0.0}, {1, 0, 1});
  EXPECT_TRUE(blendedSampleError(level, probes, volumes, outside, BlendOptions{}).uncovered);
}

TEST(AreaPercentile, WeighsByArea) {
  // 1 deg over 9 m^2 and 10 deg over 1 m^2: the median is 1, the p95 is 10.
  std::vector<AreaValue> v = {{10.0, 1.0}, {1.0, 9.0}};
  EXPECT_EQ(areaPercentile(v, 0.5), 1.0);
  EXPECT_EQ(areaPercentile(v, 0.9), 1.0);
  EXPECT_EQ(areaPercentile(v, 0.95), 10.0);
  std::vector<AreaValue> none;
  EXPECT_TRUE(std::isnan(areaPercentile(none, 0.5)));
}

// The room of the blend tests, surveyed whole: exact proxies give no error anywhere.
TEST(Survey, ExactProxiesOverTheWholeFloorAreExactAndDeterministic) {
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 4, 3}));
  const auto probes = twoProbes(kRoom, kRoom);
  SurveyOptions o;
  const SurveyResult a = surveyProbes(probes, level, o);
  EXPECT_NEAR(a.figures.walkableSquareMeters, 40.0, 1e-9);
  EXPECT_EQ(a.figures.samples, a.floor.cells.size() * 8);
  EXPECT_EQ(a.figures.probes, 2u);
  EXPECT_LT(a.figures.p95Deg, 1e-3);
  EXPECT_EQ(a.figures.uncoveredShare, 0.0);
  EXPECT_EQ(a.figures.occludedShare, 0.0);
  EXPECT_EQ(a.figures.overToleranceShare, 0.0);
  // Same figures and cells on one thread.
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const SurveyResult b = surveyProbes(probes, level, o);
  EXPECT_EQ(a.figures.medianDeg, b.figures.medianDeg);
  EXPECT_EQ(a.figures.p95Deg, b.figures.p95Deg);
  ASSERT_EQ(a.cells.size(), b.cells.size());
  for (std::size_t i = 0; i < a.cells.size(); ++i) EXPECT_EQ(a.cells[i].p95Deg, b.cells[i].p95Deg);
}

TEST(Survey, NoCorrectionIsWorseAndHalfTheRoomUncoveredIsHalf) {
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 4, 3}));
  auto probes = twoProbes(InfiniteShape{}, InfiniteShape{});
  const SurveyResult r = surveyProbes(probes, level, SurveyOptions{});
  EXPECT_GT(r.figures.p95Deg, 5.0);
  EXPECT_GT(r.figures.overToleranceShare, 0.05);
  // Only A: its outer range ends at x = 6, so 4 of the 10 m are uncovered.
  probes.pop_back();
  SurveyOptions o;
  o.seedPointsMeters = {{1.0, 1.0, 1.0}};
  const SurveyResult half = surveyProbes(probes, level, o);
  EXPECT_NEAR(half.figures.uncoveredShare, 0.4, 1e-9);
}

TEST(Survey, NoFloorUnderTheSeedsIsAnInputError) {
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 4, 3}));
  SurveyOptions o;
  o.seedPointsMeters = {{50.0, 50.0, 1.0}};
  EXPECT_THROW(surveyProbes(twoProbes(kRoom, kRoom), level, o), InputError);
  o = {};
  o.toleranceDeg = -1.0;
  EXPECT_THROW(o.check(), InputError);
}

// Four floor samples of 1 m^2 each, errors 1, 10, 20 and 30 deg, at the threshold 10: the
// worst floor is the last three, one reaching the sky, one hitting a kerb 1 m away inside the
// heaviest probe's box, one a wall 5 m away on that box's face (half its weight occluded).
TEST(WorstFloor, SharesOfWhatTheWorstReflectionsReach) {
  const BoxShape room{{5.0, 5.0, 1.5}, {5.0, 5.0, 1.5}, glm::dquat(1, 0, 0, 0)};
  const std::vector<ProxyShape> proxies = {InfiniteShape{}, room};
  auto sample = [](glm::dvec3 x, glm::dvec3 r, std::optional<glm::dvec3> hit) {
    FloorSample f;
    f.sample.xMeters = x;
    f.sample.reflected = glm::normalize(r);
    f.sample.hitsSky = !hit;
    if (hit) f.sample.trueHitMeters = *hit;
    f.areaSquareMeters = 1.0;
    return f;
  };
  const std::vector<FloorSample> samples = {sample({5, 5, 0}, {0, 1, 1}, glm::dvec3(5, 10, 5)),
                                            sample({5, 5, 0}, {0, 0, 1}, std::nullopt),
                                            sample({5, 5, 0}, {1, 0, 0.2}, glm::dvec3(6, 5, 0.2)),
                                            sample({5, 5, 0}, {1, 0, 0.3}, glm::dvec3(10, 5, 1.5))};
  std::vector<SurveySampleError> errors(4);
  const double deg[] = {1.0, 10.0, 20.0, 30.0};
  const int heaviest[] = {0, 0, 1, 1};
  for (std::size_t i = 0; i < 4; ++i) {
    errors[i].errorDeg = deg[i];
    errors[i].areaSquareMeters = 1.0;
    errors[i].heaviestProbe = heaviest[i];
  }
  errors[3].occludedWeight = 0.5;
  const WorstFloor w = worstFloor(errors, samples, 10.0, [&](int i) {
    return SurveyProbeRef{&proxies[static_cast<std::size_t>(i)], 10 + i};
  });
  EXPECT_EQ(w.thresholdDeg, 10.0);
  EXPECT_DOUBLE_EQ(w.squareMeters, 2.5);
  EXPECT_DOUBLE_EQ(w.skyShare, 0.4);
  EXPECT_DOUBLE_EQ(w.nearHitShare, 0.4);
  EXPECT_DOUBLE_EQ(w.hitInsideProxyShare, 0.4) << "the wall on the box's face is not inside";
  ASSERT_EQ(w.probes.size(), 2u);
  EXPECT_EQ(w.probes[0].probe, 11);
  EXPECT_DOUBLE_EQ(w.probes[0].share, 0.6);
  EXPECT_EQ(w.probes[1].probe, 10);
  EXPECT_DOUBLE_EQ(w.probes[1].share, 0.4);
}

// A room whose proxies are its exact box, with a 0.6 m kerb along one wall: every error left is
// a reflection meeting the kerb, near the floor point and inside the proxy.
TEST(Survey, TheWorstFloorOfExactRoomProxiesIsTheKerbStandingInTheRoom) {
  LevelMesh room = boxRoom({0, 0, 0}, {10, 4, 3});
  appendLevelMesh(room, block({0, 3.0f, 0}, {10, 4, 0.6f}));
  const LevelRayCaster level(room);
  const auto probes = twoProbes(kRoom, kRoom);
  const SurveyResult r = surveyProbes(probes, level, SurveyOptions{});
  const WorstFloor& w = r.worst;
  EXPECT_EQ(w.thresholdDeg, r.figures.p95Deg);
  EXPECT_GT(w.thresholdDeg, 5.0);
  EXPECT_NEAR(w.squareMeters, 0.05 * r.figures.walkableSquareMeters,
              0.01 * r.figures.walkableSquareMeters);
  EXPECT_EQ(w.skyShare, 0.0);
  EXPECT_EQ(w.hitInsideProxyShare, 1.0);
  EXPECT_GT(w.nearHitShare, 0.9);
  ASSERT_EQ(w.probes.size(), 2u);
  EXPECT_NEAR(w.probes[0].share + w.probes[1].share, 1.0, 1e-12);
}

TEST(Storeys, FloorOverFloorGivesTwoStoreys) {
  // A 6 m tall room with a 3 x 10 m gallery slab at z = 2.9..3 along one wall, head room
  // above and below it; a seed on each.
  LevelMesh room = boxRoom({0, 0, 0}, {10, 10, 6});
  appendLevelMesh(room, block({0, 0, 2.9f}, {3, 10, 3.0f}));
  const LevelRayCaster level(room);
  const std::vector<glm::dvec3> seeds = {{8.0, 8.0, 1.6}, {1.0, 5.0, 4.0}};
  const WalkableFloor floor = walkableFloor(level, seeds);
  const std::vector<int> storey = floorStoreys(floor);
  ASSERT_EQ(storey.size(), floor.cells.size());
  for (std::size_t i = 0; i < storey.size(); ++i)
    EXPECT_EQ(storey[i], floor.cells[i].pointMeters.z > 1.0 ? 1 : 0);
}

TEST(SurveyReport, JsonHasTheDesignNamesInOrder) {
  SurveyResult r;
  r.scene = "room";
  r.figures.walkableSquareMeters = 40.0;
  r.worst.squareMeters = 2.0;
  r.worst.probes = {{1, 0.75}, {0, 0.25}};
  std::vector<Probe> probes(2);
  probes[0].name = "hall";
  probes[1].name = "stair";
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(jobs::surveyReportJson(r, probes));
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"scene", "engine", "walkable_m2", "samples", "probes",
                                            "median_deg", "p95_deg", "over_tolerance_share",
                                            "uncovered_share", "occluded_share", "worst_floor",
                                            "seconds"}));
  EXPECT_TRUE(j["p95_deg"].is_null()) << "no visible floor: no figure, not a made-up one";
  EXPECT_EQ(j["worst_floor"]["probes"][0]["name"], "stair");
  EXPECT_EQ(j["worst_floor"]["probes"][1]["share"], 0.25);
}

TEST(SurveyMap, ReadableWideAndTheSameBytesEachTime) {
  const LevelRayCaster level(boxRoom({0, 0, 0}, {10, 4, 3}));
  const auto probes = twoProbes(kRoom, InfiniteShape{});
  const SurveyResult r = surveyProbes(probes, level, SurveyOptions{});
  std::vector<Probe> sceneProbes(2);
  sceneProbes[0].influence = probes[0].influence;
  sceneProbes[1].influence = probes[1].influence;
  const std::vector<int> storeys = floorStoreys(r.floor);
  const Rgb8Canvas a = renderSurveyMap(r, sceneProbes, storeys, 0, 1);
  const Rgb8Canvas b = renderSurveyMap(r, sceneProbes, storeys, 0, 1);
  EXPECT_GE(a.width, 800);
  EXPECT_EQ(a.rgb8, b.rgb8);
  // The scale is fixed: an exact cell is the first bin's colour, 50 deg the last's.
  EXPECT_EQ(surveyErrorColour(0.0), surveyErrorColour(0.2));
  EXPECT_NE(surveyErrorColour(0.2), surveyErrorColour(50.0));
  EXPECT_EQ(surveyErrorColour(50.0), surveyErrorColour(170.0));
}

TEST(RuntimeProbeShape, EachKindLooksUpThroughItsOwnShape) {
  RuntimeProbe p;
  p.name = "a";
  p.method = Method::Infinite;
  EXPECT_TRUE(std::holds_alternative<InfiniteShape>(runtimeProbeShape(p, "proxies.json")));
  p.method = Method::CheapK;
  p.kPerMeter = 0.5;
  EXPECT_EQ(std::get<CheapKShape>(runtimeProbeShape(p, "proxies.json")).kPerMeter, 0.5);
  p.method = Method::Obb;
  p.box = kRoom;
  EXPECT_EQ(std::get<BoxShape>(runtimeProbeShape(p, "proxies.json")).halfExtentsMeters,
            kRoom.halfExtentsMeters);
  p.method = Method::Convex;
  EXPECT_THROW(runtimeProbeShape(p, "proxies.json"), InputError) << "convex without planes";
  p.convex = convexFromBox(kRoom);
  EXPECT_EQ(std::get<ConvexProxy>(runtimeProbeShape(p, "proxies.json")).planes.size(), 6u);
  p.method = Method::Sphere;  // a sphere probe whose export lost its sphere
  EXPECT_THROW(runtimeProbeShape(p, "proxies.json"), InputError);
}

}  // namespace
}  // namespace probeproxy
