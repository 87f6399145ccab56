// Image error figures (core/measures/image_error.h) against hand-computed answers, and the
// error pictures read back as a person's image viewer would.

#include "core/measures/image_error.h"
#include "core/image/rgb_image.h"
#include "core/measures/error_images.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

namespace probeproxy {
namespace {

TEST(ImageError, ConstantOffsetGivesTheAnalyticPsnr) {
  // Two masked pixels, one unmasked pixel that is wildly off and must not count.
  const std::vector<float> reference = {0.5f, 1.0f, 0.25f, 0.2f, 0.2f, 0.2f, 9.0f, 9.0f, 9.0f};
  std::vector<float> reconstruction = reference;
  for (int i = 0; i < 6; ++i) reconstruction[i] += 0.1f;
  reconstruction[6] = -100.0f;
  const std::vector<std::uint8_t> mask = {1, 1, 0}, miss = {0, 0, 0};
  const ImageErrorFigures e = imageError(reference, reconstruction, mask, miss);
  EXPECT_EQ(e.pixels, 2u);
  EXPECT_FLOAT_EQ(static_cast<float>(e.peak), 1.0f);
  EXPECT_NEAR(e.meanAbsError, 0.1, 1e-6);
  EXPECT_NEAR(e.psnrDb, 20.0, 1e-4);  // 10 log10(1 / 0.01)
  EXPECT_EQ(e.missRate, 0.0);
}

TEST(ImageError, MissCountsAsBlackAndIsReported) {
  const std::vector<float> reference = {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f};
  const std::vector<float> reconstruction = reference;
  const std::vector<std::uint8_t> mask = {1, 1}, miss = {0, 1};
  const ImageErrorFigures e = imageError(reference, reconstruction, mask, miss);
  EXPECT_EQ(e.missRate, 0.5);
  EXPECT_NEAR(e.meanAbsError, 0.5, 1e-12);
  EXPECT_NEAR(e.psnrDb, 10.0 * std::log10(2.0), 1e-9);  // MSE = 0.5, peak 1
  EXPECT_TRUE(std::isinf(
      imageError(reference, reconstruction, mask, std::vector<std::uint8_t>{0, 0}).psnrDb));
}

TEST(ImageError, RejectsMismatchedSizesAndAnEmptyMask) {
  const std::vector<float> rgb(6, 0.0f);
  EXPECT_THROW(imageError(rgb, rgb, std::vector<std::uint8_t>{1}, std::vector<std::uint8_t>{0}),
               std::invalid_argument);
  EXPECT_THROW(
      imageError(rgb, rgb, std::vector<std::uint8_t>{0, 0}, std::vector<std::uint8_t>{0, 0}),
      std::invalid_argument);
}

TEST(ErrorImages, MissMaskAndHeatmapReadBackWithTheirColours) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "probeproxy_error_images";
  std::filesystem::create_directories(dir);
  const std::vector<std::uint8_t> mask = {1, 1, 0, 1}, miss = {1, 0, 0, 0};
  writeMissMaskPng(dir / "miss.png", 2, 2, mask, miss);
  const RgbImage m = readRgbImage(dir / "miss.png");
  ASSERT_EQ(m.width, 2);
  EXPECT_EQ(m.at(0, 0), glm::vec3(1, 0, 0));  // missed: red
  EXPECT_EQ(m.at(1, 0), glm::vec3(1, 1, 1));  // seen: white
  EXPECT_EQ(m.at(0, 1), glm::vec3(0, 0, 0));  // outside the mask: black
  const std::vector<float> absError = {0.0f, 0.0f, 0.0f, 10.0f};
  writeErrorHeatmapPng(dir / "heat.png", 2, 2, absError, mask, miss, 1.0f);
  const RgbImage h = readRgbImage(dir / "heat.png");
  EXPECT_EQ(h.at(0, 0), glm::vec3(0, 1, 1));  // a miss: cyan
  EXPECT_EQ(h.at(1, 0), glm::vec3(0, 0, 0));  // no error: black
  EXPECT_EQ(h.at(1, 1), glm::vec3(1, 1, 1));  // at or above the scale: white
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace probeproxy
