#include "core/cube/cube_face.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <random>

namespace probeproxy {
namespace {

TEST(CubeFace, AxesAreRightHandedPhotographs) {
  // right = forward x up makes each face an un-mirrored camera image (Blender renders match).
  for (const CubeFaceAxes& a : cubeFaceAxes()) {
    EXPECT_EQ(glm::cross(a.forward, a.up), a.right);
    EXPECT_EQ(glm::dot(a.forward, a.up), 0.0f);
  }
}

TEST(CubeFace, SideFacesHaveZUpAndCeilingFaceHasYUp) {
  EXPECT_EQ(cubeFaceAxes()[int(CubeFace::px)].up, glm::vec3(0, 0, 1));
  EXPECT_EQ(cubeFaceAxes()[int(CubeFace::ny)].up, glm::vec3(0, 0, 1));
  EXPECT_EQ(cubeFaceAxes()[int(CubeFace::pz)].up, glm::vec3(0, 1, 0));
  EXPECT_EQ(cubeFaceAxes()[int(CubeFace::nz)].up, glm::vec3(0, -1, 0));
  // On px the +Y side of the room shows on the left of the image.
  const glm::vec3 leftEdge = directionFromFaceUv(CubeFace::px, {0.0f, 0.5f});
  EXPECT_GT(leftEdge.y, 0.99f);
}

TEST(CubeFace, FaceCentresLookAlongTheAxes) {
  for (int f = 0; f < kCubeFaceCount; ++f) {
    EXPECT_EQ(directionFromFaceUv(CubeFace(f), {0.5f, 0.5f}), cubeFaceAxes()[f].forward);
  }
}

TEST(CubeFace, DirectionToUvAndBackIsExactToFloatPrecision) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int i = 0; i < 1000; ++i) {
      const glm::vec2 uv(unit(rng), unit(rng));
      const glm::vec3 d = directionFromFaceUv(CubeFace(f), uv) * (0.1f + 10.0f * unit(rng));
      const FaceUv back = faceUvFromDirection(d);
      ASSERT_EQ(back.face, CubeFace(f)) << "uv " << uv.x << "," << uv.y;
      EXPECT_NEAR(back.uv.x, uv.x, 1e-6f);
      EXPECT_NEAR(back.uv.y, uv.y, 1e-6f);
    }
  }
}

TEST(CubeFace, TexelCentresTileTheFace) {
  const int n = 4;
  const FaceUv first = faceUvFromDirection(texelDirection(CubeFace::nz, 0, 0, n));
  EXPECT_EQ(first.face, CubeFace::nz);
  EXPECT_NEAR(first.uv.x, 0.125f, 1e-6f);
  EXPECT_NEAR(first.uv.y, 0.125f, 1e-6f);
  EXPECT_NEAR(glm::length(texelDirection(CubeFace::py, 3, 2, n)), 1.0f, 1e-6f);
}

TEST(CubeFace, ZeroDirectionIsHandled) {
  const FaceUv z = faceUvFromDirection(glm::vec3(0.0f));
  EXPECT_EQ(z.face, CubeFace::px);
  EXPECT_EQ(z.uv, glm::vec2(0.5f));
}

TEST(CubeFace, NamesMatchFilesOfTheSuite) {
  EXPECT_EQ(cubeFaceName(CubeFace::px), "px");
  EXPECT_EQ(cubeFaceName(CubeFace::nz), "nz");
}

}  // namespace
}  // namespace probeproxy
