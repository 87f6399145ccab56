#include "core/measures/error_figures.h"
#include "core/parallax/reference_lookup.h"
#include "geometry/builtin/box_room.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/tune/greedy_plane_removal.h"
#include "geometry/tune/one_dimensional_fits.h"
#include "geometry/tune/plane_reach.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

namespace probeproxy {
namespace {

const BoxShape kRoomBox{{1.0, 0.0, 1.5}, {5.0, 3.0, 1.5}, glm::dquat(1, 0, 0, 0)};

Probe roomProbe() {
  Probe probe;
  probe.name = "room";
  probe.captureMeters = {2.0, 0.5, 1.6};
  BoxInfluence influence;
  influence.centerMeters = kRoomBox.centerMeters;
  influence.halfExtentsMeters = influence.innerHalfExtentsMeters = kRoomBox.halfExtentsMeters;
  probe.influence = influence;
  return probe;
}

LevelMesh roomMesh() {
  return boxRoom(glm::vec3(kRoomBox.centerMeters - kRoomBox.halfExtentsMeters),
                 glm::vec3(kRoomBox.centerMeters + kRoomBox.halfExtentsMeters));
}

TEST(ReferenceLookup, BoxExitIsWhereTheRayLeaves) {
  // From the floor at (1, 0, 0) straight up: the ceiling at z = 3.
  const auto t = exitDistance(kRoomBox, {1, 0, 0}, {0, 0, 1});
  ASSERT_TRUE(t.has_value());
  EXPECT_DOUBLE_EQ(*t, 3.0);
  // The same box as six planes gives the same answer on a slanted ray.
  const glm::dvec3 x(-2, 1, 0.5), r = glm::normalize(glm::dvec3(1, 2, 0.3));
  EXPECT_NEAR(*exitDistance(kRoomBox, x, r), *exitDistance(convexFromBox(kRoomBox), x, r), 1e-12);
}

TEST(ReferenceLookup, RotatedBoxAndEllipsoidExits) {
  const BoxShape rotated{{0, 0, 0}, {2, 1, 1}, glm::angleAxis(M_PI / 2, glm::dvec3(0, 0, 1))};
  EXPECT_NEAR(*exitDistance(rotated, {0, 0, 0}, {0, 1, 0}), 2.0, 1e-12);  // long axis now along y
  const SphereShape ellipsoid{{0, 0, 0}, {3, 1, 1}, glm::dquat(1, 0, 0, 0)};
  EXPECT_NEAR(*exitDistance(ellipsoid, {0, 0, 0}, {1, 0, 0}), 3.0, 1e-12);
  EXPECT_NEAR(*exitDistance(ellipsoid, {1, 0, 0}, {-1, 0, 0}), 4.0, 1e-12);
}

TEST(ReferenceLookup, MissesAreFlaggedNeverNaN) {
  EXPECT_FALSE(referenceLookup(kRoomBox, {0, 0, 1}, {20, 0, 1}, {1, 0, 0}));  // x outside
  EXPECT_FALSE(referenceLookup(kRoomBox, {0, 0, 1}, {0, 0, 1}, {0, 0, 0}));   // zero r
  ConvexProxy open = convexFromBox(kRoomBox);
  open.planes.erase(open.planes.begin());  // +x gone: unbounded along +x
  EXPECT_FALSE(referenceLookup(open, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}));
  // Exactly parallel to four planes, on the boundary of a fifth: a finite answer.
  const auto d = referenceLookup(kRoomBox, {1, 0, 1.5}, {1, 0, 0}, {0, 0, -1});
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(*d, glm::dvec3(0, 0, -1.5));
}

TEST(ErrorFigures, NearestRankPercentilesAndRates) {
  std::vector<double> errors;
  for (int i = 1; i <= 100; ++i) errors.push_back(i);
  errors.push_back(std::nan(""));
  const ErrorFigures e = summarizeErrors(errors, 9);
  EXPECT_EQ(e.samples, 110u);
  EXPECT_EQ(e.medianDeg, 50.0);
  EXPECT_EQ(e.p95Deg, 95.0);
  EXPECT_EQ(e.maxDeg, 100.0);
  EXPECT_DOUBLE_EQ(e.missRate, 1.0 / 101.0);
  EXPECT_DOUBLE_EQ(e.occludedRate, 9.0 / 110.0);
  // With the miss at 180 degrees among 101 visible samples, rank ceil(0.95 * 101) = 96.
  EXPECT_EQ(e.p95WithMissesDeg, 96.0);
}

TEST(ErrorFigures, P95WithMissesIsAMissOnceMissesPassFivePercent) {
  std::vector<double> errors(94, 1.0);
  errors.insert(errors.end(), 6, std::nan(""));
  EXPECT_EQ(summarizeErrors(errors, 0).p95WithMissesDeg, 180.0);
  EXPECT_EQ(summarizeErrors(errors, 0).p95Deg, 1.0);  // the hits alone look perfect
  errors.resize(96);                                  // 94 hits, 2 misses: rank 92 is a hit
  EXPECT_EQ(summarizeErrors(errors, 0).p95WithMissesDeg, 1.0);
}

class BoxRoomEvaluation : public ::testing::Test {
 protected:
  LevelRayCaster caster{roomMesh()};
  Probe probe = roomProbe();
};

TEST_F(BoxRoomEvaluation, MirrorFloorSamplesAreOnTheFloorInsideTheVolume) {
  const auto samples = buildReflectionSamples(caster, probe, SampleSet::MirrorFloor);
  ASSERT_EQ(samples.size(), 2048u);
  for (const ReflectionSample& s : samples) {
    ASSERT_NEAR(s.xMeters.z, 0.0, 1e-5);
    ASSERT_EQ(s.normal, glm::dvec3(0, 0, 1));
    ASSERT_GT(s.reflected.z, 0.0);
    ASSERT_FALSE(s.hitsSky);
    ASSERT_FALSE(s.occluded);  // a box room hides nothing from its probe
  }
}

TEST_F(BoxRoomEvaluation, ExactBoxIsExactAndInfiniteIsFarWorse) {
  const auto samples = buildReflectionSamples(caster, probe, SampleSet::MirrorFloor);
  const ErrorFigures exact = evaluateShape(kRoomBox, probe.captureMeters, samples);
  const ErrorFigures infinite = evaluateShape(InfiniteShape{}, probe.captureMeters, samples);
  EXPECT_LT(exact.p95Deg, 0.05);
  EXPECT_EQ(exact.missRate, 0.0);
  EXPECT_GT(infinite.medianDeg, 50 * exact.p95Deg);
  const auto all = buildReflectionSamples(caster, probe, SampleSet::AllSurfaces);
  EXPECT_LT(evaluateShape(kRoomBox, probe.captureMeters, all).p95Deg, 0.05);
}

TEST_F(BoxRoomEvaluation, SamplesAreTheSameForAnyThreadCount) {
  const auto many = buildReflectionSamples(caster, probe, SampleSet::AllSurfaces);
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const auto single = buildReflectionSamples(caster, probe, SampleSet::AllSurfaces);
  ASSERT_EQ(many.size(), single.size());
  EXPECT_EQ(std::memcmp(many.data(), single.data(), many.size() * sizeof(ReflectionSample)), 0);
}

TEST_F(BoxRoomEvaluation, CheapKAndSphereFitsBeatNoCorrection) {
  const auto samples = buildReflectionSamples(caster, probe, SampleSet::MirrorFloor);
  const double infinite = evaluateShape(InfiniteShape{}, probe.captureMeters, samples).medianDeg;
  const CheapKShape k = fitCheapK(probe.captureMeters, samples, 3.0);
  EXPECT_GT(k.kPerMeter, 0.0);
  EXPECT_LT(evaluateShape(k, probe.captureMeters, samples).medianDeg, 0.6 * infinite);
  const SphereShape sphere = fitCaptureSphere(probe.captureMeters, samples, 1.5, 6.5);
  const ErrorFigures s = evaluateShape(sphere, probe.captureMeters, samples);
  EXPECT_LT(s.medianDeg, 0.6 * infinite);
  EXPECT_LE(s.missRate, 0.01);  // misses cost as much as the worst error: the fit avoids them
}

// The simplification's reach check, kept up to date as planes go, must say what a fresh
// farthestExitMeters says, bit for bit, at every step: 40 planes tangent to a rough sphere,
// removed in a fixed random order, every remaining plane tried at every step.
TEST(PlaneReach, MatchesFarthestExitAsPlanesGo) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), radius(2.0, 6.0);
  std::vector<ProxyPlane> planes;
  while (planes.size() < 40) {
    const glm::dvec3 n(unit(rng), unit(rng), unit(rng));
    if (glm::length(n) < 0.1 || glm::length(n) > 1.0) continue;
    planes.push_back({glm::normalize(n), radius(rng)});
  }
  const glm::dvec3 from(0.3, -0.2, 0.1);
  PlaneReach reach(planes, from, 512);
  std::vector<std::size_t> order(planes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<char> kept(planes.size(), 1);
  const auto keptWithout = [&](std::size_t j) {
    std::vector<ProxyPlane> p;
    for (std::size_t i = 0; i < planes.size(); ++i)
      if (kept[i] && i != j) p.push_back(planes[i]);
    return p;
  };
  std::size_t finiteAnswers = 0, infiniteAnswers = 0;
  for (std::size_t step = 0; step + 1 < order.size(); ++step) {
    for (std::size_t j = 0; j < planes.size(); ++j) {
      if (!kept[j]) continue;
      const double want = farthestExitMeters(keptWithout(j), from, 512);
      ASSERT_EQ(reach.farthestWithoutMeters(j), want) << "step " << step << ", plane " << j;
      ++(std::isinf(want) ? infiniteAnswers : finiteAnswers);
    }
    reach.remove(order[step]);
    kept[order[step]] = 0;
  }
  EXPECT_GT(finiteAnswers, 100u);  // both kinds of answer were checked
  EXPECT_GT(infiniteAnswers, 20u);
}

TEST_F(BoxRoomEvaluation, GreedyRemovalDropsPlanesNobodyNeedsFirst) {
  const auto samples = buildReflectionSamples(caster, probe, SampleSet::MirrorFloor);
  // The room's six planes plus four far-away planes that cut nothing.
  std::vector<ProxyPlane> planes = convexFromBox(kRoomBox).planes;
  for (const glm::dvec3 n :
       {glm::dvec3(1, 1, 0), glm::dvec3(-1, 1, 0), glm::dvec3(1, -1, 0), glm::dvec3(-1, -1, 1)}) {
    planes.push_back({glm::normalize(n), 100.0});
  }
  // Bounded: every direction leaves through some plane. The planes here are axis-aligned or
  // diagonal, so their escape directions, if any, include an axis or a diagonal.
  const auto bounded = [](const std::vector<ProxyPlane>& p) {
    for (int x = -1; x <= 1; ++x) {
      for (int y = -1; y <= 1; ++y) {
        for (int z = -1; z <= 1; ++z) {
          const glm::dvec3 v(x, y, z);
          if (v != glm::dvec3(0.0) && std::none_of(p.begin(), p.end(), [&](const ProxyPlane& q) {
                return glm::dot(q.normal, v) > 1e-12;
              })) {
            return false;
          }
        }
      }
    }
    return true;
  };
  const PlaneRemovalRule rule{
      [&](const std::vector<ProxyPlane>& p, std::size_t) { return bounded(p); }, {}};
  const auto steps = greedyPlaneRemoval(planes, probe.captureMeters, samples, 4, rule);
  // The far planes cost nothing and go first; the floor, which no upward reflection reaches,
  // must stay: without it the proxy would be open below.
  ASSERT_GE(steps.size(), 5u);
  EXPECT_NEAR(steps[4].meanCostDeg, steps[0].meanCostDeg, 1e-12);
  ASSERT_EQ(steps[4].planes.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_EQ(steps[4].planes[i].offsetMeters, planes[i].offsetMeters);
  for (const PlaneRemovalStep& step : steps) EXPECT_TRUE(bounded(step.planes));
}

}  // namespace
}  // namespace probeproxy
