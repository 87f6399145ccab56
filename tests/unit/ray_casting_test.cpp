#include "geometry/builtin/box_room.h"
#include "geometry/raycast/capture_depth_cube.h"
#include "geometry/raycast/level_ray_caster.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <random>

namespace probeproxy {
namespace {

struct Room {
  glm::dvec3 lo, hi;
  double size() const { return glm::length(hi - lo); }
};

// The largest difference between the Embree depth cube and the exact distances to the walls.
double largestDepthError(const Room& room, glm::dvec3 capture, int faceSize) {
  const LevelRayCaster caster(boxRoom(glm::vec3(room.lo), glm::vec3(room.hi)));
  const DepthCube cube = captureDepthCube(caster, capture, faceSize);
  double worst = 0.0;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < faceSize; ++row) {
      for (int col = 0; col < faceSize; ++col) {
        // The exact answer is along the float direction the ray really took.
        const glm::dvec3 d(texelDirection(CubeFace(f), col, row, faceSize));
        const double exact = boxRoomDistance(room.lo, room.hi, capture, d);
        worst = std::max(worst, std::abs(double(cube.at(CubeFace(f), col, row)) - exact));
      }
    }
  }
  return worst;
}

TEST(DepthCube, BoxRoomMatchesExactDistances) {
  const Room room{{-4.0, -2.5, 0.0}, {6.0, 3.5, 3.0}};
  const double error = largestDepthError(room, {1.3, -0.7, 1.6}, 64);
  EXPECT_LT(error, 1e-4 * room.size()) << "largest error " << error << " m";
}

TEST(DepthCube, CapturePointNearACornerStillMatches) {
  const Room room{{0.0, 0.0, 0.0}, {10.0, 8.0, 4.0}};
  EXPECT_LT(largestDepthError(room, {0.05, 7.9, 0.02}, 48), 1e-4 * room.size());
}

TEST(DepthCube, TinyClosetMatches) {
  const Room room{{0.0, 0.0, 0.0}, {0.1, 0.8, 2.2}};  // 10 cm wide
  EXPECT_LT(largestDepthError(room, {0.05, 0.4, 1.1}, 32), 1e-4 * room.size());
}

TEST(DepthCube, LevelTenKilometresFromTheOriginMatches) {
  const glm::dvec3 far(10000.0, -10000.0, 250.0);
  const Room room{far + glm::dvec3(-5, -3, 0), far + glm::dvec3(5, 3, 3)};
  EXPECT_LT(largestDepthError(room, far + glm::dvec3(0.5, 0.25, 1.5), 32), 1e-4 * room.size());
}

TEST(DepthCube, OpenSkyIsInfinite) {
  LevelMesh courtyard = boxRoom({-5, -5, 0}, {5, 5, 4});
  courtyard.triangles.resize(10);  // drop the ceiling's two triangles
  const LevelRayCaster caster(courtyard);
  const DepthCube cube = captureDepthCube(caster, {0, 0, 1.5}, 16);
  const int n = cube.faceSize;
  EXPECT_TRUE(std::isinf(cube.at(CubeFace::pz, n / 2, n / 2)));
  const glm::vec3 down = texelDirection(CubeFace::nz, n / 2, n / 2, n);
  EXPECT_NEAR(cube.at(CubeFace::nz, n / 2, n / 2), 1.5 / -down.z, 1e-5);  // the floor
}

TEST(RayCaster, NormalsFollowTheWindingAndHitsNameTheTriangle) {
  const LevelMesh room = boxRoom({0, 0, 0}, {4, 4, 3});
  const LevelRayCaster caster(room);
  const RayHit floor = caster.firstHit({{1, 1, 1}, {0, 0, -1}});
  ASSERT_TRUE(floor.hit());
  EXPECT_FLOAT_EQ(floor.t, 1.0f);
  EXPECT_EQ(floor.geometricNormal, glm::vec3(0, 0, 1));  // box rooms are wound to face inwards
  EXPECT_TRUE(floor.triangle == 8 || floor.triangle == 9);
  const RayHit none = caster.firstHit({{1, 1, 1}, {0, 0, -1}, 0.0f, 0.5f});
  EXPECT_FALSE(none.hit());
  EXPECT_TRUE(std::isinf(none.t));
}

TEST(RayCaster, DegenerateTrianglesAreIgnoredNotFatal) {
  LevelMesh room = boxRoom({0, 0, 0}, {4, 4, 3});
  room.positionsMeters.push_back({2, 2, 0.5f});
  const auto v = static_cast<std::uint32_t>(room.positionsMeters.size() - 1);
  room.triangles.push_back({v, v, v});  // a point
  room.triangles.push_back({0, 1, 1});  // a line
  const LevelRayCaster caster(room);
  EXPECT_FLOAT_EQ(caster.firstHit({{2, 2, 1}, {0, 0, -1}}).t, 1.0f);
}

TEST(RayCaster, NearestTriangleIsExactInEveryDirection) {
  const LevelMesh room = boxRoom({0, 0, 0}, {4, 4, 3});
  const LevelRayCaster caster(room);
  // The nearer of two walls.
  EXPECT_NEAR(caster.nearestTriangle({1.0, 2.0, 1.5}, 10.0).distanceMeters, 1.0, 1e-6);
  EXPECT_NEAR(caster.nearestTriangle({0.3, 2.0, 0.4}, 10.0).distanceMeters, 0.3, 1e-6);
  // A point in a wall's own plane is on it, though every ray along the plane misses the wall.
  const SurfacePoint inPlane = caster.nearestTriangle({0.0, 2.0, 1.5}, 10.0);
  EXPECT_NEAR(inPlane.distanceMeters, 0.0, 1e-6);
  EXPECT_LT(inPlane.triangle, room.triangles.size());
  // Outside the room, past a corner: the corner's distance.
  EXPECT_NEAR(caster.nearestTriangle({-1.0, -1.0, -1.0}, 10.0).distanceMeters, std::sqrt(3.0),
              1e-6);
  // Nothing within the radius.
  const SurfacePoint none = caster.nearestTriangle({2.0, 2.0, 1.5}, 0.5);
  EXPECT_EQ(none.triangle, kNoTriangle);
  EXPECT_TRUE(std::isinf(none.distanceMeters));
  // Degenerate triangles (a point, a line) are measured as their nearest corner, not fatal.
  LevelMesh withDegenerate = room;
  withDegenerate.positionsMeters.push_back({2, 2, 1.0f});
  const auto v = static_cast<std::uint32_t>(withDegenerate.positionsMeters.size() - 1);
  withDegenerate.triangles.push_back({v, v, v});
  const LevelRayCaster degenerate(withDegenerate);
  const SurfacePoint point = degenerate.nearestTriangle({2.0, 2.0, 1.25}, 10.0);
  EXPECT_NEAR(point.distanceMeters, 0.25, 1e-6);
  EXPECT_EQ(point.triangle, withDegenerate.triangles.size() - 1);
}

std::vector<Ray> randomRays(int count) {
  std::mt19937 rng(42);
  std::normal_distribution<float> gauss;
  std::uniform_real_distribution<float> inside(0.2f, 2.8f);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    rays.push_back({{inside(rng), inside(rng), inside(rng)},
                    glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)))});
  }
  return rays;
}

bool sameBytes(const std::vector<RayHit>& a, const std::vector<RayHit>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(RayHit)) == 0;
}

TEST(RayCaster, BatchedEqualsOneByOneWhateverTheThreadCount) {
  const LevelRayCaster caster(boxRoom({0, 0, 0}, {3, 3, 3}));
  const std::vector<Ray> rays = randomRays(5000);
  std::vector<RayHit> oneByOne(rays.size()), allThreads(rays.size()), oneThread(rays.size());
  caster.firstHitsOneByOne(rays, oneByOne);
  caster.firstHits(rays, allThreads);
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    caster.firstHits(rays, oneThread);
  }
  EXPECT_TRUE(sameBytes(allThreads, oneThread));
  for (std::size_t i = 0; i < rays.size(); ++i) {
    ASSERT_TRUE(oneByOne[i].hit());
    EXPECT_NEAR(allThreads[i].t, oneByOne[i].t, 1e-5f * oneByOne[i].t);
  }
}

TEST(RayCaster, BatchSizeMismatchIsRefused) {
  const LevelRayCaster caster(boxRoom({0, 0, 0}, {1, 1, 1}));
  const std::vector<Ray> rays(3);
  std::vector<RayHit> hits(2);
  EXPECT_THROW(caster.firstHits(rays, hits), std::invalid_argument);
}

}  // namespace
}  // namespace probeproxy
