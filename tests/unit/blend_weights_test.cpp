// Influence factors and blend weights (core/blend/): the seed's rules one by one, against the
// seed's own pseudo-code where it applies, and continuity through the cut to N probes.

#include "core/blend/blend_weights.h"
#include "core/blend/enlighten_distance.h"
#include "core/blend/influence_factor.h"
#include "core/blend/weight_continuity.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <vector>

namespace probeproxy {
namespace {

BoxInfluence box(glm::dvec3 center, glm::dvec3 half, glm::dvec3 inner,
                 glm::dquat worldFromBox = {1, 0, 0, 0}) {
  return {center, half, worldFromBox, inner};
}

SphereInfluence sphere(glm::dvec3 center, double radius, double inner) {
  return {center, radius, inner};
}

// Dense weights, one per volume.
std::vector<double> dense(const std::vector<InfluenceVolume>& volumes, glm::dvec3 p,
                          BlendOptions options = {}) {
  std::vector<double> w(volumes.size(), 0.0);
  for (const ProbeWeight& pw : blendWeights(volumes, p, options)) w[pw.probe] = pw.weight;
  return w;
}

double sum(const std::vector<double>& w) {
  double s = 0.0;
  for (double x : w) s += x;
  return s;
}

// Lagarde & Zanuttini's pseudo-code, literally (without its inner-range early-out), on influence
// weights that are the normalized distances of the selected primitives.
std::vector<double> seedBlendFactors(const std::vector<double>& ndf) {
  double sumIW = 0.0, invSumIW = 0.0, sumBlendFactor = 0.0;
  for (double w : ndf) {
    sumIW += w;
    invSumIW += 1.0 - w;
  }
  std::vector<double> blend(ndf.size());
  for (std::size_t i = 0; i < ndf.size(); ++i) {
    blend[i] = (1.0 - ndf[i] / sumIW) / static_cast<double>(ndf.size() - 1);
    blend[i] *= (1.0 - ndf[i]) / invSumIW;
    sumBlendFactor += blend[i];
  }
  for (double& b : blend) b /= sumBlendFactor;
  return blend;
}

TEST(InfluenceFactor, SphereIsOneInsideTheInnerRadiusAndFallsLinearlyToZeroAtTheOuter) {
  const InfluenceVolume s = sphere({1, 2, 3}, 4.0, 2.0);
  EXPECT_EQ(influenceFactor(s, {1, 2, 3}), 1.0);
  EXPECT_EQ(influenceFactor(s, {1, 2, 5}), 1.0);           // on the inner sphere
  EXPECT_NEAR(influenceFactor(s, {1, 5, 3}), 0.5, 1e-15);  // halfway through the band
  EXPECT_EQ(influenceFactor(s, {5, 2, 3}), 0.0);           // on the outer sphere
  EXPECT_EQ(influenceFactor(s, {9, 2, 3}), 0.0);
  EXPECT_FALSE(coversPoint(s, {5, 2, 3}));
  EXPECT_TRUE(coversPoint(s, {4.999, 2, 3}));
}

TEST(InfluenceFactor, RotatedBoxIsMeasuredInItsOwnFrameAndItsAxesFactorsMultiply) {
  // Box x axis along world y: half-extents (4, 1, 1), inner (2, 1, 1).
  const glm::dquat worldFromBox = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 0, 1));
  const InfluenceVolume b = box({10, 0, 0}, {4, 1, 1}, {2, 1, 1}, worldFromBox);
  EXPECT_NEAR(normalizedDistance(b, {10, 3, 0}), 0.5, 1e-12);  // box x = 3
  EXPECT_NEAR(normalizedDistance(b, {10, -3, 0}), 0.5, 1e-12);
  EXPECT_EQ(normalizedDistance(b, {12, 0, 0}), 1.0);  // box y = -2: outside though world x < 14
  EXPECT_NEAR(normalizedDistance(b, {10, 1.5, 0.99}), 0.0, 1e-12);  // inner range
  const InfluenceVolume banded = box({0, 0, 0}, {4, 2, 2}, {2, 1, 1}, worldFromBox);
  EXPECT_NEAR(influenceFactor(banded, {-1.5, 3, 0}), 0.5 * 0.5, 1e-12);  // box (3, 1.5, 0)
  // An axis with inner == outer has no band: the factor stays up to the side, 0 on it.
  EXPECT_NEAR(influenceFactor(b, {10.999, 3, 0}), 0.5, 1e-12);
  EXPECT_EQ(influenceFactor(b, {11.001, 3, 0}), 0.0);
}

TEST(InfluenceFactor, IsContinuousThroughTheBand) {
  const InfluenceVolume b = box({0, 0, 0}, {3, 2, 1}, {1, 1.5, 0.5},
                                glm::angleAxis(0.3, glm::normalize(glm::dvec3(1, 2, 3))));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-4, 4);
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 p(u(rng), u(rng), u(rng));
    const glm::dvec3 q = p + glm::dvec3(1e-6, -1e-6, 1e-6);
    // Lipschitz: |grad| <= sqrt(sum over axes of 1 / band^2) = sqrt(1/4 + 4 + 4) per metre.
    EXPECT_LE(std::abs(influenceFactor(b, p) - influenceFactor(b, q)),
              glm::length(q - p) * 2.88 + 1e-12);
  }
}

TEST(EnlightenDistance, IsTheSquaredDistanceToTheBoxInItsFrame) {
  const glm::dquat worldFromBox = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 0, 1));
  const InfluenceVolume b = box({0, 0, 0}, {4, 1, 1}, {4, 1, 1}, worldFromBox);
  EXPECT_EQ(enlightenDistanceSq(b, {0.5, 3.9, 0}), 0.0);
  EXPECT_NEAR(enlightenDistanceSq(b, {3, 0, 0}), 4.0, 1e-12);  // 2 m past the box's y side
  EXPECT_NEAR(enlightenDistanceSq(b, {2, 6, 2}), 1 + 4 + 1, 1e-12);
}

TEST(BlendWeights, TwoOverlappingVolumesGiveExactlyTheSeedsPseudoCode) {
  const std::vector<InfluenceVolume> v = {box({0, 0, 0}, {4, 2, 2}, {2, 1, 1}),
                                          sphere({4, 0.5, 0}, 3.0, 1.0)};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(1.0, 3.5), yz(-0.8, 0.8);
  int compared = 0;
  for (int i = 0; i < 500; ++i) {
    const glm::dvec3 p(x(rng), yz(rng), yz(rng));
    const double a0 = normalizedDistance(v[0], p), a1 = normalizedDistance(v[1], p);
    if (a0 <= 0 || a0 >= 1 || a1 <= 0 || a1 >= 1) continue;
    const std::vector<double> seed = seedBlendFactors({a0, a1});
    const std::vector<double> ours = dense(v, p);
    EXPECT_NEAR(ours[0], seed[0], 1e-12);
    EXPECT_NEAR(ours[1], seed[1], 1e-12);
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

TEST(BlendWeights, ZeroAtTheOuterBoundaryWhateverOverlaps) {
  const std::vector<InfluenceVolume> v = {box({0, 0, 0}, {4, 2, 2}, {1, 1, 1}),
                                          box({5, 0, 0}, {4, 2, 2}, {1, 1, 1}),
                                          sphere({2.5, 0, 0}, 3.0, 0.5)};
  // x = 4 - eps is just inside volume 0's +x side; 1 and 2 cover it too.
  for (double eps : {1e-3, 1e-6, 1e-9}) {
    const std::vector<double> w = dense(v, {4 - eps, 0.3, 0.2});
    EXPECT_LT(w[0], 10 * eps) << eps;
    EXPECT_NEAR(sum(w), 1.0, 1e-12);
  }
  EXPECT_EQ(dense(v, {4, 0.3, 0.2})[0], 0.0);
}

TEST(BlendWeights, FullInsideAnInnerRangeWhateverOverlapsAndContinuousAtItsEdge) {
  // Volume 2's inner sphere (radius 0.5 at x = 2.5) lies in the outer ranges of 0 and 1.
  const std::vector<InfluenceVolume> v = {box({0, 0, 0}, {4, 2, 2}, {1, 1, 1}),
                                          box({5, 0, 0}, {4, 2, 2}, {1, 1, 1}),
                                          sphere({2.5, 0, 0}, 3.0, 0.5)};
  EXPECT_EQ(dense(v, {2.5, 0, 0}), (std::vector<double>{0, 0, 1}));
  EXPECT_EQ(dense(v, {2.5, 0.5, 0}), (std::vector<double>{0, 0, 1}));
  // Just outside the inner range the weight is still ~1: no early-out pop. (The seed's
  // pseudo-code gives 3 primitives at a = 0 only 2/3 there; its early-out then jumps to 1.)
  EXPECT_GT(dense(v, {2.5, 0.5 + 1e-6, 0})[2], 1 - 1e-5);
  const double a0 = normalizedDistance(v[0], {2.5, 0.5, 0});
  const double a1 = normalizedDistance(v[1], {2.5, 0.5, 0});
  EXPECT_NEAR(seedBlendFactors({a0, a1, 1e-9})[2], 2.0 / 3.0, 0.05);
}

TEST(BlendWeights, ASmallerVolumeInsideALargerOneDominates) {
  // A hall with no inner range but its centre, and a small sphere inside it off centre.
  const std::vector<InfluenceVolume> v = {box({0, 0, 0}, {10, 10, 3}, {0, 0, 0}),
                                          sphere({5, 5, 0}, 2.0, 0.5)};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec3 p = glm::dvec3(5, 5, 0) + glm::dvec3(u(rng), u(rng), u(rng) * 0.5);
    const double aSmall = normalizedDistance(v[1], p);
    if (aSmall >= 1) continue;
    const std::vector<double> w = dense(v, p);
    if (aSmall < normalizedDistance(v[0], p)) {
      EXPECT_GT(w[1], 0.5);
    }
    if (aSmall == 0) {
      EXPECT_EQ(w[1], 1.0);
    }
  }
  // Inner ranges that overlap (the seed forbids it): the smaller volume takes 100%.
  const std::vector<InfluenceVolume> nested = {box({0, 0, 0}, {10, 10, 3}, {9, 9, 2}),
                                               sphere({5, 5, 0}, 2.0, 1.0)};
  EXPECT_EQ(dense(nested, {5, 5, 0}), (std::vector<double>{0, 1}));
}

TEST(BlendWeights, SumToOneWhereCoveredAndEmptyOutsideEveryVolume) {
  const std::vector<InfluenceVolume> v = {box({0, 0, 0}, {4, 2, 2}, {1, 1, 1}),
                                          box({5, 0, 0}, {4, 2, 2}, {1, 1, 1}),
                                          sphere({2.5, 0, 0}, 3.0, 0.5)};
  for (BlendScheme scheme : {BlendScheme::Lagarde, BlendScheme::Enlighten}) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> x(-5, 10), yz(-3, 3);
    for (int i = 0; i < 2000; ++i) {
      const glm::dvec3 p(x(rng), yz(rng), yz(rng));
      const std::vector<ProbeWeight> w = blendWeights(v, p, {scheme, 4});
      bool covered = false;
      for (const InfluenceVolume& vol : v) covered = covered || coversPoint(vol, p);
      ASSERT_EQ(w.empty(), !covered);
      double s = 0.0;
      for (const ProbeWeight& pw : w) {
        EXPECT_GT(pw.weight, 0.0);
        s += pw.weight;
      }
      if (covered) {
        EXPECT_NEAR(s, 1.0, 1e-12);
      }
    }
  }
  EXPECT_TRUE(blendWeights(v, {20, 0, 0}, {BlendScheme::Enlighten, 4}).empty());
}

TEST(BlendWeights, EnlightenWeighsOneOverEpsilonPlusDistanceSquared) {
  const std::vector<InfluenceVolume> v = {box({0, 0, 0}, {1, 1, 1}, {1, 1, 1}),
                                          box({5, 0, 0}, {1, 1, 1}, {1, 1, 1}),
                                          sphere({0, 0, 0}, 20.0, 1.0)};
  // x = 2: 1 m from box 0, 2 m from box 1, inside the sphere's bounding cube.
  const std::vector<double> w = dense(v, {2, 0, 0}, {BlendScheme::Enlighten, 4});
  const double w0 = 1 / (kEnlightenEpsilon + 1), w1 = 1 / (kEnlightenEpsilon + 4),
               w2 = 1 / kEnlightenEpsilon;
  EXPECT_NEAR(w[0], w0 / (w0 + w1 + w2), 1e-15);
  EXPECT_NEAR(w[1], w1 / (w0 + w1 + w2), 1e-15);
  EXPECT_NEAR(w[2], w2 / (w0 + w1 + w2), 1e-12);
}

TEST(BlendWeights, KeepsTheNMostInfluentialAndFadesTheNthWithoutAJump) {
  // Six spheres along x overlapping a shared stretch; walk along it with N = 2.
  std::vector<InfluenceVolume> v;
  for (int i = 0; i < 6; ++i) v.push_back(sphere({i * 0.7, 0, 0}, 5.0, 0.2));
  for (BlendScheme scheme : {BlendScheme::Lagarde, BlendScheme::Enlighten}) {
    const BlendOptions options{scheme, 2};
    std::vector<double> previous = dense(v, {0.3, 0.5, 0}, options);
    double largest = 0.0;
    for (double x = 0.3; x <= 3.2; x += 1e-4) {
      const glm::dvec3 p(x, 0.5, 0);
      const std::vector<ProbeWeight> w = blendWeights(v, p, options);
      EXPECT_LE(w.size(), 2u);
      const std::vector<double> d = dense(v, p, options);
      for (std::size_t i = 0; i < v.size(); ++i) {
        largest = std::max(largest, std::abs(d[i] - previous[i]));
      }
      previous = d;
    }
    // Lagarde: a changes by <= 1e-4 / 4.8 m per step; the fade is 0.1 wide in a.
    EXPECT_LT(largest, 0.01) << blendSchemeName(scheme);
  }
}

TEST(BlendWeights, TiesAreBrokenDeterministically) {
  // Two identical volumes share equally; two identical inner ranges go to the lower index.
  const std::vector<InfluenceVolume> twins = {box({0, 0, 0}, {2, 2, 2}, {1, 1, 1}),
                                              box({0, 0, 0}, {2, 2, 2}, {1, 1, 1})};
  EXPECT_EQ(dense(twins, {1.5, 0, 0}), (std::vector<double>{0.5, 0.5}));
  EXPECT_EQ(dense(twins, {0, 0, 0}), (std::vector<double>{1, 0}));
  // N = 1 with two tied candidates: the fade would zero both, so the lower index stays.
  EXPECT_EQ(dense(twins, {1.5, 0, 0}, {BlendScheme::Lagarde, 1}), (std::vector<double>{1, 0}));
  EXPECT_THROW(blendWeights(twins, {0, 0, 0}, {BlendScheme::Lagarde, 0}), std::invalid_argument);
}

TEST(BlendWeights, SchemeNamesRoundTrip) {
  for (BlendScheme s : {BlendScheme::Lagarde, BlendScheme::Enlighten}) {
    EXPECT_EQ(blendSchemeFromName(blendSchemeName(s)), s);
  }
  EXPECT_FALSE(blendSchemeFromName("nearest").has_value());
}

TEST(WeightContinuity, FindsTheJumpWhereAVolumeEndsWithoutABandInsideAnother) {
  // Volume 1 has no band along y (inner == outer) and ends at y = 1 inside volume 0.
  const std::vector<InfluenceVolume> v = {box({0, 0, 0}, {4, 4, 2}, {1, 1, 1}),
                                          box({2, 0, 0}, {2, 1, 2}, {1, 1, 1})};
  const WeightContinuity c = measureWeightContinuity(v, gridOverVolumes(v, 0.0, 0.05));
  EXPECT_GT(c.largestJump, 0.3);
  EXPECT_GE(c.jumpProbe, 0);  // both weights jump, by the same amount
  EXPECT_NEAR(std::abs(c.jumpToMeters.y), 1.0, 0.051);
  EXPECT_LT(c.largestSumError, 1e-12);
  // The seed's corridor: two boxes overlapping along x, sharing their sides, with a band
  // along x only. (Lagarde's weight leaves an inner range with slope (1 - a_other) / a_other
  // per unit of a and nears a volume's edge with slope |grad a| / w_other: nested volumes need
  // wide bands, or the other volume deep enough, to stay under 0.02 per cm.)
  const std::vector<InfluenceVolume> smooth = {box({0, 0, 0}, {4, 1.5, 1.5}, {2.5, 1.5, 1.5}),
                                               box({6, 0, 0}, {4, 1.5, 1.5}, {2.5, 1.5, 1.5})};
  EXPECT_LT(measureWeightContinuity(smooth, gridOverVolumes(smooth, 0.0, 0.01)).largestJump, 0.02);
}

}  // namespace
}  // namespace probeproxy
