// Cross and equirectangular cubemap images (core/cube/cube_cross.h, equirect.h) and the one
// entry that reads any of them (readCubemapImage).

#include "core/cube/cube_cross.h"
#include "core/cube/cubemap_io.h"
#include "core/cube/equirect.h"
#include "core/errors/input_error.h"

#include "analytic_cube.h"
#include "test_files.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

namespace probeproxy {
namespace {

using testing::cubeFromFunction;

Cubemap randomCube(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(-2.0f, 1000.0f);
  return cubeFromFunction(n,
                          [&](glm::vec3) { return glm::vec3(value(rng), value(rng), value(rng)); });
}

Cubemap directionCube(int n) {
  return cubeFromFunction(n, [](glm::vec3 d) { return d; });
}

void expectSameLevel0(const Cubemap& a, const Cubemap& b) {
  ASSERT_EQ(a.faceSize(), b.faceSize());
  for (int f = 0; f < kCubeFaceCount; ++f) {
    EXPECT_EQ(a.levels[0].rgb[f], b.levels[0].rgb[f]) << "face " << cubeFaceName(CubeFace(f));
  }
}

glm::vec3 pixelAt(const RgbImage& image, int x, int y) {
  const std::size_t at = (static_cast<std::size_t>(y) * image.width + x) * 3;
  return {image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]};
}

class CubemapLayouts : public testing::TempFolderTest {};

TEST_F(CubemapLayouts, SixFilesToCrossToSixFilesIsBitExact) {
  const Cubemap original = randomCube(8, 11);
  const std::string six = (folder_ / "probe_{face}.exr").string();
  writeCubemap(original, six);
  const Cubemap fromFiles = readCubemap(six);
  for (auto layout : {CubemapImageLayout::HorizontalCross, CubemapImageLayout::VerticalCross}) {
    const std::filesystem::path cross = folder_ / "cross.exr";
    writeCubemapImage(fromFiles, cross, layout);
    const Cubemap fromCross = readCubemapImage(cross);
    EXPECT_EQ(fromCross.numLevels(), fromFiles.numLevels());
    const std::string again = (folder_ / "again_{face}.exr").string();
    writeCubemap(fromCross, again);
    expectSameLevel0(readCubemap(again), original);
  }
}

TEST_F(CubemapLayouts, EveryFaceLandsInItsCell) {
  // Each cell of the cross holds its face's texel directions (cube_cross.h's table); py is
  // turned 180 degrees in the vertical cross; empty cells are black.
  const int n = 4;
  const Cubemap cube = directionCube(n);
  struct Cell {
    CrossLayout layout;
    CubeFace face;
    int col, row;
    bool turned;
  };
  const Cell cells[] = {
      {CrossLayout::Horizontal, CubeFace::pz, 1, 0, false},
      {CrossLayout::Horizontal, CubeFace::px, 0, 1, false},
      {CrossLayout::Horizontal, CubeFace::ny, 1, 1, false},
      {CrossLayout::Horizontal, CubeFace::nx, 2, 1, false},
      {CrossLayout::Horizontal, CubeFace::py, 3, 1, false},
      {CrossLayout::Horizontal, CubeFace::nz, 1, 2, false},
      {CrossLayout::Vertical, CubeFace::pz, 1, 0, false},
      {CrossLayout::Vertical, CubeFace::px, 0, 1, false},
      {CrossLayout::Vertical, CubeFace::ny, 1, 1, false},
      {CrossLayout::Vertical, CubeFace::nx, 2, 1, false},
      {CrossLayout::Vertical, CubeFace::nz, 1, 2, false},
      {CrossLayout::Vertical, CubeFace::py, 1, 3, true},
  };
  for (const Cell& c : cells) {
    const RgbImage image = crossFromCube(cube, c.layout);
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const int x = c.col * n + (c.turned ? n - 1 - col : col);
        const int y = c.row * n + (c.turned ? n - 1 - row : row);
        EXPECT_EQ(pixelAt(image, x, y), texelDirection(c.face, col, row, n))
            << cubeFaceName(c.face) << " texel " << col << ", " << row;
      }
    }
  }
  EXPECT_EQ(pixelAt(crossFromCube(cube, CrossLayout::Horizontal), 0, 0), glm::vec3(0.0f));
  EXPECT_EQ(pixelAt(crossFromCube(cube, CrossLayout::Vertical), 2 * n, 3 * n), glm::vec3(0.0f));
}

TEST_F(CubemapLayouts, CrossIsContinuousAcrossEveryInnerEdge) {
  // The cube unfolded from inside: two neighbouring pixels of non-empty cells look in
  // directions at most about one texel apart, across cell edges too (a swapped or turned
  // face would jump by up to 180 degrees).
  const int n = 16;
  const Cubemap cube = directionCube(n);
  const float texelRadians = 2.0f * std::atan(1.0f / n);  // widest texel, at a face centre
  for (auto layout : {CrossLayout::Horizontal, CrossLayout::Vertical}) {
    const RgbImage image = crossFromCube(cube, layout);
    int edgesChecked = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const glm::vec3 d = pixelAt(image, x, y);
        if (d == glm::vec3(0.0f)) continue;
        for (const glm::ivec2 step : {glm::ivec2(1, 0), glm::ivec2(0, 1)}) {
          if (x + step.x >= image.width || y + step.y >= image.height) continue;
          const glm::vec3 e = pixelAt(image, x + step.x, y + step.y);
          if (e == glm::vec3(0.0f)) continue;
          EXPECT_LT(std::acos(std::min(1.0f, glm::dot(d, e))), 1.01f * texelRadians)
              << "pixels (" << x << ", " << y << ") and the next";
          if ((x + step.x) % n == 0 && step.x == 1) ++edgesChecked;
          if ((y + step.y) % n == 0 && step.y == 1) ++edgesChecked;
        }
      }
    }
    EXPECT_EQ(edgesChecked, 5 * n);  // five shared cell edges, n pixel pairs each
  }
}

TEST_F(CubemapLayouts, EquirectLooksWhereBlenderDoes) {
  const RgbImage image = equirectFromCube(directionCube(32), 256);
  ASSERT_EQ(image.height, 128);
  const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 0.03f; };
  EXPECT_TRUE(near(glm::normalize(pixelAt(image, 128, 64)), {1, 0, 0}));   // centre: +X
  EXPECT_TRUE(near(glm::normalize(pixelAt(image, 192, 64)), {0, -1, 0}));  // u = 0.75: -Y
  EXPECT_TRUE(near(glm::normalize(pixelAt(image, 64, 64)), {0, 1, 0}));    // u = 0.25: +Y
  EXPECT_TRUE(near(glm::normalize(pixelAt(image, 0, 64)), {-1, 0, 0}));    // edges: -X
  EXPECT_GT(pixelAt(image, 10, 0).z, 0.99f);                               // top: +Z
  EXPECT_LT(pixelAt(image, 10, 127).z, -0.99f);                            // bottom: -Z
  EXPECT_TRUE(near(equirectDirection(0.5f, 0.5f), {1, 0, 0}));
}

TEST_F(CubemapLayouts, CubeToEquirectToCubeWithinBound) {
  // A smooth function of direction through two bilinear resamplings: cube (N = 32) ->
  // equirect (256 x 128) -> cube. Bilinear interpolation over a cell h_u x h_v errs by at most
  // (h_u^2 + h_v^2) / 8 * M, M a bound on f's second derivatives. A texel spans at most
  // h = 2 / 32 = 0.0625 rad (at a face centre), an equirect pixel 2 pi / 256 = 0.0245 rad (less
  // in longitude near the poles); f's channels have second derivatives under M = 6 along the
  // sphere (sin(2 x): 4 from the argument, 2 from the sphere's curvature). Both passes:
  // (2 * 0.0625^2 + 2 * 0.0245^2) / 8 * 6 = 6.8e-3 per channel.
  const auto f = [](glm::vec3 d) {
    return glm::vec3(std::sin(2.0f * d.x) + d.z, std::cos(2.0f * d.y) * 0.5f, d.x * d.y + 1.0f);
  };
  const int n = 32;
  Cubemap cube = cubeFromFunction(n, f);
  cube.buildMipChain();
  const Cubemap back = cubeFromEquirect(equirectFromCube(cube, 8 * n), n);
  float worst = 0.0f;
  for (int face = 0; face < kCubeFaceCount; ++face) {
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const glm::vec3 exact = f(texelDirection(CubeFace(face), col, row, n));
        const glm::vec3 got = back.texel(CubeFace(face), 0, col, row);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] - exact[c]));
      }
    }
  }
  EXPECT_LT(worst, 6.8e-3f);
  std::printf("largest cube -> equirect -> cube error: %.2e\n", worst);
}

TEST_F(CubemapLayouts, ReadsEquirectFileAtFaceSizeWidthOverFour) {
  const std::filesystem::path file = folder_ / "sky.exr";
  writeCubemapImage(directionCube(16), file, CubemapImageLayout::Equirect);
  const Cubemap cube = readCubemapImage(file);
  EXPECT_EQ(cube.faceSize(), 16);
  EXPECT_EQ(cube.numLevels(), fullMipCount(16));
  // Four equirect pixels per texel at the equator: nearly the texel's own direction.
  EXPECT_LT(glm::length(cube.texel(CubeFace::px, 0, 8, 8) - texelDirection(CubeFace::px, 8, 8, 16)),
            0.01f);
  EXPECT_LT(glm::length(cube.texel(CubeFace::pz, 0, 8, 8) - texelDirection(CubeFace::pz, 8, 8, 16)),
            0.05f);
}

TEST_F(CubemapLayouts, BadImagesAreOneLineInputErrors) {
  const std::filesystem::path wrong = folder_ / "wrong.exr";
  writeRgbExr(wrong, RgbImage{10, 6, std::vector<float>(10 * 6 * 3, 1.0f)});
  try {
    readCubemapImage(wrong);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(),
              "cubemap image is 10 x 6 pixels: expected a 4:3 horizontal cross or a 3:4 vertical "
              "cross of square faces, or a 2:1 equirectangular image");
  }
  try {
    readCubemapImage(folder_ / "missing.exr");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), "cubemap image file not found");
    EXPECT_EQ(e.file(), folder_ / "missing.exr");
  }
  EXPECT_THROW(readCubemapImage(folder_ / "missing_{face}.exr"), InputError);
  EXPECT_THROW(
      cubeFromCross(RgbImage{8, 7, std::vector<float>(8 * 7 * 3)}, CrossLayout::Horizontal),
      std::invalid_argument);
}

}  // namespace
}  // namespace probeproxy
