// Mixing cubemaps at a point of interest (core/blend/mix_cubemaps.h) and the top-down weight
// picture (core/blend/weight_picture.h).

#include "core/blend/mix_cubemaps.h"
#include "core/blend/weight_picture.h"
#include "core/blend/weight_picture_legend.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace probeproxy {
namespace {

// Face f, texel (col, row): a value that differs per face, texel and channel.
Cubemap patternCube(int n, float scale) {
  std::array<std::vector<float>, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int i = 0; i < n * n * 3; ++i)
      faces[f].push_back(scale * static_cast<float>(f * 1000 + i));
  }
  Cubemap cube = Cubemap::fromFaces(n, std::move(faces));
  cube.buildMipChain();
  return cube;
}

TEST(MixCubemaps, IsTheWeightedSumOfEveryTexelOfEveryLevel) {
  const Cubemap a = patternCube(8, 1.0f), b = patternCube(8, -0.5f), c = patternCube(8, 2.0f);
  const std::vector<WeightedCubemap> weighted = {{&a, 0.5f}, {&b, 0.25f}, {&c, 0.25f}};
  const Cubemap mixed = mixCubemaps(weighted);
  ASSERT_EQ(mixed.numLevels(), 4);  // 8, 4, 2, 1
  for (int level = 0; level < mixed.numLevels(); ++level) {
    const int n = mixed.faceSize(level);
    EXPECT_EQ(n, a.faceSize(level));
    for (int f = 0; f < kCubeFaceCount; ++f) {
      for (int row = 0; row < n; ++row) {
        for (int col = 0; col < n; ++col) {
          const CubeFace face = static_cast<CubeFace>(f);
          const glm::vec3 expected = 0.5f * a.texel(face, level, col, row) +
                                     0.25f * b.texel(face, level, col, row) +
                                     0.25f * c.texel(face, level, col, row);
          const glm::vec3 got = mixed.texel(face, level, col, row);
          for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(got[k], expected[k], 1e-3f * (1 + std::abs(expected[k])));
        }
      }
    }
  }
}

TEST(MixCubemaps, OneProbeWithWeightOneIsThatProbe) {
  const Cubemap a = patternCube(5, 1.0f);
  const std::vector<WeightedCubemap> one = {{&a, 1.0f}};
  const Cubemap mixed = mixCubemaps(one);
  for (int level = 0; level < a.numLevels(); ++level) {
    for (int f = 0; f < kCubeFaceCount; ++f)
      EXPECT_EQ(mixed.levels[level].rgb[f], a.levels[level].rgb[f]);
  }
}

TEST(MixCubemaps, RefusesCubesOfDifferentSizes) {
  const Cubemap a = patternCube(8, 1.0f), b = patternCube(4, 1.0f);
  const std::vector<WeightedCubemap> mismatched = {{&a, 0.5f}, {&b, 0.5f}};
  try {
    mixCubemaps(mismatched);
    FAIL() << "mixed cubes of 8 and 4 px";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "mixCubemaps: cubemaps differ in size (4 px, 3 levels against 8 px, 4 levels)");
  }
  EXPECT_THROW(mixCubemaps(std::vector<WeightedCubemap>{}), std::invalid_argument);
  EXPECT_FALSE(sameCubemapLayout(a, b));
}

TEST(WeightPicture, EachProbeIsItsColourAndOverlapsAreTheWeightedSum) {
  // Two boxes along x: probe 0 red on the left, probe 1 green on the right, crossing in the
  // middle; at x = 0 the weights are 1/2 each by symmetry.
  const std::vector<InfluenceVolume> v = {
      BoxInfluence{{-2, 0, 0}, {3, 1, 1}, {1, 0, 0, 0}, {1.5, 1, 1}},
      BoxInfluence{{2, 0, 0}, {3, 1, 1}, {1, 0, 0, 0}, {1.5, 1, 1}}};
  const WeightPicture p = renderWeightPicture(v, 0.0, {}, 400);
  // Bounds x [-5.5, 5.5] (11 m), y [-1.5, 1.5] (3 m) with the margin: 400 x 110 pixels.
  EXPECT_EQ(p.width, 400);
  EXPECT_EQ(p.height, 110);
  const auto pixelAt = [&](double x, double y) {
    const int col = static_cast<int>((x - p.minMeters.x) / p.metersPerPixel);
    const int row = p.height - 1 - static_cast<int>((y - p.minMeters.y) / p.metersPerPixel);
    const std::size_t i = (static_cast<std::size_t>(row) * p.width + col) * 3;
    return glm::ivec3(p.rgb8[i], p.rgb8[i + 1], p.rgb8[i + 2]);
  };
  EXPECT_EQ(pixelAt(-3.0, 0.3), glm::ivec3(255, 0, 0));
  EXPECT_EQ(pixelAt(3.0, 0.3), glm::ivec3(0, 255, 0));
  // Near the middle: Lagarde's two-volume weight (1 - a) / a at the pixel's centre.
  const int col = static_cast<int>((0.01 - p.minMeters.x) / p.metersPerPixel);
  const double x = p.minMeters.x + (col + 0.5) * p.metersPerPixel;
  const double a0 = (std::abs(x + 2) - 1.5) / 1.5, a1 = (std::abs(x - 2) - 1.5) / 1.5;
  const double w0 = (1 - a0) / a0, w1 = (1 - a1) / a1;
  const glm::ivec3 middle = pixelAt(x, 0.3);
  EXPECT_NEAR(middle.r, 255 * w0 / (w0 + w1), 0.5 + 1e-9);
  EXPECT_NEAR(middle.g, 255 * w1 / (w0 + w1), 0.5 + 1e-9);
  EXPECT_EQ(middle.b, 0);
  EXPECT_EQ(pixelAt(0.0, 1.4), glm::ivec3(0, 0, 0));      // outside every volume
  EXPECT_EQ(pixelAt(-4.99, 0.3), glm::ivec3(255, 0, 0));  // just inside probe 0's outer side
  EXPECT_EQ(probeColour(0), glm::u8vec3(255, 0, 0));
  EXPECT_EQ(probeColour(2), glm::u8vec3(0, 0, 255));
}

TEST(WeightPicture, TheLegendUnderTheSliceNamesEachProbesColourAndTheScale) {
  const std::vector<InfluenceVolume> v = {
      BoxInfluence{{-2, 0, 0}, {3, 1, 1}, {1, 0, 0, 0}, {1.5, 1, 1}},
      BoxInfluence{{2, 0, 0}, {3, 1, 1}, {1, 0, 0, 0}, {1.5, 1, 1}}};
  const WeightPicture p = renderWeightPicture(v, 0.0, {}, 400);
  const std::vector<std::string> names = {"left", "right"};
  const Rgb8Canvas c = weightPictureWithLegend(p, names, "blend weights");
  ASSERT_EQ(c.width, p.width);
  ASSERT_GT(c.height, p.height + 100) << "a title, two rows of keys and a scale bar";
  const auto pixelAt = [&](int col, int row) {
    const std::size_t i = (static_cast<std::size_t>(row) * c.width + col) * 3;
    return glm::ivec3(c.rgb8[i], c.rgb8[i + 1], c.rgb8[i + 2]);
  };
  for (int row = 0; row < p.height; ++row)  // the slice as it was
    for (int col = 0; col < p.width; col += 7)
      ASSERT_EQ(pixelAt(col, row),
                glm::ivec3(p.rgb8[(row * p.width + col) * 3], p.rgb8[(row * p.width + col) * 3 + 1],
                           p.rgb8[(row * p.width + col) * 3 + 2]));
  // The keys, 12 px in and under a 26 px title, one 220 px column in 400 px: the probes'
  // swatches first, a 24 px row each.
  const int keys = p.height + 12 + 26 + 9;
  EXPECT_EQ(pixelAt(12 + 14, keys), glm::ivec3(255, 0, 0));
  EXPECT_EQ(pixelAt(12 + 14, keys + 24), glm::ivec3(0, 255, 0));
  // The scale bar: 2 m at this picture's 36.4 px per metre (a fifth of 400 px is 2.2 m),
  // black from column 12, its end tick at 12 + 73 - 2.
  const int bar = c.height - 40 + 2;
  EXPECT_EQ(pixelAt(12 + 40, bar), glm::ivec3(0, 0, 0));
  EXPECT_EQ(pixelAt(12 + 73 - 1, bar), glm::ivec3(0, 0, 0));
  EXPECT_EQ(pixelAt(12 + 73 + 3, bar), glm::ivec3(255, 255, 255));
}

}  // namespace
}  // namespace probeproxy
