// Fresnel (Bjorke, GPU Gems ch. 19) and the distance-based roughness (core/shading/).

#include "core/cube/cubemap_sampling.h"
#include "core/shading/distance_roughness.h"
#include "core/shading/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace probeproxy {
namespace {

TEST(FresnelSchlick, NormalIncidenceIsF0) {
  for (float f0 : {0.0f, 0.04f, 0.5f, 0.95f}) {
    EXPECT_FLOAT_EQ(fresnelSchlick(f0, 1.0f), f0);
    EXPECT_FLOAT_EQ(fresnelSchlick(f0, -1.0f), f0);  // the seed's abs(vdn)
  }
}

TEST(FresnelSchlick, GrazingIsOne) {
  for (float f0 : {0.0f, 0.04f, 0.5f}) {
    EXPECT_FLOAT_EQ(fresnelSchlick(f0, 0.0f), 1.0f);
    EXPECT_NEAR(fresnelSchlick(f0, 1e-3f), 1.0f, 5.0f * 1e-3f);
  }
}

TEST(FresnelSchlick, MonotonicTowardsGrazingAndBounded) {
  float previous = fresnelSchlick(0.04f, 1.0f);
  for (int i = 999; i >= 0; --i) {
    const float f = fresnelSchlick(0.04f, static_cast<float>(i) / 1000.0f);
    EXPECT_GE(f, previous) << "cos " << i / 1000.0;
    previous = f;
  }
  EXPECT_FLOAT_EQ(fresnelSchlick(0.04f, 1.0001f), 0.04f);  // slightly denormalized input
}

TEST(FresnelSchlick, MatchesSeed001WithSchlickParameters) {
  // fres = KrMin + (Kr - KrMin) * pow(1 - abs(vdn), FresExp), KrMin = F0, Kr = 1, FresExp = 5.
  for (float vdn : {0.1f, 0.37f, 0.8f}) {
    const float seed = 0.04f + (1.0f - 0.04f) * std::pow(1.0f - vdn, 5.0f);
    EXPECT_NEAR(fresnelSchlick(0.04f, vdn), seed, 1e-6f);
  }
}

TEST(DistanceRoughness, CaptureAtShadingPointLeavesRoughnessUnchanged) {
  const glm::vec3 c(1, 2, 3), p(4, -2, 3);
  for (float r : {0.0f, 0.1f, 0.5f, 1.0f}) EXPECT_FLOAT_EQ(roughnessSeenFromCapture(r, c, p, c), r);
}

TEST(DistanceRoughness, NearTheWallSharpensFarBlurs) {
  // Capture 4 m from the wall; shading points 1 m and 9 m from the hit.
  EXPECT_FLOAT_EQ(roughnessSeenFromCapture(0.4f, 1.0f, 4.0f), 0.2f);
  EXPECT_FLOAT_EQ(roughnessSeenFromCapture(0.4f, 9.0f, 4.0f), 0.6f);
  // The mip follows: sharper below, blurrier above the capture point's own.
  const float own = mipFromRoughness(0.4f, 8);
  EXPECT_LT(mipFromRoughness(roughnessSeenFromCapture(0.4f, 1.0f, 4.0f), 8), own);
  EXPECT_GT(mipFromRoughness(roughnessSeenFromCapture(0.4f, 9.0f, 4.0f), 8), own);
}

TEST(DistanceRoughness, MonotonicInDistanceAndClamped) {
  float previous = 0.0f;
  for (int i = 0; i <= 400; ++i) {
    const float r = roughnessSeenFromCapture(0.5f, 0.05f * static_cast<float>(i), 2.0f);
    EXPECT_GE(r, previous);
    EXPECT_LE(r, 1.0f);
    previous = r;
  }
  EXPECT_FLOAT_EQ(previous, 1.0f);  // 20 m from the hit, seen from 2 m: clamped
  EXPECT_FLOAT_EQ(roughnessSeenFromCapture(1.7f, 1.0f, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(roughnessSeenFromCapture(-0.2f, 1.0f, 1.0f), 0.0f);
}

TEST(DistanceRoughness, DegenerateInputsGiveNoNaN) {
  const glm::vec3 c(1, 2, 3);
  EXPECT_FLOAT_EQ(roughnessSeenFromCapture(0.5f, glm::vec3(0, 0, 0), c, c), 1.0f);  // P = C
  EXPECT_FLOAT_EQ(roughnessSeenFromCapture(0.0f, glm::vec3(0, 0, 0), c, c), 0.0f);
  EXPECT_FLOAT_EQ(roughnessSeenFromCapture(0.0f, 5.0f, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(roughnessSeenFromCapture(0.5f, 0.0f, 0.0f), 1.0f);
  EXPECT_FLOAT_EQ(roughnessSeenFromCapture(0.5f, 1e30f, 1e-30f), 1.0f);
  EXPECT_FLOAT_EQ(roughnessSeenFromCapture(0.5f, 0.0f, 3.0f), 0.0f);  // x on the wall: a mirror
  EXPECT_TRUE(
      std::isnan(roughnessSeenFromCapture(std::numeric_limits<float>::quiet_NaN(), 1.0f, 1.0f)));
}

}  // namespace
}  // namespace probeproxy
