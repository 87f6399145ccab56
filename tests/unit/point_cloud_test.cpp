// Hodgman's point-cloud splat: the octahedral map's round trip, and splats of known points
// landing in the right direction.

#include "core/pointcloud/octahedral.h"
#include "core/pointcloud/point_cloud_splat.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <random>

namespace probeproxy {
namespace {

double angleDeg(glm::vec3 a, glm::vec3 b) {
  const double c = glm::dot(glm::normalize(glm::dvec3(a)), glm::normalize(glm::dvec3(b)));
  const double s =
      glm::length(glm::cross(glm::normalize(glm::dvec3(a)), glm::normalize(glm::dvec3(b))));
  return glm::degrees(std::atan2(s, c));
}

TEST(Octahedral, RoundTripIsExactToFloatRounding) {
  std::mt19937 rng(7);
  std::normal_distribution<float> g;
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 d(g(rng), g(rng), g(rng));
    const glm::vec2 uv = octahedralUvFromDirection(d);
    ASSERT_GE(uv.x, 0.0f);
    ASSERT_LE(uv.x, 1.0f);
    ASSERT_GE(uv.y, 0.0f);
    ASSERT_LE(uv.y, 1.0f);
    worst = std::max(worst, angleDeg(directionFromOctahedralUv(uv), d));
  }
  EXPECT_LT(worst, 1e-3);
  // The axes land where the convention says.
  EXPECT_EQ(octahedralUvFromDirection({0, 0, 1}), glm::vec2(0.5f, 0.5f));
  EXPECT_EQ(octahedralUvFromDirection({1, 0, 0}), glm::vec2(1.0f, 0.5f));
  EXPECT_EQ(octahedralUvFromDirection({0, 1, 0}), glm::vec2(0.5f, 0.0f));
}

TEST(Octahedral, EdgeWrapLandsOnTheTexelAcrossTheFold) {
  const int n = 16;
  const double texelDeg = glm::degrees(std::sqrt(4.0 * 3.14159265 / (n * n)));
  for (int row = 0; row < n; ++row) {
    const float v = (row + 0.5f) / n;
    // The square's left edge folds onto itself: (0, v) and (0, 1 - v) are one direction.
    EXPECT_LT(
        angleDeg(directionFromOctahedralUv({0.0f, v}), directionFromOctahedralUv({0.0f, 1.0f - v})),
        1e-3);
    // So texel -1 of a row is texel 0 of the mirrored row: a neighbour of texel 0 on the sphere.
    int c = -1, r = row;
    wrapOctahedralTexel(c, r, n);
    EXPECT_EQ(c, 0);
    EXPECT_EQ(r, n - 1 - row);
    const glm::vec3 inside = directionFromOctahedralUv({0.5f / n, v});
    const glm::vec3 across = directionFromOctahedralUv({(c + 0.5f) / n, (r + 0.5f) / n});
    EXPECT_LT(angleDeg(inside, across), 1.5 * texelDeg) << row;
  }
}

// On an analytic box room's walls: points at known directions from the shading point, each
// splatted map sampled back along that direction gives that point's colour, within a texel.
TEST(PointCloudSplat, KnownPointsComeBackInTheirDirection) {
  const int n = 64;
  const float texelDeg = glm::degrees(std::sqrt(4.0f * 3.14159265f / (n * n)));
  PointCloud cloud;
  cloud.originMeters = {10.0, -3.0, 1.0};
  std::mt19937 rng(3);
  std::normal_distribution<float> g;
  std::vector<glm::vec3> dirs;
  for (int i = 0; i < 40; ++i) {
    glm::vec3 d = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
    // Keep them apart so each owns its texels.
    bool apart = true;
    for (const glm::vec3& e : dirs) apart = apart && angleDeg(d, e) > 6.0 * texelDeg;
    if (!apart) continue;
    dirs.push_back(d);
    RadiancePoint p;
    p.fromOriginMeters = 2.0f * d;  // 2 m away, facing the centre
    p.normal = -d;
    p.rgb = glm::vec3(static_cast<float>(dirs.size()), 0.0f, 1.0f);
    p.radiusMeters = 0.01f;  // much less than a texel: one texel each
    cloud.points.push_back(p);
  }
  ASSERT_GT(dirs.size(), 20u);
  PointCloudOptions options;
  options.mapSize = n;
  options.blurRadiusTexels = 0;
  const OctahedralMap map = splatPointCloud(cloud, cloud.originMeters, options);
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    // The texel holding the point: the map's direction there is within a texel of the point's.
    const glm::vec2 uv = octahedralUvFromDirection(dirs[i]) * static_cast<float>(n);
    const int col = static_cast<int>(uv.x), row = static_cast<int>(uv.y);
    const glm::vec4 t = map.texels[static_cast<std::size_t>(row) * n + col];
    EXPECT_EQ(t.x, static_cast<float>(i + 1));
    EXPECT_GT(t.w, 0.0f);
    const glm::vec3 centre = directionFromOctahedralUv({(col + 0.5f) / n, (row + 0.5f) / n});
    EXPECT_LT(angleDeg(centre, dirs[i]), 1.5 * texelDeg) << i;
    // Sampled along its own direction: its own colour (the only data nearby).
    const std::optional<glm::vec3> seen = sampleOctahedralMap(map, dirs[i]);
    ASSERT_TRUE(seen.has_value());
    EXPECT_FLOAT_EQ(seen->x, static_cast<float>(i + 1));
  }
  // Far from every point: nothing there, a miss.
  int misses = 0;
  for (int i = 0; i < 100; ++i) {
    const glm::vec3 d = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
    bool far = true;
    for (const glm::vec3& e : dirs) far = far && angleDeg(d, e) > 3.0 * texelDeg;
    if (!far) continue;
    EXPECT_FALSE(sampleOctahedralMap(map, d).has_value());
    ++misses;
  }
  EXPECT_GT(misses, 0);
}

TEST(PointCloudSplat, NearerPointWinsAndTheBlurFillsHoles) {
  PointCloud cloud;
  RadiancePoint far, near;
  far.fromOriginMeters = {0, 0, 4};
  far.normal = {0, 0, -1};
  far.rgb = {1, 0, 0};
  far.radiusMeters = 0.01f;
  near = far;
  near.fromOriginMeters = {0, 0, 1};
  near.rgb = {0, 1, 0};
  cloud.points = {far, near};
  PointCloudOptions options;
  options.blurRadiusTexels = 0;
  EXPECT_EQ(*pointCloudRadiance(cloud, glm::dvec3(0.0), {0, 0, 1}, options), glm::vec3(0, 1, 0));
  // One texel away from the splat: empty without the blur, the splat's colour with it.
  const glm::vec3 beside = directionFromOctahedralUv({0.5f + 1.5f / 64, 0.5f});
  EXPECT_FALSE(pointCloudRadiance(cloud, glm::dvec3(0.0), beside, options).has_value());
  options.blurRadiusTexels = 2;
  const OctahedralMap map = splatPointCloud(cloud, glm::dvec3(0.0), options);
  const std::optional<glm::vec3> filled = sampleOctahedralMap(map, beside);
  ASSERT_TRUE(filled.has_value());
  EXPECT_EQ(*filled, glm::vec3(0, 1, 0));
}

}  // namespace
}  // namespace probeproxy
