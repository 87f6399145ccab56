// Cubemaps: mip chain, seam-aware sampling, roughness to mip (the Enlighten documentation), file
// I/O.
#include "core/cube/cubemap.h"
#include "core/cube/cubemap_io.h"
#include "core/cube/cubemap_sampling.h"
#include "core/cube/write_depth_cube.h"  // cubeFacePath
#include "core/errors/input_error.h"
#include "core/image/write_exr.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>

namespace probeproxy {
namespace {

// Every texel stores its own unit centre direction as its colour.
Cubemap directionCube(int n) {
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        const glm::vec3 d = texelDirection(CubeFace(f), col, row, n);
        faces[f].insert(faces[f].end(), {d.x, d.y, d.z});
      }
    }
  }
  Cubemap cube = Cubemap::fromFaces(n, std::move(faces));
  cube.buildMipChain();
  return cube;
}

Cubemap constantCube(int n, glm::vec3 colour) {
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (auto& face : faces) {
    for (int i = 0; i < n * n; ++i) face.insert(face.end(), {colour.r, colour.g, colour.b});
  }
  Cubemap cube = Cubemap::fromFaces(n, std::move(faces));
  cube.buildMipChain();
  return cube;
}

Cubemap randomCube(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(-2.0f, 1000.0f);
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (auto& face : faces) {
    for (int i = 0; i < n * n * 3; ++i) face.push_back(value(rng));
  }
  Cubemap cube = Cubemap::fromFaces(n, std::move(faces));
  cube.buildMipChain();
  return cube;
}

// What a sampler without seam handling does: bilinear within the face, clamping to its edge.
glm::vec3 sampleClampToEdge(const Cubemap& cube, glm::vec3 direction) {
  const FaceUv at = faceUvFromDirection(direction);
  const int n = cube.faceSize(0);
  const float x = at.uv.x * n - 0.5f, y = at.uv.y * n - 0.5f;
  const int c0 = static_cast<int>(std::floor(x)), r0 = static_cast<int>(std::floor(y));
  const float fx = x - std::floor(x), fy = y - std::floor(y);
  auto t = [&](int c, int r) {
    return cube.texel(at.face, 0, std::clamp(c, 0, n - 1), std::clamp(r, 0, n - 1));
  };
  return (1 - fy) * ((1 - fx) * t(c0, r0) + fx * t(c0 + 1, r0)) +
         fy * ((1 - fx) * t(c0, r0 + 1) + fx * t(c0 + 1, r0 + 1));
}

// Largest colour step between neighbouring samples along the great circle normal to `axis`.
template <typename Sampler>
float largestStepOnGreatCircle(glm::vec3 axis, float stepRadians, Sampler sample) {
  axis = glm::normalize(axis);
  const glm::vec3 helper = std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 e1 = glm::normalize(glm::cross(axis, helper));
  const glm::vec3 e2 = glm::cross(axis, e1);
  const int steps = static_cast<int>(std::ceil(2.0 * M_PI / stepRadians));
  float largest = 0.0f;
  glm::vec3 previous = sample(e1);
  for (int i = 1; i <= steps; ++i) {
    const double angle = i * static_cast<double>(stepRadians);
    const glm::vec3 d =
        static_cast<float>(std::cos(angle)) * e1 + static_cast<float>(std::sin(angle)) * e2;
    const glm::vec3 current = sample(d);
    largest = std::max(largest, glm::length(current - previous));
    previous = current;
  }
  return largest;
}

// Great circles that cross many edges: fixed-seed random ones, one through four cube corners
// (normal (1, -1, 0) holds (1, 1, +-1) and (-1, -1, +-1)) and ones hugging edges.
std::vector<glm::vec3> greatCircleAxes() {
  std::vector<glm::vec3> axes = {{1, -1, 0}, {0, 1, -1}, {1, 1, 1}, {1, 2, 3}, {0.01f, 1, 1}};
  std::mt19937 rng(4);
  std::normal_distribution<float> gauss;
  for (int i = 0; i < 6; ++i) axes.push_back({gauss(rng), gauss(rng), gauss(rng)});
  return axes;
}

TEST(CubemapSampling, TexelCentresReturnTheirOwnDirection) {
  for (int n : {1, 2, 5, 8}) {
    const Cubemap cube = directionCube(n);
    for (int f = 0; f < kCubeFaceCount; ++f) {
      for (int row = 0; row < n; ++row) {
        for (int col = 0; col < n; ++col) {
          const glm::vec3 d = texelDirection(CubeFace(f), col, row, n);
          const glm::vec3 s = sampleBilinear(cube, d, 0.0f);
          ASSERT_LT(glm::length(s - d), 1e-5f)
              << "n " << n << " face " << f << " texel " << col << ", " << row;
        }
      }
    }
  }
}

TEST(CubemapSampling, AnyDirectionGivesNearlyThatDirection) {
  // Bilinear interpolation of the texel-centre directions stays within a quarter of the largest
  // texel's angular size (2 / N radians, at the face centre) of the looked-up direction, edges
  // and corners included (measured: about 0.23 / N).
  std::mt19937 rng(11);
  std::normal_distribution<float> gauss;
  for (int n : {4, 8, 16}) {
    const Cubemap cube = directionCube(n);
    const float bound = 0.25f * 2.0f / static_cast<float>(n);
    float largest = 0.0f;
    for (int i = 0; i < 20000; ++i) {
      const glm::vec3 d = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
      largest = std::max(largest, glm::length(sampleBilinear(cube, d, 0.0f) - d));
    }
    EXPECT_LT(largest, bound) << "n " << n;
  }
}

TEST(CubemapSampling, GradientCrossesSeamsAndCornersWithoutAStep) {
  // Colour = direction changes by one unit per radian; interpolating it between texel centres
  // keeps the slope near 1 (measured up to 1.4, at corners where texels are most distorted), so
  // a step of `step` radians may change the colour by at most kSlope * step. A seam that clamps
  // instead jumps by about half a texel's colour difference, ~1 / N: hundreds of times more.
  const float step = 1e-4f;
  const float kSlope = 2.0f;
  for (int n : {1, 5, 8}) {
    const Cubemap cube = directionCube(n);
    for (const glm::vec3& axis : greatCircleAxes()) {
      for (float level : {0.0f, 0.5f}) {
        const float largest = largestStepOnGreatCircle(
            axis, step, [&](glm::vec3 d) { return sampleBilinear(cube, d, level); });
        EXPECT_LT(largest, kSlope * step) << "n " << n << " level " << level << " axis " << axis.x
                                          << " " << axis.y << " " << axis.z;
      }
    }
  }
}

TEST(CubemapSampling, TheSeamTestCatchesAClampingSampler) {
  // Guards the test above: the same walk with a sampler that ignores seams must fail it.
  const Cubemap cube = directionCube(8);
  const float largest = largestStepOnGreatCircle(
      {1, 2, 3}, 1e-4f, [&](glm::vec3 d) { return sampleClampToEdge(cube, d); });
  EXPECT_GT(largest, 100.0f * 2.0f * 1e-4f);
}

TEST(CubemapSampling, FractionalLevelIsLinearBetweenLevels) {
  const Cubemap cube = randomCube(8, 3);
  ASSERT_EQ(cube.numLevels(), 4);
  const glm::vec3 d = glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f));
  const glm::vec3 a = sampleBilinear(cube, d, 1.0f);
  const glm::vec3 b = sampleBilinear(cube, d, 2.0f);
  EXPECT_NE(a, b);
  const glm::vec3 mid = sampleBilinear(cube, d, 1.25f);
  EXPECT_LT(glm::length(mid - (0.75f * a + 0.25f * b)), 1e-3f);
  // Levels clamp to the chain; at a face centre the 1 x 1 level gives that face's one texel.
  EXPECT_EQ(sampleBilinear(cube, d, 99.0f), sampleBilinear(cube, d, 3.0f));
  EXPECT_EQ(sampleBilinear(cube, d, -1.0f), sampleBilinear(cube, d, 0.0f));
  for (int f = 0; f < kCubeFaceCount; ++f) {
    EXPECT_EQ(sampleBilinear(cube, cubeFaceAxes()[f].forward, 3.0f),
              cube.texel(CubeFace(f), 3, 0, 0));
  }
}

TEST(CubemapSampling, MipFromRoughnessFollowsSeed004) {
  // the Enlighten documentation: mip = numMips + 2 * log2(roughness), clamped to [0, numMips - 1].
  EXPECT_FLOAT_EQ(mipFromRoughness(0.5f, 8), 6.0f);
  EXPECT_FLOAT_EQ(mipFromRoughness(0.25f, 8), 4.0f);
  EXPECT_FLOAT_EQ(mipFromRoughness(0.125f, 8), 2.0f);
  EXPECT_FLOAT_EQ(mipFromRoughness(0.7f, 8), 8.0f + 2.0f * std::log2(0.7f));
  EXPECT_FLOAT_EQ(mipFromRoughness(1.0f, 8), 7.0f);     // 8 clamps to the last level
  EXPECT_FLOAT_EQ(mipFromRoughness(0.0625f, 8), 0.0f);  // exactly 0
  EXPECT_FLOAT_EQ(mipFromRoughness(0.01f, 8), 0.0f);    // below 0 clamps
  EXPECT_FLOAT_EQ(mipFromRoughness(0.0f, 8), 0.0f);     // log2(0) = -inf
  EXPECT_FLOAT_EQ(mipFromRoughness(0.9f, 1), 0.0f);
  EXPECT_THROW(mipFromRoughness(std::nanf(""), 8), std::invalid_argument);
  EXPECT_THROW(mipFromRoughness(0.5f, 0), std::invalid_argument);
}

TEST(CubemapMips, ChainRunsDownToOneTexelWithFloorHalving) {
  EXPECT_EQ(fullMipCount(1), 1);
  EXPECT_EQ(fullMipCount(8), 4);
  EXPECT_EQ(fullMipCount(12), 4);
  const Cubemap cube = constantCube(12, {1, 1, 1});
  ASSERT_EQ(cube.numLevels(), 4);
  EXPECT_EQ(cube.faceSize(1), 6);
  EXPECT_EQ(cube.faceSize(2), 3);
  EXPECT_EQ(cube.faceSize(3), 1);
}

TEST(CubemapMips, ConstantCubemapStaysConstant) {
  const glm::vec3 colour(0.25f, 1.5f, 3.0f);
  for (int n : {1, 5, 7, 8, 12, 13}) {
    const Cubemap cube = constantCube(n, colour);
    ASSERT_EQ(cube.numLevels(), fullMipCount(n));
    for (int level = 0; level < cube.numLevels(); ++level) {
      const int size = cube.faceSize(level);
      for (int f = 0; f < kCubeFaceCount; ++f) {
        for (int row = 0; row < size; ++row) {
          for (int col = 0; col < size; ++col) {
            const glm::vec3 t = cube.texel(CubeFace(f), level, col, row);
            ASSERT_LT(glm::length(t - colour), 1e-6f) << "n " << n << " level " << level;
          }
        }
      }
    }
  }
}

TEST(CubemapMips, TwoByTwoFaceMipsToItsMean) {
  const Cubemap cube = randomCube(2, 5);
  ASSERT_EQ(cube.numLevels(), 2);
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const CubeFace face(static_cast<CubeFace>(f));
    const glm::vec3 mean = (cube.texel(face, 0, 0, 0) + cube.texel(face, 0, 1, 0) +
                            cube.texel(face, 0, 0, 1) + cube.texel(face, 0, 1, 1)) /
                           4.0f;
    EXPECT_LT(glm::length(cube.texel(face, 1, 0, 0) - mean), 1e-3f) << "face " << f;
  }
}

TEST(CubemapMips, OddSizeWeighsChildrenByTheAreaCovered) {
  // 5 -> 2: parent 0 covers children [0, 2.5): weights 1, 1, 0.5. With texel value = its column,
  // the parent holds (0 + 1 + 2 * 0.5) / 2.5 = 0.8 and parent 1 holds (2 * 0.5 + 3 + 4) / 2.5
  // = 3.2.
  const int n = 5;
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (auto& face : faces) {
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) face.insert(face.end(), {float(col), 0.0f, float(row)});
    }
  }
  Cubemap cube = Cubemap::fromFaces(n, std::move(faces));
  cube.buildMipChain();
  ASSERT_EQ(cube.faceSize(1), 2);
  EXPECT_NEAR(cube.texel(CubeFace::ny, 1, 0, 1).x, 0.8f, 1e-6f);
  EXPECT_NEAR(cube.texel(CubeFace::ny, 1, 1, 1).x, 3.2f, 1e-6f);
  EXPECT_NEAR(cube.texel(CubeFace::ny, 1, 1, 1).z, 3.2f, 1e-6f);
}

TEST(CubemapMips, FromFacesRejectsBadInput) {
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (auto& face : faces) face.assign(4 * 4 * 3, 1.0f);
  faces[3].pop_back();
  EXPECT_THROW(Cubemap::fromFaces(4, faces), std::invalid_argument);
  faces[3].push_back(std::nanf(""));
  EXPECT_THROW(Cubemap::fromFaces(4, faces), std::invalid_argument);
  EXPECT_THROW(Cubemap::fromFaces(0, {}), std::invalid_argument);
}

class CubemapIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(::testing::TempDir()) /
           ("cubemap_io_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string pattern(const std::string& stem) const {
    return (dir_ / (stem + "_{face}.exr")).string();
  }
  std::filesystem::path dir_;
};

TEST_F(CubemapIo, WriteThenReadIsBitIdentical) {
  const Cubemap cube = randomCube(5, 9);
  writeCubemap(cube, pattern("probe"));
  const Cubemap back = readCubemap(pattern("probe"));
  ASSERT_EQ(back.faceSize(0), 5);
  EXPECT_EQ(back.numLevels(), fullMipCount(5));
  for (int f = 0; f < kCubeFaceCount; ++f) EXPECT_EQ(back.levels[0].rgb[f], cube.levels[0].rgb[f]);
  // A mip level writes at its own size.
  writeCubemap(cube, pattern("mip1"), 1);
  EXPECT_EQ(readCubemap(pattern("mip1")).levels[0].rgb[4], cube.levels[1].rgb[4]);
}

TEST_F(CubemapIo, FaceFilesUseTheConventionNames) {
  writeCubemap(constantCube(2, {1, 2, 3}), pattern("probe"));
  for (const char* name : {"px", "nx", "py", "ny", "pz", "nz"}) {
    EXPECT_TRUE(std::filesystem::exists(dir_ / (std::string("probe_") + name + ".exr"))) << name;
  }
}

TEST_F(CubemapIo, MissingFaceIsAnInputErrorNamingIt) {
  writeCubemap(constantCube(4, {1, 1, 1}), pattern("probe"));
  const std::filesystem::path gone = cubeFacePath(pattern("probe"), CubeFace::ny);
  std::filesystem::remove(gone);
  try {
    readCubemap(pattern("probe"));
    FAIL() << "no error for a missing face";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), gone);
    EXPECT_NE(std::string(e.what()).find("probe_ny.exr"), std::string::npos) << e.what();
  }
}

TEST_F(CubemapIo, FacesOfDifferentSizesAreAnInputError) {
  writeCubemap(constantCube(4, {1, 1, 1}), pattern("probe"));
  writeCubemap(constantCube(2, {1, 1, 1}), pattern("small"));
  const std::filesystem::path odd = cubeFacePath(pattern("probe"), CubeFace::pz);
  std::filesystem::copy_file(cubeFacePath(pattern("small"), CubeFace::pz), odd,
                             std::filesystem::copy_options::overwrite_existing);
  try {
    readCubemap(pattern("probe"));
    FAIL() << "no error for faces of different sizes";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), odd);
    EXPECT_NE(e.problem().find("2 x 2"), std::string::npos) << e.what();
  }
}

TEST_F(CubemapIo, NonSquareFaceAndBadPatternAreInputErrors) {
  writeCubemap(constantCube(4, {1, 1, 1}), pattern("probe"));
  const std::filesystem::path wide = cubeFacePath(pattern("probe"), CubeFace::nx);
  writeExr(wide, 4, 3, {"R", "G", "B"}, std::vector<float>(4 * 3 * 3, 1.0f));
  try {
    readCubemap(pattern("probe"));
    FAIL() << "no error for a non-square face";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), wide);
  }
  EXPECT_THROW(readCubemap((dir_ / "probe.exr").string()), InputError);
}

TEST_F(CubemapIo, ReadsPngAsLinear) {
  // 8-bit sRGB: 255 -> 1, 0 -> 0, 128 -> ((128/255 + 0.055) / 1.055)^2.4 = 0.2158605.
  const std::string png = (dir_ / "ldr_{face}.png").string();
  const unsigned char pixels[2 * 2 * 3] = {255, 0, 128, 255, 0, 128, 255, 0, 128, 255, 0, 128};
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const std::string file = cubeFacePath(png, CubeFace(f)).string();
    auto out = OIIO::ImageOutput::create(file);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(file, OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels));
    ASSERT_TRUE(out->close());
  }
  const Cubemap cube = readCubemap(png);
  const glm::vec3 t = cube.texel(CubeFace::py, 0, 1, 1);
  EXPECT_FLOAT_EQ(t.r, 1.0f);
  EXPECT_FLOAT_EQ(t.g, 0.0f);
  EXPECT_NEAR(t.b, 0.2158605f, 1e-5f);
}

}  // namespace
}  // namespace probeproxy
