// Each stage of the proxy build (geometry/probe_proxies/build_probe_proxy.h) on its own, in a box
// room where every answer is exact.

#include "core/errors/invariant_checks.h"
#include "geometry/builtin/box_room.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/probe_proxies/fit_candidates.h"
#include "geometry/probe_proxies/probe_samples.h"
#include "geometry/probe_proxies/probe_view.h"
#include "geometry/probe_proxies/select_proxy.h"
#include "geometry/probe_proxies/simplify_hull.h"
#include "tests/unit/room_probe.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {
namespace {

const glm::dvec3 kLo(-4, -2, 0), kHi(6, 3, 3), kCapture(1, 0.5, 1.6);

const LevelRayCaster& room() {
  static const LevelMesh mesh = boxRoom(glm::vec3(kLo), glm::vec3(kHi));
  static const LevelRayCaster caster(mesh);
  return caster;
}

Probe probe() { return probeAt(kCapture, kLo, kHi); }

ProxyBuildOptions options() {
  ProxyBuildOptions o;
  o.depthFaceSize = 32;
  o.samples.targetSamples = 256;
  return o;
}

// The room's six walls as outward planes (n . x <= d inside).
bool isRoomWall(const ProxyPlane& p, double tolerance) {
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      glm::dvec3 n(0.0);
      n[axis] = side == 0 ? -1.0 : 1.0;
      const double d = side == 0 ? -kLo[axis] : kHi[axis];
      if (glm::dot(p.normal, n) > 1 - 1e-9 && std::abs(p.offsetMeters - d) < tolerance) return true;
    }
  }
  return false;
}

TEST(BuildStages, SeeLevelFindsEveryTexelOnTheWallsAndTheSixWallPlanes) {
  const ProbeView view = seeLevel(room(), kCapture, 32);
  EXPECT_EQ(view.hits.size(), 6u * 32 * 32);
  EXPECT_EQ(view.pointsMeters.size(), view.hits.size());  // a closed room has no sky
  EXPECT_EQ(view.skyShare, 0.0);
  for (const glm::dvec3& p : view.pointsMeters) {
    const glm::dvec3 inside = glm::min(p - kLo, kHi - p);
    EXPECT_LT(std::min({inside.x, inside.y, inside.z}), 1e-5);  // on a wall
  }
  EXPECT_NEAR(view.nearestMeters, 1.4, 1e-2);  // the ceiling, straight up (a texel centre)
  EXPECT_LT(view.farthestMeters, glm::distance(kCapture, kLo) + 1e-5);
  ASSERT_EQ(view.wallPlanes.size(), 6u);
  for (const ProxyPlane& p : view.wallPlanes) EXPECT_TRUE(isRoomWall(p, 1e-5));
}

TEST(BuildStages, FitAndReportSamplesAreDrawnWithDifferentSeeds) {
  const ProbeSamples s = drawProbeSamples(room(), probe(), options());
  ASSERT_FALSE(s.floor.empty());
  ASSERT_FALSE(s.all.empty());
  EXPECT_EQ(s.fit.size() > s.floor.size(), true);  // mirror_floor and all_surfaces together
  for (const ReflectionSample& r : s.floor) EXPECT_NEAR(r.normal.z, 1.0, 1e-6);
  EXPECT_NE(s.fit.front().xMeters, s.floor.front().xMeters);
}

TEST(BuildStages, FitCandidatesComeInTheirFixedOrderAndTheBoxIsTheRoom) {
  const ProbeView view = seeLevel(room(), kCapture, 32);
  const ProbeSamples s = drawProbeSamples(room(), probe(), options());
  const FittedCandidates f = fitCandidates(view, s.fit, ProxyShape(InfiniteShape{}));
  std::vector<std::string> kinds;
  for (const ProxyCandidate& c : f.candidates) kinds.push_back(candidateName(c));
  EXPECT_EQ(kinds, (std::vector<std::string>{"authored", "infinite", "cheap_k", "sphere",
                                             "min_sphere", "aabb", "obb", "room_box", "hull"}));
  ASSERT_TRUE(f.hull.has_value());
  EXPECT_TRUE(f.findings.empty());
  const BoxShape& box = std::get<BoxShape>(f.candidates[5].shape);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(box.centerMeters[axis] - box.halfExtentsMeters[axis], kLo[axis], 1e-5);
    EXPECT_NEAR(box.centerMeters[axis] + box.halfExtentsMeters[axis], kHi[axis], 1e-5);
  }
}

TEST(BuildStages, SimplificationStartsFromTheWallsAndNamesEachStepByItsPlanes) {
  const ProbeView view = seeLevel(room(), kCapture, 32);
  const ProbeSamples s = drawProbeSamples(room(), probe(), options());
  const FittedCandidates f = fitCandidates(view, s.fit, std::nullopt);
  const std::vector<ProxyPlane> start = startingPlanes(*f.hull, view);
  // The hull's facets on the walls are replaced by the walls' own planes (float hits averaged).
  EXPECT_EQ(std::count_if(start.begin(), start.end(),
                          [](const ProxyPlane& p) { return isRoomWall(p, 1e-5); }),
            6);
  double ms = -1.0;
  const std::vector<ProxyCandidate> steps = simplifyHull(*f.hull, view, s.fit, true, ms);
  EXPECT_GE(ms, 0.0);
  for (const ProxyCandidate& c : steps) {
    const auto& convex = std::get<ConvexProxy>(c.shape);
    EXPECT_EQ(c.origin, CandidateOrigin::Simplified);
    EXPECT_EQ(candidateName(c), "convex_" + std::to_string(convex.planes.size()));
    EXPECT_GE(convex.planes.size(), 4u);
    EXPECT_LT(convex.planes.size(), start.size());
  }
}

ProxyCandidate candidate(CandidateOrigin origin, ProxyShape shape, double p95, double mean,
                         double missRate = 0.0) {
  ProxyCandidate c{origin, std::move(shape), {}, {}, 0.0};
  c.error.p95Deg = p95;
  c.error.meanCostDeg = mean;
  c.error.missRate = missRate;
  c.error.p95WithMissesDeg = missRate > 0.05 ? 180.0 : p95;
  return c;
}

ConvexProxy planes(int count) {
  ConvexProxy c;
  c.planes.resize(static_cast<std::size_t>(count), ProxyPlane{{0, 0, 1}, 1.0});
  return c;
}

TEST(BuildStages, SelectionKeepsTheFewestPlanesWithinToleranceElseTheMostAccurate) {
  ProxyBuildOptions o;
  o.toleranceDeg = 1.0;
  std::vector<ProxyCandidate> c = {candidate(CandidateOrigin::Infinite, InfiniteShape{}, 50, 20),
                                   candidate(CandidateOrigin::Aabb, BoxShape{}, 0.9, 0.3),
                                   candidate(CandidateOrigin::Simplified, planes(5), 0.5, 0.2),
                                   candidate(CandidateOrigin::Simplified, planes(4), 2.0, 0.5)};
  EXPECT_EQ(selectProxy(c, o), 2u);  // 5 planes under the tolerance beat the 6-plane box
  c[2] = candidate(CandidateOrigin::Simplified, planes(5), 0.5, 0.2, 0.5);  // ... unless it misses
  EXPECT_EQ(selectProxy(c, o), 1u);
  o.toleranceDeg = 0.1;  // nothing meets it: the best p95 with misses, sparing planes
  EXPECT_EQ(selectProxy(c, o), 1u);
  // A proxy that misses 1% of rays (10x the allowed rate) but is right elsewhere beats a
  // never-missing cheap_k that is wrong everywhere: the player sees p95, misses included.
  std::vector<ProxyCandidate> real = {
      candidate(CandidateOrigin::CheapK, CheapKShape{}, 60, 20),
      candidate(CandidateOrigin::Aabb, BoxShape{}, 40, 12),
      candidate(CandidateOrigin::Simplified, planes(6), 14, 5, 0.01)};
  EXPECT_EQ(selectProxy(real, o), 2u);
  real[1] = candidate(CandidateOrigin::Aabb, BoxShape{}, 14.2,
                      5);  // within noise of the best: the simpler box
  EXPECT_EQ(selectProxy(real, o), 1u);
  c.insert(c.begin(), candidate(CandidateOrigin::Authored, BoxShape{}, 90, 90));
  EXPECT_EQ(selectProxy(c, o), 0u);  // the artist's, unless asked to regenerate
  o.regenerate = true;
  EXPECT_EQ(selectProxy(c, o), 2u);
}

// Layout writes its kept proxies into a scene file, which holds no cheap_k (DESIGN.md's
// contract): the best a scene can hold is kept instead, or `build` on that scene would measure
// another proxy than the layout did.
TEST(BuildStages, ALayoutsShapesAreOnesASceneHoldsButCheapK) {
  ProxyBuildOptions o;
  o.toleranceDeg = 1.0;
  std::vector<ProxyCandidate> c = {candidate(CandidateOrigin::Infinite, InfiniteShape{}, 50, 20),
                                   candidate(CandidateOrigin::CheapK, CheapKShape{}, 0.5, 0.2),
                                   candidate(CandidateOrigin::Aabb, BoxShape{}, 0.9, 0.3)};
  EXPECT_EQ(selectProxy(c, o), 1u);
  o.layoutShapesOnly = true;
  EXPECT_EQ(selectProxy(c, o), 2u);
  o.toleranceDeg = 0.1;  // none meets it: the most accurate a scene can hold
  EXPECT_EQ(selectProxy(c, o), 2u);
}

// The room's walls, with its -x wall swapped for a plane 0.14 degrees off its +y wall: the
// two meet 2 km away, in a wedge so thin that the nearest of PlaneReach's 2048 directions
// (about 4.5 degrees apart) leaves it 65 m out.
ConvexProxy wedge() {
  const glm::dvec3 slant = glm::normalize(glm::dvec3(-5, -2000, 0));  // through (6,-2), (-1994,3)
  ConvexProxy wedge;
  wedge.planes = {{{1, 0, 0}, kHi.x},
                  {{0, 1, 0}, kHi.y},
                  {{0, 0, 1}, kHi.z},
                  {{0, 0, -1}, -kLo.z},
                  {slant, glm::dot(slant, glm::dvec3(kHi.x, kLo.y, 0))}};
  return wedge;
}

TEST(BuildStages, AStepWhoseCornersReachFarIsDroppedWithTheStepsAfterIt) {
  ProxyBuildOptions o;
  o.toleranceDeg = 1.0;
  ConvexProxy room = convexFromBox({0.5 * (kLo + kHi), 0.5 * (kHi - kLo), {1, 0, 0, 0}});
  room.verticesMeters.clear();
  room.triangles.clear();
  ProbeProxyBuild b;
  b.candidates = {candidate(CandidateOrigin::Aabb, BoxShape{}, 1.5, 0.3),
                  candidate(CandidateOrigin::Simplified, room, 0.8, 0.2),
                  candidate(CandidateOrigin::Simplified, wedge(), 0.5, 0.2),
                  candidate(CandidateOrigin::Simplified, planes(4), 5.0, 2.0)};
  const double farthestSeen = 40.0;  // e.g. down a corridor from the room
  ASSERT_LE(farthestExitMeters(wedge().planes, kCapture),
            kMaxReachOverFarthestSeen * farthestSeen);  // the sampled reach lets it pass
  const ProbeProxyBuild asSelected = [&] {
    ProbeProxyBuild s = b;
    s.kept = selectProxy(s.candidates, o);
    return s;
  }();
  ASSERT_EQ(asSelected.kept, 2u);  // the wedge: the fewest planes within tolerance

  ProbeProxyBuild near = asSelected;
  dropStepsReachingFar(near, kCapture, farthestSeen, o);
  ASSERT_EQ(near.candidates.size(), 2u);  // the wedge and the step after it, which holds it
  EXPECT_EQ(near.kept, 1u);               // the room's six planes, the next within tolerance
  EXPECT_EQ(std::get<ConvexProxy>(near.candidates[1].shape).verticesMeters.size(), 8u);

  ProbeProxyBuild far = asSelected;  // a probe that sees a kilometre may keep it
  dropStepsReachingFar(far, kCapture, 1000.0, o);
  EXPECT_EQ(far.candidates.size(), 4u);
  EXPECT_EQ(far.kept, 2u);
  EXPECT_EQ(std::get<ConvexProxy>(far.candidates[2].shape).verticesMeters.size(), 6u);
}

TEST(BuildStages, FinishingTheKeptConvexGivesItCornersAndChecksTheCapture) {
  ProbeProxyBuild b;
  ConvexProxy box = convexFromBox({0.5 * (kLo + kHi), 0.5 * (kHi - kLo), {1, 0, 0, 0}});
  box.verticesMeters.clear();
  box.triangles.clear();
  b.candidates.push_back({CandidateOrigin::Simplified, box, {}, {}, 0.0});
  finishKeptProxy(b, kCapture);
  const auto& kept = std::get<ConvexProxy>(b.candidates[0].shape);
  EXPECT_EQ(kept.verticesMeters.size(), 8u);
  EXPECT_EQ(kept.triangles.size(), 12u);
  EXPECT_TRUE(b.findings.empty());
  finishKeptProxy(b, kHi + glm::dvec3(1.0));
  EXPECT_EQ(b.findings, std::vector<std::string>{"the capture point is not inside the kept proxy"});
  b.kept = 3;  // past the candidates: an invariant, not a crash
  EXPECT_THROW(finishKeptProxy(b, kCapture), InvariantError);
}

}  // namespace
}  // namespace probeproxy

namespace probeproxy {
namespace {

// A probe's influence reaches through a wall into the next room; the proxy is fitted
// on the floor a player can walk to from its capture point, not on the room behind the wall.
TEST(BuildStages, FitSamplesStayOnTheFloorConnectedToTheCapturePoint) {
  LevelMesh level = boxRoom({0, 0, 0}, {5, 4, 3}, "near");
  appendLevelMesh(level, boxRoom({5.2f, 0, 0}, {10, 4, 3}, "behind_the_wall"));
  const LevelRayCaster caster(level);
  const Probe p = probeAt({2.5, 2, 1.6}, {0, 0, 0}, {10, 4, 3});
  ReflectionSampleOptions o;
  o.targetSamples = 512;
  o.connectedFloorOnly = true;
  const std::vector<glm::dvec3> cameras = reflectionCameras(caster, p, o);
  ASSERT_FALSE(cameras.empty());
  for (const glm::dvec3& c : cameras) EXPECT_LT(c.x, 5.0);
  for (const ReflectionSample& s : buildReflectionSamples(caster, p, SampleSet::MirrorFloor, o))
    EXPECT_LT(s.xMeters.x, 5.0);
  o.connectedFloorOnly = false;  // what the runtime shades: the other room too
  const std::vector<glm::dvec3> all = reflectionCameras(caster, p, o);
  EXPECT_TRUE(std::any_of(all.begin(), all.end(), [](glm::dvec3 c) { return c.x > 5.2; }));
  // The build fits on the first and reports on the second.
  const ProbeSamples samples = drawProbeSamples(caster, p, options());
  for (const ReflectionSample& s : samples.fit) EXPECT_LT(s.eyeMeters.x, 5.0);
  EXPECT_TRUE(std::any_of(samples.floor.begin(), samples.floor.end(),
                          [](const ReflectionSample& s) { return s.eyeMeters.x > 5.2; }));
}

}  // namespace
}  // namespace probeproxy
